// `ferrodyn geometry search`: JSON for one position, CSV batch, exit code 2 on bad input.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace {

struct CliRun {
  int code;
  std::string out;
};

CliRun run(const std::string& args) {
  const std::string cmd = std::string(FERRODYN_EXE) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf{};
  while (p && fgets(buf.data(), buf.size(), p)) out += buf.data();
  const int status = p ? pclose(p) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

const std::string kProfiles = std::string(FERRO_DATA_DIR) + "/profiles/";
const std::string kPair = "--wheel " + kProfiles + "MBench_S1002_v3.prw --rail " + kProfiles +
                          "MBench_UIC60_v3.prr --gauge 1.435 --flange-back 1.360 "
                          "--flange-back-y -0.070 --radius 0.460";

}  // namespace

TEST(geometry_cli, search_prints_every_contact_point_as_json) {
  // Manchester case 14 (y = 6.5 mm), 2 x 10 kN: tread on the left, flange on the right.
  const CliRun r = run("geometry search " + kPair +
                       " --y 0.0065 --roll -0.004376 --yaw 0.0156 --load 20000");
  ASSERT_EQ(r.code, 0) << r.out;
  const auto json = nlohmann::json::parse(r.out);
  const auto& points = json.at("points");
  EXPECT_EQ(points.size(), 2u);
  bool flange = false;
  double total = 0.0;
  for (const auto& p : points) {
    const std::string side = p.at("side");
    EXPECT_TRUE(side == "left" || side == "right") << side;
    flange = flange || p.at("flange").get<bool>();
    total += p.at("normal_force_n").get<double>() *
             std::cos(p.at("contact_angle_deg").get<double>() * 3.14159265358979 / 180.0);
  }
  EXPECT_TRUE(flange);
  EXPECT_NEAR(total, 20000.0, 1e-2);  // vertical equilibrium of the solved pose
}

TEST(geometry_cli, former_millimetre_spellings_are_aliases_of_the_si_options) {
  // The same Manchester case 14 through the hidden former spellings: the same output.
  const std::string si = " --y 0.0065 --roll -0.004376 --yaw 0.0156 --load 20000";
  const std::string old = " --y-mm 6.5 --roll-rad -0.004376 --yaw-rad 0.0156 --load-n 20000";
  const CliRun a = run("geometry search " + kPair + si);
  const CliRun b = run("geometry search --wheel " + kProfiles + "MBench_S1002_v3.prw --rail " +
                       kProfiles + "MBench_UIC60_v3.prr --gauge-mm 1435 --flange-back-mm 1360 " +
                       "--flange-back-y-mm -70 --radius-mm 460 --shear-modulus 82e9" + old);
  ASSERT_EQ(a.code, 0) << a.out;
  ASSERT_EQ(b.code, 0) << b.out;
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  EXPECT_EQ(ja.at("points"), jb.at("points"));
  // The pose echo differs by the mm -> m -> mm round trip only.
  constexpr double kRoundTrip = 1e-12;  // [mm], a few ulps of 6.5
  for (const char* key : {"y_mm", "height_mm", "roll_rad", "yaw_rad"}) {
    EXPECT_NEAR(ja.at("pose").at(key).get<double>(), jb.at("pose").at(key).get<double>(),
                kRoundTrip)
        << key;
  }
  // Both spellings at once, or a height with a load: bad input naming the option.
  const CliRun twice = run("geometry search " + kPair + " --y 0.0065 --y-mm 6.5");
  EXPECT_EQ(twice.code, 2) << twice.out;
  EXPECT_NE(twice.out.find("--y-mm"), std::string::npos) << twice.out;
  const CliRun both = run("geometry search " + kPair + " --height-mm 0.1 --load 20000");
  EXPECT_EQ(both.code, 2) << both.out;
  EXPECT_NE(both.out.find("--load"), std::string::npos) << both.out;
}

TEST(geometry_cli, batch_csv_in_csv_out) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string in = (dir / "ferro_geometry_batch_in.csv").string();
  const std::string out = (dir / "ferro_geometry_batch_out.csv").string();
  std::filesystem::remove(out);  // an output is replaced only with --overwrite
  std::ofstream(in)
      << "case,y_mm,roll_rad,yaw_rad,load_n\n1,0,0,0,20000\n11,5.0,-0.0003554,0.012,20000\n";
  const CliRun r = run("geometry search " + kPair + " --batch " + in + " -o " + out);
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream f(out);
  std::string line;
  int rows = 0, case11_right = 0;
  std::getline(f, line);
  EXPECT_NE(line.find("contact_angle_deg"), std::string::npos);
  while (std::getline(f, line)) {
    ++rows;
    if (line.rfind("11,", 0) == 0 && line.find(",right,") != std::string::npos) ++case11_right;
  }
  // Centred: the two connected lobes of each wheel are two members of one joined run (each
  // wheel's gap has two minima under the rail); y = 5 mm: 1 left + 2 right (separate runs).
  EXPECT_EQ(rows, 4 + 3);
  EXPECT_EQ(case11_right, 2);  // two-point contact on the right wheel
}

TEST(geometry_cli, bad_input_exits_with_code_2_and_names_it) {
  const CliRun r1 =
      run("geometry search --wheel /nonexistent.prw --rail " + kProfiles + "MBench_UIC60_v3.prr");
  EXPECT_EQ(r1.code, 2);
  EXPECT_NE(r1.out.find("/nonexistent.prw"), std::string::npos);
  const CliRun r2 = run("geometry search " + kPair + " --inclination 1:x");
  EXPECT_EQ(r2.code, 2);
  EXPECT_NE(r2.out.find("--inclination"), std::string::npos);
  const CliRun r3 = run("geometry search --wheel " + kProfiles + "MBench_S1002_v3.prw --rail " +
                        kProfiles + "MBench_UIC60_v3.prr --gauge 14.35");
  EXPECT_EQ(r3.code, 2);
  EXPECT_NE(r3.out.find("track_gauge"), std::string::npos);
}

TEST(geometry_cli, pair_yaml_writes_table_diagram_and_conicity) {
  // The Manchester benchmark file is a valid PAIR.yaml (track + wheelset keys, paths relative).
  const auto dir = std::filesystem::temp_directory_path() / "ferro_geometry_pair";
  std::filesystem::remove_all(dir);
  const CliRun r =
      run("geometry pair " + std::string(FERRO_DATA_DIR) +
          "/manchester_contact_benchmark_a22.yaml --no-plots -o " + dir.string());
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* f : {"contact_table.h5", "contact_points.csv", "conicity.csv", "profiles.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
  std::ifstream con(dir / "conicity.csv");
  std::string line;
  int rows = 0;
  while (std::getline(con, line)) ++rows;
  EXPECT_EQ(rows, 21);  // header + amplitudes 0.5 .. 10 mm
  const CliRun bad = run("geometry pair /nonexistent/pair.yaml --no-plots");
  EXPECT_EQ(bad.code, 2);
}
