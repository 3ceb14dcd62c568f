// `ferrodyn validate` runs every check `run` makes before its first step (it builds the model
// through the same factory), so a scene validate accepts, run accepts. Each case below is one
// kind of key with a bad value that the loader alone let through while the model, its contact
// geometry, its tables or the run refused it (or never finished): validate must now refuse it,
// naming the file, line, column and key, and run must refuse it the same way.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "process.hpp"
#include "scene_edits.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;
const std::string M = "scenarios/vehicles/manchester_vehicle1.yaml";
const std::string C = "scenarios/vehicles/cooperrider_wagon.yaml";
const std::string EF = "scenarios/scenes/manchester_straight_erri.yaml";
const std::string TD = "scenarios/scenes/thesis_derailment.yaml";
const std::string TT = "scenarios/parts/thesis_derailment_track.yaml";
const std::string CS = "scenarios/scenes/cooperrider_straight.yaml";
const std::string CU = "scenarios/scenes/manchester_curve_1200.yaml";

struct Mutation {
  std::string name;
  std::string file, from, to;  // the edit, in a repository file
  std::string scene;           // the scene run with it
  // The message names this key (at the end of its key path); "a|b" for a rule relating two
  // keys, which the loader may place at either.
  std::string key;
};

// Refused by run but accepted by validate (or never ending under run) before validate built the
// model; then the values nonsense to both.
const std::vector<Mutation> kMutations = {
    {"wheelset flange_back_distance negative", M, "flange_back_distance: 1.360",
     "flange_back_distance: -1", EF, "wheelset.flange_back_distance|wheel_rail.flange_back_distance"},
    {"wheelset flange_back_distance beyond the gauge", M, "flange_back_distance: 1.360",
     "flange_back_distance: 1.5", EF, "wheelset.flange_back_distance|wheel_rail.flange_back_distance"},
    {"nominal_rolling_radius 5 m", M, "nominal_rolling_radius: 0.46", "nominal_rolling_radius: 5",
     EF, "wheelset.nominal_rolling_radius"},
    {"nominal_rolling_radius 5 cm", M, "nominal_rolling_radius: 0.46",
     "nominal_rolling_radius: 0.05", EF, "wheelset.nominal_rolling_radius"},
    {"vehicle rail_inclination", M, "rail_inclination: 0.0", "rail_inclination: 0.5", EF,
     "wheel_rail.rail_inclination"},
    {"scene contact rail_inclination", TD, "rail_inclination: 0.0746739", "rail_inclination: -1",
     TD, "contact.rail_inclination"},
    {"vehicle geometry track_gauge below the flange backs", M, "track_gauge: 1.435",
     "track_gauge: 1.3", EF, "geometry.track_gauge|wheel_rail.flange_back_distance"},
    {"vehicle wheel_rail track_gauge", M, "  poisson: 0.28\n", "  poisson: 0.28\n  track_gauge: 1.3\n",
     EF, "wheel_rail.track_gauge|wheel_rail.flange_back_distance"},
    {"vehicle wheel_rail flange_back_distance", M, "  poisson: 0.28\n",
     "  poisson: 0.28\n  flange_back_distance: 2\n", EF, "wheel_rail.flange_back_distance"},
    {"vehicle wheel_rail flange_back_y", M, "  poisson: 0.28\n",
     "  poisson: 0.28\n  flange_back_y: 0.5\n", EF, "wheel_rail.flange_back_y"},
    {"scene contact track_gauge", TD, "  friction: 0.5\n", "  friction: 0.5\n  track_gauge: 1.3\n",
     TD, "contact.track_gauge|contact.flange_back_distance"},
    {"scene contact flange_back_distance", TD, "  friction: 0.5\n",
     "  friction: 0.5\n  flange_back_distance: -1\n", TD, "contact.flange_back_distance"},
    {"scene contact flange_back_y", TD, "  friction: 0.5\n", "  friction: 0.5\n  flange_back_y: -0.5\n",
     TD, "contact.flange_back_y"},
    {"track part gauge", TT, "schema_version: 1\n", "schema_version: 1\ngauge: 1.3\n", TD,
     "track.gauge|contact.flange_back_distance"},
    {"gravity zero", C, "gravity: 9.81", "gravity: 0", CS, "gravity"},
    {"output.plots unknown signal", EF, "plots: [wheelset_1.left.Y,", "plots: [no_such.signal,",
     EF, "output.plots"},
    {"output.csv unknown signal", EF, "  interval: 5.0e-3\n",
     "  interval: 5.0e-3\n  csv: [no_such.signal]\n", EF, "output.csv"},
    {"simulation.initial unknown state", EF, "  t_end: 10.0\n",
     "  t_end: 10.0\n  initial: {no_such.y: 0.001}\n", EF, "simulation.initial.no_such.y"},
    {"simulation.initial beyond the state's bound", EF, "  t_end: 10.0\n",
     "  t_end: 10.0\n  initial: {wheelset_1.y: 0.5}\n", EF, "simulation.initial.wheelset_1.y"},
    {"model.frozen spin", EF, "  type: vehicle\n", "  type: vehicle\n  frozen: [wheelset_1.spin]\n",
     EF, "model.frozen"},
    {"wheel_profile not a profile", EF, "  tangential: chopaya\n",
     "  tangential: chopaya\n  wheel_profile: ../../README.md\n", EF, "contact.wheel_profile"},
    {"rail_profile not a profile", EF, "  tangential: chopaya\n",
     "  tangential: chopaya\n  rail_profile: ../../README.md\n", EF, "contact.rail_profile"},
    {"wheel_profile a folder", TD, "wheel_profile: ../../data/profiles/MBench_S1002_v3.prw",
     "wheel_profile: ../../data/profiles", TD, "contact.wheel_profile"},
    {"imported_table not a table", C,
     "imported_table: ../../data/cooperrider_wagon/contact_table_s1002_uic60_1in40.csv",
     "imported_table: ../../README.md", CS, "wheel_rail.imported_table"},
    {"imported_table a folder", C,
     "imported_table: ../../data/cooperrider_wagon/contact_table_s1002_uic60_1in40.csv",
     "imported_table: ../../data", CS, "wheel_rail.imported_table"},
    {"table_file a folder", EF, "table_file: ../../out/manchester_s1002_uic60_table.h5",
     "table_file: ../../scenarios", EF, "contact.table_file"},
    {"reduction_table not a table", EF, "  tangential: chopaya\n",
     "  tangential: chopaya\n  reduction_table: ../../README.md\n", EF, "contact.reduction_table"},
    {"reduction_table_point unknown axis", EF, "  tangential: chopaya\n",
     "  tangential: chopaya\n  reduction_table: ../../fe_contact/examples/thesis_layer_study.h5\n"
     "  reduction_table_point: {nope: 1}\n",
     EF, "contact.reduction_table_point"},
    {"reduction_table_point missing an axis", EF, "  tangential: chopaya\n",
     "  tangential: chopaya\n  reduction_table: ../../fe_contact/examples/thesis_layer_study.h5\n"
     "  reduction_table_point: {layer_thickness: 125.0e-6}\n",
     EF, "contact.reduction_table_point"},
    {"conical tread join beyond the tread", TD, "join_y: -0.026", "join_y: 0.099", TD,
     "contact.wheel_conical_tread.join_y"},
    {"measured irregularity file not irregularities", TT, "irregularities:\n",
     "irregularities:\n  - {type: measured, file: ../../README.md}\n", TD, "file"},
    {"track length 1.4e18 m", EF, "length: 600", "length: 1.4e18", EF, "length"},
    {"irregularity wavelength_max 1.4e18 m", EF, "wavelength_max: 150",
     "wavelength_max: 1.4e18", EF, "wavelength_max"},
    {"car body below the rails", M, "  cg_height: 1.8", "  cg_height: -1", EF, "car_body.cg_height"},
    {"secondary springs at rail level", M, "secondary_height: 0.8275", "secondary_height: 0", EF,
     "geometry.secondary_height"},
    {"contact_half_distance zero", C, "contact_half_distance: 0.75", "contact_half_distance: 0", CS,
     "wheel_rail.contact_half_distance"},
    {"curve radius 1 mm", CU, "radius: 1200", "radius: 0.001", CU, "radius"},
};

std::string scratch_out(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ferro_agreement_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return (dir / (name + ".h5")).string();
}

TEST(ValidateAgreement, the_kinds_of_key_cover_thirty_one_keys) {
  std::set<std::string> keys;
  for (const auto& m : kMutations) keys.insert(m.file + ":" + m.key);
  EXPECT_GE(keys.size(), 31u);
}

TEST(ValidateAgreement, validate_refuses_what_run_refuses_at_the_same_key) {
  int index = 0;
  for (const Mutation& m : kMutations) {
    SCOPED_TRACE(m.name);
    // The edited file replaces its original in the mirror; the scene there names it.
    const std::string edited_name = "edited_" + std::to_string(index++) + ".yaml";
    const std::string edited = test::edited_copy(m.file, m.from, m.to, edited_name);
    std::string scene = (test::scene_mirror() / m.scene).string();
    if (m.file != m.scene) {
      // Point the scene at the edited file (the value naming it, not a comment).
      const fs::path rel = fs::path("..") / fs::path(m.file).parent_path().filename() /
                           fs::path(m.file).filename();
      const std::string original = ": " + rel.string();
      const std::string scene_text = test::text_of(m.scene);
      if (scene_text.find(original) != std::string::npos) {
        scene = test::edited_copy(
            m.scene, original, ": " + (rel.parent_path() / edited_name).string(),
            "scene_" + edited_name);
      } else {
        ADD_FAILURE() << m.scene << " does not name " << original;
        continue;
      }
    } else {
      scene = edited;
    }
    const std::string located = fs::path(edited).filename().string() +
                                ":[0-9]+:[0-9]+: [^ ]*(?:" +
                                std::regex_replace(m.key, std::regex("\\."), "\\.") + ")";
    const auto v = test::run_capture({test::ferrodyn_exe(), "validate", scene}, 60);
    EXPECT_EQ(v.exit_code, 2) << v.output;
    EXPECT_TRUE(std::regex_search(v.output, std::regex(located))) << located << "\n" << v.output;
    const auto r = test::run_capture({test::ferrodyn_exe(), "run", scene, "--t-end", "0.002",
                                      "--no-plots", "-q", "-o", scratch_out(edited_name)},
                                     60);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex(located))) << located << "\n" << r.output;
  }
}

}  // namespace
}  // namespace ferro::scenarios
