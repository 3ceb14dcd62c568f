// Choosing the cases of a wheelset-contact study (`contact wheelset --cases`) and the paths and
// folder checks of a verb's output (ferro/scenarios/claimed_output.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "ferro/scenarios/claimed_output.hpp"
#include "ferro/scenarios/wheelset_contact_run.hpp"

namespace ferro::scenarios {
namespace {

WheelsetContactInput three_cases() {
  WheelsetContactInput in;
  for (int id : {1, 2, 3}) {
    contact::WheelsetCase c;
    c.id = id;
    c.lateral = 1e-3 * id;
    in.cases.push_back(c);
  }
  return in;
}

TEST(WheelsetCases, KeptInTheOrderAsked) {
  WheelsetContactInput in = three_cases();
  select_wheelset_cases(in, {3, 1}, "study.yaml");
  ASSERT_EQ(in.cases.size(), 2u);
  EXPECT_EQ(in.cases[0].id, 3);
  EXPECT_EQ(in.cases[0].lateral, 3e-3);
  EXPECT_EQ(in.cases[1].id, 1);
  WheelsetContactInput all = three_cases();
  select_wheelset_cases(all, {}, "study.yaml");
  EXPECT_EQ(all.cases.size(), 3u);
}

TEST(WheelsetCases, UnknownIdNamesTheFileAndTheIds) {
  WheelsetContactInput in = three_cases();
  try {
    select_wheelset_cases(in, {2, 9}, "study.yaml");
    FAIL() << "case 9 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--cases: case 9 is not in study.yaml (ids 1..3)");
  }
}

TEST(ClaimedOutput, SiblingAndPlotFolder) {
  EXPECT_EQ(sibling("out/run.h5", "_plots"), "out/run_plots");
  EXPECT_EQ(sibling("run.h5", "_eig.h5"), "run_eig.h5");
  namespace fs = std::filesystem;
  const fs::path base = fs::temp_directory_path() / "ferro_claimed_output_test";
  fs::remove_all(base);
  fs::create_directories(base);
  // A missing folder is made for the probe and removed again.
  check_plot_folder((base / "a" / "b").string(), "plots");
  EXPECT_FALSE(fs::exists(base / "a"));
  // Below a file: refused, naming the option and the file.
  std::ofstream(base / "file") << "x";
  try {
    check_plot_folder((base / "file" / "p").string(), "--plot-dir");
    FAIL() << "a folder below a file accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--plot-dir: cannot write the plots in"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("is not a folder"), std::string::npos);
  }
  fs::remove_all(base);
}

}  // namespace
}  // namespace ferro::scenarios
