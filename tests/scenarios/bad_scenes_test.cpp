// Malformed scene files: each must give exit code 2 and a message naming the file, the line and
// the key (tests/scenarios/data/bad/*.yaml).
#include <gtest/gtest.h>

#include <filesystem>

#include "process.hpp"

namespace ferro::scenarios {
namespace {

struct BadScene {
  const char* file;  // in tests/scenarios/data/bad
  int line;          // expected line in the message
  const char* key;   // expected key path in the message
  const char* hint;  // another expected fragment (allowed values, suggestion, ...)
};

const BadScene kBadScenes[] = {
    {"missing_mass", 4, "model.mass", "missing required key 'mass'"},
    {"wrong_type_mass", 5, "model.mass", "expected a number, got 'heavy'"},
    {"unknown_key", 9, "model.conicty", "did you mean 'conicity'?"},
    {"negative_mass", 5, "model.mass", "must be a finite positive value in kg"},
    {"nan_conicity", 9, "model.conicity", "expected a finite number"},
    {"unknown_integrator", 22, "solver.integrator", "did you mean 'cvode_bdf'?"},
    {"truncated", 14, "(document)", "malformed YAML"},
    {"missing_schema_version", 1, "schema_version", "reads schema_version 1"},
    {"wrong_schema_version", 1, "schema_version", "supported: 1"},
    {"negative_rtol", 23, "solver.rtol", "must lie in (0, 1)"},
    {"max_order_too_high", 24, "solver.max_order", "1..5 for cvode_bdf"},
    {"stability_flag_not_boolean", 24, "solver.stability_limit_detection", "allowed: true, false"},
    {"unknown_signal", 26, "output.csv", "did you mean 'wheelset.y'?"},
    {"unknown_initial_state", 20, "simulation.initial.wheelset.lateral",
     "valid keys here: wheelset.y"},
    {"zero_t_end", 19, "simulation.t_end", "must be > 0 s"},
    {"missing_include", 12, "track", "does not exist"},
    {"poisson_out_of_range", 17, "contact.wheel.poisson", "must lie in [0, 0.5)"},
    {"unknown_model_type", 4, "model.type", "allowed: suspended_wheelset"},
    {"list_at_top", 1, "(document)", "expected a mapping"},
    {"duplicate_speed", 19, "simulation.speed_kmh", "not both"},
    {"vehicle_off_track", 10, "simulation.t_end", "runs off the track"},
    {"vehicle_unknown_scope", 5, "model.scope", "did you mean 'bogie'?"},
    {"vehicle_curve_without_radius", 9, "track.sections[2].radius", "missing required key"},
    {"vehicle_bad_contact_override", 8, "contact.tangential_options", "mz"},
    {"vehicle_semi_hertz_imported", 9, "contact.normal",
     "allowed: normal hertz with geometry 'imported', or normal semi_hertz with geometry table "
     "or search"},
    {"duplicate_key", 19, "simulation.speed", "first given at line 18, again at line 19"},
    {"complex_key", 17, "(key)", "a key must be a plain word, got '? '"},
    {"second_document", 27, "(document)", "2 YAML documents in one file"},
    {"deep_nesting", 20, "(document)", "nested deeper than"},
    {"include_directory", 12, "track", "is a directory"},
    {"include_name_too_long", 12, "track", "File name too long"},
    {"leading_comma", 1, "(document)", "',' outside [ ] or { }"},
    {"output_between_steps", 26, "output.interval", "not a whole multiple of solver.fixed_step"},
};

class BadSceneFile : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneFile, exits_2_naming_file_line_and_key) {
  const auto& c = GetParam();
  const std::string path = std::string("tests/scenarios/data/bad/") + c.file + ".yaml";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  const std::vector<std::vector<std::string>> commands = {
      {FERRODYN_EXE, "validate", path},
      {FERRODYN_EXE, "run", path, "--no-plots", "-o",
       "/tmp/ferro_bad_" + std::string(c.file) + ".h5"}};
  for (const auto& cmd : commands) {
    const auto r = test::run_capture(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd[1] << ": " << r.output;
    EXPECT_NE(r.output.find(path + ":" + std::to_string(c.line) + ":"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(c.key), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.hint), std::string::npos) << r.output;
  }
}

INSTANTIATE_TEST_SUITE_P(Malformed, BadSceneFile, ::testing::ValuesIn(kBadScenes),
                         [](const auto& info) { return std::string(info.param.file); });

TEST(BadSceneFile, every_file_in_the_folder_is_covered) {
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator("tests/scenarios/data/bad")) {
    if (e.path().extension() == ".yaml") ++files;
  }
  EXPECT_EQ(files, std::size(kBadScenes));
  EXPECT_GE(files, 10u);
}

TEST(BadCommandLine, unknown_option_and_missing_file_exit_2) {
  EXPECT_EQ(
      test::run_capture({FERRODYN_EXE, "run", "tests/scenarios/data/good_minimal.yaml", "--warp"})
          .exit_code,
      2);
  const auto r = test::run_capture({FERRODYN_EXE, "run", "no/such/scene.yaml"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("no/such/scene.yaml"), std::string::npos) << r.output;
  const auto r2 =
      test::run_capture({FERRODYN_EXE, "run", "tests/scenarios/data/good_minimal.yaml",
                         "--integrator", "leapfrog", "--no-plots", "-o", "/tmp/ferro_unused.h5"});
  EXPECT_EQ(r2.exit_code, 2);
  EXPECT_NE(r2.output.find("leapfrog"), std::string::npos) << r2.output;
}

}  // namespace
}  // namespace ferro::scenarios
