// Every verb spells the same thing the same way (-o/--output, --no-plots, SI values, --spin,
// `contact mim`, `geometry pair`); the former spellings still work, hidden from the help, and give
// the same results.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "process.hpp"

namespace {

namespace fs = std::filesystem;
using ferro::test::run_capture;

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ferro_cli_spelling_" + std::to_string(getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string line_with(const std::string& text, const std::string& start) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(start, 0) == 0) return line;
  return "";
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(CliSpelling, help_shows_the_common_spellings_only) {
  for (const std::vector<std::string>& verb :
       {std::vector<std::string>{"contact", "curve"}, {"contact", "patch"}, {"contact", "mim"},
        {"contact", "mim-table"}, {"contact", "wheelset"}, {"geometry", "pair"},
        {"bench", "contact"}}) {
    std::vector<std::string> args = {FERRODYN_EXE};
    args.insert(args.end(), verb.begin(), verb.end());
    args.emplace_back("--help");
    const auto r = run_capture(args);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("--output"), std::string::npos) << verb[1] << r.output;
    for (const char* old : {"--out ", "--out-dir", "--no-png", "--no-plot ", "--a-mm", "--young-gpa"})
      EXPECT_EQ(r.output.find(old), std::string::npos) << verb[1] << ": " << old;
  }
  const auto top = run_capture({FERRODYN_EXE, "--help"});
  EXPECT_EQ(top.output.find("\n  mim "), std::string::npos) << top.output;
}

TEST(CliSpelling, contact_mim_in_si_matches_the_former_mm_spelling) {
  const auto si = run_capture({FERRODYN_EXE, "contact", "mim", "--a", "4e-3", "--b", "3e-3", "--fn",
                               "3e4", "--xi-x", "1e-3", "--young", "210e9", "--elements", "12"});
  const auto old = run_capture({FERRODYN_EXE, "mim", "--a-mm", "4", "--b-mm", "3", "--fn", "3e4",
                                "--xi-x", "1e-3", "--young-gpa", "210", "--elements", "12"});
  ASSERT_EQ(si.exit_code, 0) << si.output;
  ASSERT_EQ(old.exit_code, 0) << old.output;
  EXPECT_FALSE(line_with(si.output, "Fn = ").empty()) << si.output;
  EXPECT_EQ(line_with(si.output, "Fn = "), line_with(old.output, "Fn = "));
  const auto missing = run_capture({FERRODYN_EXE, "contact", "mim", "--b", "3e-3", "--fn", "3e4"});
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("--a"), std::string::npos) << missing.output;
}

TEST(CliSpelling, spin_is_spin_everywhere) {
  const std::vector<std::string> base = {FERRODYN_EXE, "contact", "eval", "--a", "6e-3", "--b",
                                         "4e-3", "--fn", "5e4", "--mu", "0.3"};
  auto with = [&](const char* flag) {
    auto args = base;
    args.insert(args.end(), {flag, "0.2"});
    return run_capture(args);
  };
  const auto spin = with("--spin"), phi = with("--phi");
  ASSERT_EQ(spin.exit_code, 0) << spin.output;
  EXPECT_EQ(spin.output, phi.output);
  EXPECT_NE(spin.output.find("\"force_y\""), std::string::npos);
}

TEST(CliSpelling, geometry_pair_matches_the_former_positional_form) {
  const fs::path dir = scratch("pair");
  const std::string pair = std::string(FERRO_DATA_DIR) + "/manchester_contact_benchmark_a22.yaml";
  const auto now = run_capture({FERRODYN_EXE, "geometry", "pair", pair, "-o",
                                (dir / "new").string(), "--no-plots"});
  const auto before = run_capture({FERRODYN_EXE, "geometry", pair, "--out-dir",
                                   (dir / "old").string(), "--no-plot"});
  ASSERT_EQ(now.exit_code, 0) << now.output;
  ASSERT_EQ(before.exit_code, 0) << before.output;
  const std::string conicity = read(dir / "new" / "conicity.csv");
  EXPECT_GT(conicity.size(), 100u);
  EXPECT_EQ(conicity, read(dir / "old" / "conicity.csv"));
}

TEST(CliSpelling, curve_output_and_plots_switch) {
  const fs::path dir = scratch("curve");
  const std::string yaml = "scenarios/cases/contact/thesis_spheres.yaml";
  const auto now = run_capture({FERRODYN_EXE, "contact", "curve", yaml, "-o",
                                (dir / "new").string(), "--no-plots"});
  const auto before = run_capture({FERRODYN_EXE, "contact", "curve", yaml, "--out",
                                   (dir / "old").string(), "--no-png"});
  ASSERT_EQ(now.exit_code, 0) << now.output;
  ASSERT_EQ(before.exit_code, 0) << before.output;
  EXPECT_FALSE(fs::exists(dir / "new" / "thesis_spheres_curves.png"));
  const std::string csv = read(dir / "new" / "thesis_spheres_curves.csv");
  EXPECT_GT(csv.size(), 1000u);
  EXPECT_EQ(csv, read(dir / "old" / "thesis_spheres_curves.csv"));
}

}  // namespace
