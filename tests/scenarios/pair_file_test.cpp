// Wheel-rail pair files: the strict YAML reader gives located errors and exit code 2 for bad
// input; the Manchester benchmark file (external data, no schema_version) reads as is.
#include "ferro/scenarios/pair_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "process.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;

const std::string kData = FERRO_DATA_DIR;
const std::string kA22 = kData + "/manchester_contact_benchmark_a22.yaml";

// A pair file in a scratch folder, with the shipped profiles referenced by absolute path.
std::string write_pair(const std::string& name, const std::string& track_extra,
                       const std::string& top_extra = "") {
  const fs::path dir = fs::temp_directory_path() / "ferro_pair_file";
  fs::create_directories(dir);
  const fs::path path = dir / (name + ".yaml");
  std::ofstream(path) << top_extra << "track:\n  gauge: 1435.0\n"
                      << track_extra << "  rail_profile: " << kData
                      << "/profiles/MBench_UIC60_v3.prr\n"
                      << "wheelset:\n  flange_back_distance: 1360.0\n"
                      << "  flange_back_position: -70.0\n  nominal_radius: 460.0\n"
                      << "  wheel_profile: " << kData << "/profiles/MBench_S1002_v3.prw\n";
  return path.string();
}

// Runs `ferrodyn geometry PAIR --no-plot` and expects exit 2 with every fragment in the message.
void expect_bad_pair(const std::string& path, const std::vector<std::string>& fragments) {
  const fs::path out = fs::temp_directory_path() / "ferro_pair_file_out";
  const auto r =
      test::run_capture({FERRODYN_EXE, "geometry", path, "--no-plot", "--out-dir", out.string()});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(path + ":"), std::string::npos) << r.output;
  for (const auto& f : fragments) EXPECT_NE(r.output.find(f), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("bad conversion"), std::string::npos) << r.output;
}

TEST(pair_file, manchester_benchmark_reads_without_schema_version) {
  const PairFile p = load_pair_file(kA22);
  // Values of the published input file, converted from mm.
  EXPECT_DOUBLE_EQ(p.params.track_gauge, 1.435);
  EXPECT_DOUBLE_EQ(p.params.gauge_depth, 0.014);
  EXPECT_DOUBLE_EQ(p.params.flange_back_distance, 1.360);
  EXPECT_DOUBLE_EQ(p.params.flange_back_y, -0.070);
  EXPECT_DOUBLE_EQ(p.params.nominal_radius, 0.460);
  EXPECT_EQ(fs::path(p.rail_profile).filename(), "MBench_UIC60_v3.prr");
}

TEST(pair_file, inclination_ratio_and_angle) {
  EXPECT_DOUBLE_EQ(parse_inclination("1:40", "x"), std::atan(1.0 / 40.0));
  EXPECT_DOUBLE_EQ(parse_inclination("0.025", "x"), 0.025);
  EXPECT_THROW((void)parse_inclination("1:0", "x"), std::invalid_argument);
  EXPECT_THROW((void)parse_inclination("nan", "x"), std::invalid_argument);
}

TEST(pair_file, complex_key_exits_2_located) {
  expect_bad_pair(write_pair("complex_key", "", "? [a, b]\n: 1\n"),
                  {":1:", "a key must be a plain word"});
}

TEST(pair_file, list_for_a_number_exits_2_located) {
  expect_bad_pair(write_pair("list_gauge_height", "  gauge_height: [1]\n"),
                  {":3:", "track.gauge_height", "expected a number, got a list"});
}

TEST(pair_file, duplicate_key_names_both_lines) {
  expect_bad_pair(write_pair("duplicate", "  gauge: 1000.0\n"),
                  {"track.gauge", "first given at line 2, again at line 3"});
}

TEST(pair_file, unknown_key_and_wrong_schema_version) {
  expect_bad_pair(write_pair("unknown", "  gauge_hieght: 14\n"),
                  {"track.gauge_hieght", "did you mean 'gauge_height'?"});
  expect_bad_pair(write_pair("schema", "", "schema_version: 7\n"), {"supported: 1"});
}

TEST(pair_file, profile_in_metres_is_reported_not_conicity_zero) {
  const fs::path dir = fs::temp_directory_path() / "ferro_pair_file";
  fs::create_directories(dir);
  const fs::path rail = dir / "rail_in_metres.txt";
  {
    std::ofstream out(rail);
    for (int i = 0; i <= 30; ++i) {
      const double y = -0.035 + 0.07 * i / 30.0;
      out << y << " " << 0.02 * y * y << "\n";
    }
  }
  std::string text = "track:\n  gauge: 1435.0\n  rail_profile: " + rail.string() +
                     "\nwheelset:\n  flange_back_distance: 1360.0\n  nominal_radius: 460.0\n"
                     "  wheel_profile: " +
                     kData + "/profiles/MBench_S1002_v3.prw\n";
  const fs::path pair = dir / "metres.yaml";
  std::ofstream(pair) << text;
  const auto r = test::run_capture(
      {FERRODYN_EXE, "geometry", pair.string(), "--no-plot", "--out-dir", (dir / "out").string()});
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("implausible profile size"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(rail.string()), std::string::npos) << r.output;
}

TEST(pair_file, non_finite_search_position_exits_2) {
  const std::string prof = kData + "/profiles/";
  for (const char* bad : {"nan", "inf"}) {
    const auto r = test::run_capture(
        {FERRODYN_EXE, "geometry", "search", "--wheel", prof + "MBench_S1002_v3.prw", "--rail",
         prof + "MBench_UIC60_v3.prr", "--flange-back-y", "-0.070", "--y", bad});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--y"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("finite"), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace ferro::scenarios
