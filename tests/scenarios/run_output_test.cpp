// ferrodyn run end to end: the HDF5 layout of docs/OUTPUT.md, CSV export, a SIGINT halfway
// through a run, and a solver failure -- each must leave a readable file holding every sample up
// to the moment the run stopped, with a status attribute saying what happened.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>
#include <signal.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ferro/scenarios/h5_output.hpp"
#include "process.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;
const std::string kScene = "tests/scenarios/data/good_minimal.yaml";

std::string temp_file(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ferro_tests_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return (dir / name).string();
}

TEST(RunOutput, layout_metadata_and_csv) {
  const std::string out = temp_file("layout.h5");
  const auto r = test::run_capture({FERRODYN_EXE, "run", kScene, "-o", out, "--csv", "wheelset.y",
                                    "contact.lateral_force", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("completed"), std::string::npos) << r.output;
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "completed");
  EXPECT_EQ(f.string_attribute("/", "program"), "ferrodyn");
  EXPECT_EQ(f.string_attribute("/", "integrator"), "cvode_bdf");
  EXPECT_FALSE(f.string_attribute("/", "version").empty());
  const auto t = f.read_vector("/time");
  // t_end 0.5 s every 1 ms (the default interval): 501 samples.
  ASSERT_EQ(t.size(), 501u);
  EXPECT_DOUBLE_EQ(t.back(), 0.5);
  EXPECT_DOUBLE_EQ(f.number_attribute("/", "t_reached"), 0.5);
  for (const char* s : {"wheelset.y", "wheelset.yaw", "wheelset.y_dot", "wheelset.yaw_dot",
                        "contact.lateral_force", "contact.yaw_moment"}) {
    const auto v = f.read_vector(std::string("/signals/") + s);
    EXPECT_EQ(v.size(), t.size()) << s;
  }
  EXPECT_EQ(f.string_attribute("/signals/wheelset.y", "unit"), "m");
  EXPECT_EQ(f.string_attribute("/time", "unit"), "s");
  const auto y = f.read_vector("/signals/wheelset.y");
  EXPECT_DOUBLE_EQ(y.front(), 1e-3);  // simulation.initial
  // The CSV holds the same samples.
  std::ifstream csv(fs::path(out).replace_extension(".csv"));
  ASSERT_TRUE(csv.good());
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "time,wheelset.y,contact.lateral_force");
  std::size_t rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, t.size());
}

TEST(RunOutput, sigint_halfway_leaves_every_sample_up_to_the_interrupt) {
  const std::string out = temp_file("interrupted.h5");
  const std::string ref = temp_file("reference.h5");
  // Paced at 2 simulated seconds per wall second, an 8 s run lasts 4 s of wall time; the
  // non-TTY progress log (lines from 1 s of wall time on) announces 50 % at 2 s and the test
  // interrupts right then.
  test::BackgroundProcess p(
      {FERRODYN_EXE, "run", kScene, "-o", out, "--t-end", "8", "--pace", "2", "--no-plots"});
  std::string line;
  bool halfway = false;
  while (p.read_line(line)) {
    if (line.find("progress: 50%") != std::string::npos) {
      halfway = true;
      p.signal(SIGINT);
      break;
    }
  }
  ASSERT_TRUE(halfway) << "no 50% progress line seen";
  EXPECT_EQ(p.wait(), 130);

  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "interrupted");
  EXPECT_NE(f.string_attribute("/", "status_message").find("signal"), std::string::npos);
  const auto t = f.read_vector("/time");
  const double t_reached = f.number_attribute("/", "t_reached");
  ASSERT_GT(t.size(), 4000u);  // past 50 % of 8001 samples
  ASSERT_LT(t.size(), 8001u);  // but not the whole run
  EXPECT_DOUBLE_EQ(t.back(), t_reached);
  for (std::size_t i = 1; i < t.size(); ++i) ASSERT_NEAR(t[i] - t[i - 1], 1e-3, 1e-9) << i;
  const auto y = f.read_vector("/signals/wheelset.y");
  ASSERT_EQ(y.size(), t.size());

  // Every stored sample equals the uninterrupted run's (same integrator, deterministic).
  const auto r = test::run_capture(
      {FERRODYN_EXE, "run", kScene, "-o", ref, "--t-end", "8", "--no-plots", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto y_ref = H5File::open_read(ref).read_vector("/signals/wheelset.y");
  for (std::size_t i = 0; i < y.size(); ++i) ASSERT_DOUBLE_EQ(y[i], y_ref[i]) << i;
}

TEST(RunOutput, solver_failure_reports_time_state_and_cause) {
  // Allowing one internal step between outputs makes CVODE give up (CV_TOO_MUCH_WORK) early.
  const std::string scene = temp_file("fail.yaml");
  {
    std::ifstream in(kScene);
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    const std::string key = "  rtol: 1.0e-8\n";
    text.replace(text.find(key), key.size(), key + "  max_steps: 1\n");
    std::ofstream(scene) << text;
  }
  const std::string out = temp_file("fail.h5");
  const auto r = test::run_capture({FERRODYN_EXE, "run", scene, "-o", out, "--no-plots"});
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("CV_TOO_MUCH_WORK"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("t = "), std::string::npos) << r.output;
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "solver_failure");
  EXPECT_NE(f.string_attribute("/", "status_message").find("CV_TOO_MUCH_WORK"), std::string::npos);
  const auto state = f.read_vector("/failure/state");
  EXPECT_EQ(state.size(), 4u);
  const auto t = f.read_vector("/time");
  ASSERT_GE(t.size(), 1u);
  EXPECT_EQ(f.read_vector("/signals/wheelset.y").size(), t.size());
  EXPECT_LE(t.back(), f.number_attribute("/", "t_reached") + 1e-12);
}

TEST(RunOutput, every_shipped_scene_runs) {
  // Vehicle scenes run a short stretch here (their full runs are in docs/PERFORMANCE.md).
  constexpr const char* kVehicleSmokeSeconds = "0.05";
  for (const auto& e : fs::directory_iterator("scenarios/scenes")) {
    if (e.path().extension() != ".yaml") continue;
    const YAML::Node model = YAML::LoadFile(e.path().string())["model"];
    const bool vehicle_scene = model.IsMap() && model["type"].as<std::string>("") == "vehicle";
    const std::string out = temp_file(e.path().stem().string() + ".h5");
    const auto v = test::run_capture({FERRODYN_EXE, "validate", e.path().string()});
    EXPECT_EQ(v.exit_code, 0) << v.output;
    std::vector<std::string> run = {FERRODYN_EXE, "run", e.path().string(), "-o", out,
                                    "--no-plots", "-q"};
    if (vehicle_scene) run.insert(run.end(), {"--t-end", kVehicleSmokeSeconds});
    const auto r = test::run_capture(run);
    EXPECT_EQ(r.exit_code, 0) << e.path() << "\n" << r.output;
    EXPECT_EQ(H5File::open_read(out).string_attribute("/", "status"), "completed") << e.path();
    std::vector<std::string> eig = {FERRODYN_EXE, "eig", e.path().string(), "-o",
                                    temp_file("eig.h5"), "--no-plots", "--overwrite"};
    if (vehicle_scene) eig.insert(eig.end(), {"--points", "3"});
    const auto ev = test::run_capture(eig);
    EXPECT_EQ(ev.exit_code, 0) << ev.output;
  }
}

TEST(RunOutput, plots_are_written_as_png_and_svg) {
  const std::string out = temp_file("plots.h5");
  const std::string dir = temp_file("plots_dir");
  const auto r =
      test::run_capture({FERRODYN_EXE, "run", kScene, "-o", out, "-q", "--plot-dir", dir});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir + "/wheelset.y.png")) << r.output;
  EXPECT_TRUE(fs::exists(dir + "/wheelset.y.svg")) << r.output;
  const auto p = test::run_capture(
      {FERRODYN_EXE, "plot", out, "contact.yaw_moment", "-o", dir, "--format", "png"});
  EXPECT_EQ(p.exit_code, 0) << p.output;
  EXPECT_TRUE(fs::exists(dir + "/contact.yaw_moment.png"));
  const auto bad = test::run_capture({FERRODYN_EXE, "plot", out, "no.such.signal", "-o", dir});
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("no.such.signal"), std::string::npos);
}

}  // namespace
}  // namespace ferro::scenarios
