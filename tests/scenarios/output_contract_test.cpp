// The output contract (scenarios/include/ferro/scenarios/output_file.hpp, docs/OUTPUT.md): an
// output is written under a temporary name and renamed when complete, never replaces an input or
// another output of the same run, replaces an existing file only with --overwrite, and says at
// every flush how many samples it holds and up to when; a run that fails after its output exists
// leaves that output with its status.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "ferro/scenarios/h5_output.hpp"
#include "limited_process.hpp"
#include "process.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;
const std::string kMinimal = "tests/scenarios/data/good_minimal.yaml";
const std::string kErri = "scenarios/scenes/manchester_straight_erri.yaml";

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ferro_output_contract_" + std::to_string(getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Files in `dir` whose name ends in ".part" (temporary outputs).
std::vector<std::string> temporary_files(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.size() > 5 && name.compare(name.size() - 5, 5, ".part") == 0) out.push_back(name);
  }
  return out;
}

// What every run output must say of itself: t_reached is its last sample, `samples` their count.
void expect_consistent(const H5File& f) {
  const auto t = f.read_vector("/time");
  EXPECT_EQ(static_cast<std::size_t>(f.number_attribute("/", "samples")), t.size());
  EXPECT_DOUBLE_EQ(f.number_attribute("/", "t_reached"), t.empty() ? 0.0 : t.back());
}

TEST(OutputContract, a_second_run_on_the_same_name_is_refused_and_the_first_completes) {
  const fs::path dir = scratch("two_runs");
  const std::string out = (dir / "same.h5").string();
  // The first run is paced to last about 3 s of wall time.
  test::LimitedProcess first({test::ferrodyn_exe(), "run", kMinimal, "--no-plots", "-q",
                              "--pace", "1", "--t-end", "3", "-o", out},
                             {});
  const auto start = std::chrono::steady_clock::now();
  while (temporary_files(dir).empty() &&
         std::chrono::steady_clock::now() - start < std::chrono::seconds(20)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto second = test::run_capture(
      {test::ferrodyn_exe(), "run", kMinimal, "--no-plots", "-q", "--t-end", "2", "-o", out});
  EXPECT_EQ(second.exit_code, 2) << second.output;
  EXPECT_NE(second.output.find("being written by another program"), std::string::npos)
      << second.output;
  EXPECT_EQ(first.wait_for(120.0), 0) << first.output();
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "completed");
  EXPECT_EQ(f.read_vector("/time").size(), 3001u);  // t_end 3 s every 1 ms
  expect_consistent(f);
  EXPECT_TRUE(temporary_files(dir).empty());
}

TEST(OutputContract, an_output_never_replaces_an_input_or_another_output) {
  const fs::path dir = scratch("inputs");
  // The HDF5 file and its CSV on one name.
  const auto same = test::run_capture({test::ferrodyn_exe(), "run", kMinimal, "--no-plots", "-q",
                                       "-o", (dir / "x.csv").string(), "--csv", "all"});
  EXPECT_EQ(same.exit_code, 2) << same.output;
  EXPECT_NE(same.output.find("already another output of this run"), std::string::npos)
      << same.output;
  EXPECT_FALSE(fs::exists(dir / "x.csv"));

  // Every file a scene reads: the scene, its vehicle file, and the imported contact table the
  // CSV beside an output named like it would replace.
  const std::string scene = "scenarios/scenes/cooperrider_straight.yaml";
  const std::string table = "data/cooperrider_wagon/contact_table_s1002_uic60_1in40";
  for (const auto& [output, input] :
       {std::pair{scene, scene},
        std::pair{std::string("scenarios/vehicles/cooperrider_wagon.yaml"),
                  std::string("scenarios/vehicles/cooperrider_wagon.yaml")},
        std::pair{table + ".h5", table + ".csv"}}) {
    const std::string before = file_text(input);
    ASSERT_FALSE(before.empty()) << input;
    const auto r = test::run_capture({test::ferrodyn_exe(), "run", scene, "--no-plots", "-q",
                                      "--t-end", "0.01", "--csv", "all", "--overwrite", "-o",
                                      output});
    EXPECT_EQ(r.exit_code, 2) << output << "\n" << r.output;
    EXPECT_NE(r.output.find("is an input of this run"), std::string::npos) << r.output;
    EXPECT_EQ(file_text(input), before) << input;
  }
  EXPECT_FALSE(fs::exists(table + ".h5"));
  EXPECT_TRUE(temporary_files("data/cooperrider_wagon").empty());

  // An assessment written over the run it assesses.
  const std::string run = (dir / "d.h5").string();
  ASSERT_EQ(test::run_capture({test::ferrodyn_exe(), "run",
                               "scenarios/scenes/thesis_derailment.yaml", "--no-plots", "-q",
                               "--t-end", "1", "-o", run})
                .exit_code,
            0);
  const std::string before = file_text(run);
  const auto d = test::run_capture(
      {test::ferrodyn_exe(), "assess", run, "-o", run, "--overwrite", "--no-plots"});
  EXPECT_EQ(d.exit_code, 2) << d.output;
  EXPECT_EQ(file_text(run), before);
  EXPECT_EQ(H5File::open_read(run).string_attribute("/", "status"), "completed");
}

TEST(OutputContract, an_existing_output_is_replaced_only_with_overwrite) {
  const fs::path dir = scratch("overwrite");
  const std::string out = (dir / "o.h5").string();
  const auto run = [&](const std::string& t_end, bool overwrite) {
    std::vector<std::string> args = {test::ferrodyn_exe(), "run", kMinimal, "--no-plots", "-q",
                                     "--t-end", t_end, "-o", out};
    if (overwrite) args.push_back("--overwrite");
    return test::run_capture(args);
  };
  ASSERT_EQ(run("0.2", false).exit_code, 0);
  const std::string first = file_text(out);
  const auto again = run("0.3", false);
  EXPECT_EQ(again.exit_code, 2) << again.output;
  EXPECT_NE(again.output.find("exists; pass --overwrite"), std::string::npos) << again.output;
  EXPECT_EQ(file_text(out), first);
  const auto replaced = run("0.3", true);
  EXPECT_EQ(replaced.exit_code, 0) << replaced.output;
  EXPECT_EQ(H5File::open_read(out).read_vector("/time").size(), 301u);
  EXPECT_TRUE(temporary_files(dir).empty());
}

TEST(OutputContract, a_csv_path_that_cannot_be_written_leaves_the_previous_results_alone) {
  const fs::path dir = scratch("blocked_csv");
  const std::string out = (dir / "X.h5").string();
  ASSERT_EQ(test::run_capture({test::ferrodyn_exe(), "run", kMinimal, "--no-plots", "-q", "-o", out})
                .exit_code,
            0);
  const std::string before = file_text(out);
  fs::create_directories(dir / "X.csv");  // where the CSV would go: a folder
  const auto r = test::run_capture({test::ferrodyn_exe(), "run", kMinimal, "--no-plots", "-q",
                                    "-o", out, "--overwrite", "--csv", "all"});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("X.csv"), std::string::npos) << r.output;
  EXPECT_EQ(file_text(out), before);
  EXPECT_TRUE(temporary_files(dir).empty());
}

TEST(OutputContract, a_killed_run_leaves_samples_and_t_reached_that_agree) {
  const fs::path dir = scratch("killed");
  const std::string out = (dir / "k.h5").string();
  // Paced at 1 s per wall second: after 2 s of wall time about 2000 samples are computed, and
  // at most 0.5 s of them (the flush period) may still be in memory when SIGKILL comes.
  test::LimitedProcess p({test::ferrodyn_exe(), "run", kMinimal, "--no-plots", "-q", "--pace",
                          "1", "--t-end", "30", "-o", out},
                         {});
  std::this_thread::sleep_for(std::chrono::seconds(2));
  p.signal(SIGKILL);
  EXPECT_EQ(p.wait_for(60.0), 137);
  const auto left = temporary_files(dir);
  ASSERT_EQ(left.size(), 1u);  // the temporary name: the run never completed
  const H5File f = H5File::open_read((dir / left.front()).string());
  EXPECT_EQ(f.string_attribute("/", "status"), "running");
  const auto t = f.read_vector("/time");
  EXPECT_GT(t.size(), 500u);
  expect_consistent(f);
}

TEST(OutputContract, a_full_disk_leaves_t_reached_at_the_last_sample) {
  const fs::path dir = scratch("full");
  const std::string out = (dir / "f.h5").string();
  test::LimitedProcess p({test::ferrodyn_exe(), "run", "scenarios/scenes/wheelset_hunting.yaml",
                          "--t-end", "200", "--no-plots", "-q", "-o", out},
                         {{RLIMIT_FSIZE, 2 * 1024 * 1024}});
  EXPECT_EQ(p.wait_for(300.0), 1) << p.output();
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "error");
  EXPECT_GT(f.read_vector("/time").size(), 1000u);
  expect_consistent(f);
}

TEST(OutputContract, a_failure_before_the_first_sample_leaves_a_file_saying_why) {
  // A car body of 1e30 kg: valid input, but no static equilibrium exists for the suspension.
  const fs::path dir = scratch("equilibrium");
  fs::create_directories(dir / "vehicles");
  std::string vehicle = file_text("scenarios/vehicles/manchester_vehicle1.yaml");
  const std::string mass = "  mass: 32000\n";
  ASSERT_NE(vehicle.find(mass), std::string::npos);
  vehicle.replace(vehicle.find(mass), mass.size(), "  mass: 1.0e30\n");
  const std::string profiles = fs::absolute("data/profiles").string();
  for (const char* name : {"MBench_S1002_v3.prw", "MBench_UIC60_v3.prr"}) {
    const std::string rel = std::string("../../data/profiles/") + name;
    vehicle.replace(vehicle.find(rel), rel.size(), profiles + "/" + name);
  }
  std::ofstream(dir / "vehicles" / "heavy.yaml") << vehicle;
  std::string scene = file_text(kErri);
  const std::string ref = "../vehicles/manchester_vehicle1.yaml";
  ASSERT_NE(scene.find(ref), std::string::npos);
  scene.replace(scene.find(ref), ref.size(), "vehicles/heavy.yaml");
  const std::string table = "../../out/manchester_s1002_uic60_table.h5";  // the shared cache
  ASSERT_NE(scene.find(table), std::string::npos);
  scene.replace(scene.find(table), table.size(),
                fs::absolute("out/manchester_s1002_uic60_table.h5").string());
  std::ofstream(dir / "heavy_scene.yaml") << scene;
  const std::string out = (dir / "e.h5").string();
  const auto r = test::run_capture({test::ferrodyn_exe(), "run",
                                    (dir / "heavy_scene.yaml").string(), "--no-plots", "-q",
                                    "--t-end", "0.01", "-o", out});
  EXPECT_EQ(r.exit_code, 1) << r.output;
  ASSERT_TRUE(fs::exists(out)) << r.output;
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "error");
  EXPECT_NE(f.string_attribute("/", "status_message").find("static_equilibrium"),
            std::string::npos);
  EXPECT_EQ(f.number_attribute("/", "samples"), 0.0);
}

}  // namespace
}  // namespace ferro::scenarios
