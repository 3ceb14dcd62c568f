// The requests behind the command line's verbs, as the library holds them: each parameter's
// limits and former keys, the pose search with former batch columns, the contact evaluation, the
// sweep's files, the eigenvalue study's scene and the work-precision checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>

#include "ferro/scenarios/analysis/studies.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"
#include "ferro/scenarios/contact_files.hpp"
#include "ferro/scenarios/mim_solve.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/pose_output.hpp"
#include "ferro/scenarios/pose_search.hpp"
#include "ferro/scenarios/run.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/scenarios/work_precision.hpp"

namespace ferro::scenarios {
namespace {

const Parameter& find(const Parameters& ps, const std::string& key) {
  for (const Parameter& p : ps)
    if (p.key == key) return p;
  throw std::logic_error("no parameter " + key);
}

std::string scene_path(const std::string& name) {
  return std::string(FERRO_SOURCE_DIR) + "/scenarios/scenes/" + name;
}

TEST(VerbRequests, parameters_carry_the_limits_the_command_line_checks) {
  RunOverrides o;
  const Parameters ps = parameters(o);
  ASSERT_TRUE(find(ps, "t_end").range);
  EXPECT_EQ(find(ps, "t_end").range->problem("0"), "must be > 0 s, got '0'");
  EXPECT_EQ(find(ps, "speed").range->problem("0"), "");  // standing still is a speed
  EXPECT_NE(find(ps, "rtol").range->problem("1"), "");
  ASSERT_TRUE(find(ps, "points").count);
  EXPECT_NE(find(ps, "points").count->problem("1"), "");  // a sweep needs two speeds
  EXPECT_FALSE(find(ps, "integrator").range);
  analysis::SweepRequest s;
  EXPECT_EQ(find(parameters(s), "jobs").count->problem("0"),
            "must be a whole number in 1..1024, got '0'");
}

TEST(VerbRequests, former_keys_convert_to_si) {
  PoseInput pose;
  EXPECT_EQ(find(parameters(pose), "y").former->key, "y_mm");
  EXPECT_EQ(find(parameters(pose), "y").former->to_si, 1e-3);
  MimRequest mim;
  EXPECT_EQ(find(parameters(mim), "young").former->key, "young_gpa");
  EXPECT_EQ(find(parameters(mim), "young").former->to_si, 1e9);
}

SearchPairOptions manchester_pair() {
  SearchPairOptions o;
  const std::string profiles = std::string(FERRO_DATA_DIR) + "/profiles/";
  o.wheel = profiles + "MBench_S1002_v3.prw";
  o.rail = profiles + "MBench_UIC60_v3.prr";
  o.flange_back = 1.360;
  o.flange_back_y = -0.070;
  o.radius = 0.460;
  return o;
}

TEST(VerbRequests, pose_batch_reads_former_columns_as_their_si_keys) {
  // The same Manchester case 11 position given in SI columns and in the former mm/rad/N
  // columns: the same contact points.
  const auto pair = make_search_pair(manchester_pair());
  const double estar = pose_search_modulus(82e9, 0.28);
  const auto rows = [&](const std::string& csv) {
    std::istringstream in(csv);
    std::string out;
    search_pose_batch(pair, in, "test", PoseInput{}, estar,
                      [&](const std::string& text) { out += text; });
    return out.substr(out.find('\n') + 1);  // without the header
  };
  const std::string si = rows("y,roll,yaw,load\n0.005,-0.0003554,0.012,20000\n");
  const std::string old = rows("y_mm,roll_rad,yaw_rad,load_n\n5,-0.0003554,0.012,20000\n");
  ASSERT_NE(si.find("right"), std::string::npos) << si;
  // Each row echoes its input cells first; the solution after them is the same.
  const auto solved = [](const std::string& text) {
    std::string s;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      std::size_t at = 0;
      for (int i = 0; i < 4; ++i) at = line.find(',', at) + 1;
      s += line.substr(at) + "\n";
    }
    return s;
  };
  EXPECT_EQ(solved(si), solved(old));
}

TEST(VerbRequests, pose_search_refuses_a_height_with_a_load) {
  PoseInput pose;
  pose.height = 1e-4;
  pose.load = 2e4;
  std::ostringstream out;
  try {
    search_poses(manchester_pair(), pose, "", "-", false, out, Spelling::option);
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--load"), std::string::npos) << e.what();
  }
}

TEST(VerbRequests, contact_eval_in_the_linear_range_is_kalker_linear_law) {
  // F_x = -G a b C11 xi_x for Kalker's linear theory (same material: G the shear modulus).
  EvalRequest r;
  r.input.a = 6e-3;
  r.input.b = 4e-3;
  r.input.fn = 5e4;
  r.input.mu = 0.3;
  r.input.xi_x = 1e-4;
  r.input.model = "kalker_linear";
  std::istringstream no_input;
  std::ostringstream out;
  run_contact_eval(r, false, no_input, "stdin", out);
  const auto j = nlohmann::json::parse(out.str());
  const double expected = -82e9 * 6e-3 * 4e-3 * j.at("c11").get<double>() * 1e-4;
  constexpr double kRoundOff = 1e-12;  // relative: one product, a few ulps
  EXPECT_NEAR(j.at("force_x").get<double>(), expected, std::abs(expected) * kRoundOff);
  EXPECT_EQ(out.str().back(), '\n');
  // A batch: one row per case after the header.
  std::istringstream batch("xi_x\n1e-4\n-1e-4\n");
  std::ostringstream rows;
  run_contact_eval(r, true, batch, "stdin", rows);
  const std::string text = rows.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3) << text;
  r.options = {"no_equals"};
  EXPECT_THROW(run_contact_eval(r, false, no_input, "stdin", out), std::invalid_argument);
}

TEST(VerbRequests, sweep_files_claimed_by_the_writer_only) {
  const Scene scene = load_scene(scene_path("wheelset_hunting.yaml"));
  const auto dir = std::filesystem::temp_directory_path() / "ferro_sweep_files";
  std::filesystem::create_directories(dir);
  const std::string given = (dir / "s.h5").string();
  std::filesystem::remove(given);
  analysis::SweepRequest reader;
  const auto other = analysis::claim_sweep_files(scene, given, false, true, false, reader);
  EXPECT_FALSE(other.claimed);
  EXPECT_EQ(reader.output, given);
  EXPECT_EQ(reader.journal, given + ".points");
  analysis::SweepRequest writer;
  auto files = analysis::claim_sweep_files(scene, given, false, true, true, writer);
  ASSERT_TRUE(files.claimed);
  EXPECT_NE(writer.output, given);  // written under a temporary name until commit
  EXPECT_EQ(files.claimed->commit(), given);
  EXPECT_TRUE(std::filesystem::exists(given));
  // Without -o: beside the scene's output file.
  analysis::SweepRequest fallback;
  const auto beside = analysis::claim_sweep_files(scene, "", false, true, false, fallback);
  EXPECT_EQ(beside.output, sibling(scene.output.file, "_sweep.h5"));
}

TEST(VerbRequests, eigen_study_has_its_own_range_and_checks_the_factors) {
  const Scene scene = load_scene(scene_path("wheelset_hunting.yaml"));
  analysis::EigenRequest r;
  const Scene s = analysis::eigen_study_scene(scene, r);
  EXPECT_EQ(s.eigen.speed_min, 1.0);
  EXPECT_EQ(s.eigen.speed_max, 150.0);
  EXPECT_EQ(s.eigen.points, 150);
  r.k11 = 1.5;  // K_ij lie in (0, 1]
  EXPECT_THROW((void)analysis::eigen_study_scene(scene, r), std::invalid_argument);
}

TEST(VerbRequests, work_precision_refuses_a_negative_settling_time) {
  const Scene scene = load_scene(scene_path("wheelset_hunting.yaml"));
  WorkPrecisionOptions o;
  o.settle = -1.0;
  EXPECT_THROW(check_work_precision(scene, o), std::invalid_argument);
  o.settle = 0.5;
  EXPECT_NO_THROW(check_work_precision(scene, o));
}

}  // namespace
}  // namespace ferro::scenarios
