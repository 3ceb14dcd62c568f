// Every option and scene value is read strictly: NaN, empty, zero or negative where meaningless
// are refused with the allowed range (exit 2, nothing written); the work a verb is asked for is
// bounded before it starts; nonsense scene values are refused at their key and line; a vehicle
// may stand still (--speed 0).
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "ferro/scenarios/h5_output.hpp"
#include "process.hpp"
#include "scene_edits.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;
const std::string kMinimal = "tests/scenarios/data/good_minimal.yaml";
const std::string kHunting = "scenarios/scenes/wheelset_hunting.yaml";
const std::string kVehicle = "scenarios/scenes/manchester_straight_erri.yaml";
// Refusals come before any work: well under this even on a loaded machine.
constexpr double kRefusalSeconds = 30.0;

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / ("ferro_strict_input_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

using test::text_of;

// The repository file `source` edited (test::edited_copy), or any file written into `dir`.
std::string edited(const std::string& source, const std::string& from, const std::string& to,
                   const std::string& name, const fs::path& dir = {}) {
  if (dir.empty()) return test::edited_copy(source, from, to, name);
  std::string text = text_of(source);
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

// Copies the attributes of `object` (a group or a dataset) from `in` to `out`.
void copy_attributes(const H5File& in, H5File& out, const std::string& object) {
  for (const auto& attr : in.attribute_names(object)) {
    try {
      out.set_attribute(object, attr, in.integer_attribute(object, attr));
      continue;
    } catch (const std::exception&) {
    }
    try {
      out.set_attribute(object, attr, in.number_attribute(object, attr));
    } catch (const std::exception&) {
      out.set_attribute(object, attr, in.string_attribute(object, attr));
    }
  }
}

// Copies `group` of `in` with everything under it (numeric and text datasets) into `out`, but
// /signals/position, which the caller writes.
void copy_object(const H5File& in, H5File& out, const std::string& group) {
  out.ensure_group(group);
  copy_attributes(in, out, group);
  for (const auto& name : in.members(group)) {
    const std::string path = (group == "/" ? "" : group) + "/" + name;
    if (path == "/signals/position") continue;
    bool is_group = true;
    try {
      (void)in.members(path);
    } catch (const std::exception&) {
      is_group = false;
    }
    if (is_group) {
      copy_object(in, out, path);
      continue;
    }
    try {
      io::Dims dims;
      const auto values = in.read_array(path, &dims);
      out.write_array(path, values, dims);
    } catch (const std::exception&) {
      out.write_text(path, in.read_text(path));
    }
    copy_attributes(in, out, path);
  }
}

struct Refusal {
  std::vector<std::string> args;  // after the program
  std::string names;              // the message must name this
};

void expect_refused(const Refusal& c) {
  std::vector<std::string> args = {test::ferrodyn_exe()};
  args.insert(args.end(), c.args.begin(), c.args.end());
  std::string shown;
  for (const auto& a : c.args) shown += " '" + a + "'";
  const auto start = std::chrono::steady_clock::now();
  const auto r = test::run_capture(args, kRefusalSeconds);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_code, 2) << shown << "\n" << r.output;
  EXPECT_NE(r.output.find(c.names), std::string::npos) << shown << "\n" << r.output;
  EXPECT_LT(seconds, kRefusalSeconds) << shown;
}

TEST(StrictInput, option_values_that_mean_nothing_are_refused) {
  const std::string out = (scratch() / "never.h5").string();
  fs::remove(out);
  const std::vector<Refusal> cases = {
      {{"run", kHunting, "--speed", "nan", "-o", out}, "--speed"},
      {{"run", kHunting, "--t-end", "nan", "-o", out}, "--t-end"},
      {{"run", kHunting, "--fixed-step", "nan", "-o", out}, "--fixed-step"},
      {{"run", kHunting, "--integrator", "", "-o", out}, "--integrator"},
      {{"run", kHunting, "-o", ""}, "--output"},
      {{"run", kHunting, "--t-end", "inf", "-o", out}, "--t-end"},
      {{"run", kHunting, "--speed", "-1", "-o", out}, "--speed"},
      {{"run", kHunting, "--speed", "0", "-o", out}, "--speed"},  // the linear wheelset needs V > 0
      {{"eig", kHunting, "--points", "0", "-o", out}, "--points"},
      {{"eig", kHunting, "--points", "-3", "-o", out}, "--points"},
      {{"eig", kHunting, "--speed-min", "nan", "-o", out}, "--speed-min"},
      {{"assess", out, "--mu", "nan"}, "--mu"},
      {{"assess", out, "--mu", "-1"}, "--mu"},
      {{"assess", out, "--flange-angle-deg", "0"}, "--flange-angle-deg"},
      {{"assess", out, "--flange-angle-deg", "-10"}, "--flange-angle-deg"},
      {{"assess", out, "--flange-angle-deg", "nan"}, "--flange-angle-deg"},
      {{"assess", out, "--section-length", "0"}, "--section-length"},
      {{"assess", out, "--section-length", "-1"}, "--section-length"},
      {{"assess", out, "--f0", "0"}, "--f0"},
      {{"assess", out, "--f0", "nan"}, "--f0"},
      {{"assess", out, "--floor-offset", "-1"}, "--floor-offset"},
      {{"assess", out, "--y-over-q-limit", "0"}, "--y-over-q-limit"},
      {{"assess", out, "--category", ""}, "--category"},
      {{"assess", out, "-o", ""}, "--output"},
      {{"sweep", kHunting, "--speed-min", "10", "--speed-max", "20", "--max-new-points", "-1"},
       "--max-new-points"},
      {{"critical-speed", "ramp", kHunting, "--disturbance", "nan"}, "--disturbance"},
  };
  for (const auto& c : cases) expect_refused(c);
  EXPECT_FALSE(fs::exists(out));
}

TEST(StrictInput, work_is_bounded_before_it_starts) {
  const fs::path dir = scratch();
  // A run file whose positions span 2e15 m, for the assessment.
  const std::string run = (dir / "bounded_run.h5").string();
  fs::remove(run);
  ASSERT_EQ(test::run_capture({test::ferrodyn_exe(), "run", "scenarios/scenes/thesis_derailment.yaml",
                               "--no-plots", "-q", "--t-end", "0.5", "-o", run})
                .exit_code,
            0);
  const std::string far = (dir / "far_positions.h5").string();
  fs::copy_file(run, far, fs::copy_options::overwrite_existing);
  {
    // Positions stretched to 2e15 m: the assessment must refuse the means it would compute.
    const H5File in = H5File::open_read(run);
    H5File f = H5File::create(far);
    copy_object(in, f, "/");
    auto pos = in.read_vector("/signals/position");
    for (std::size_t i = 0; i < pos.size(); ++i) pos[i] = 2e15 * static_cast<double>(i) / pos.size();
    f.write_vector("/signals/position", pos, in.string_attribute("/signals/position", "unit"));
    f.close();
  }
  const std::vector<Refusal> cases = {
      {{"assess", run, "--section-length", "1e-9", "--no-plots", "-o", (dir / "d1.h5").string()},
       "--section-length"},
      {{"assess", far, "--no-plots", "-o", (dir / "d2.h5").string()}, "windows; at most"},
      {{"geometry", "search", "--wheel", "data/profiles/MBench_S1002_v3.prw", "--rail",
        "data/profiles/MBench_UIC60_v3.prr", "--section-step", "1e-9"},
       "--section-step"},
      {{"eig", kHunting, "--points", "1000000000", "-o", (dir / "e.h5").string()}, "--points"},
      {{"critical-speed", "ramp", kHunting, "--hold", "1e-9", "-o", (dir / "r.h5").string()},
       "--hold"},
  };
  for (const auto& c : cases) expect_refused(c);
}

TEST(StrictInput, a_disturbance_beyond_the_model_is_refused_with_a_message) {
  const auto r = test::run_capture({test::ferrodyn_exe(), "critical-speed", "ramp", kHunting,
                                    "--disturbance", "10", "--no-plots", "-o",
                                    (scratch() / "ramp.h5").string()},
                                   kRefusalSeconds);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--disturbance: 10 m lies beyond the bound"), std::string::npos)
      << r.output;
}

TEST(StrictInput, nonsense_scene_values_are_refused_at_their_line) {
  // Vehicle files beside the shipped ones (their profiles are named relative to them), with a
  // copy of the fast ERRI scene naming each.
  const auto vehicle_copy = [&](const std::string& from, const std::string& to,
                                const std::string& name) {
    edited("scenarios/vehicles/manchester_vehicle1.yaml", from, to, name);
    return edited(kVehicle, "../vehicles/manchester_vehicle1.yaml", "../vehicles/" + name,
                  "scene_" + name);
  };
  struct Case {
    std::string scene, file_named, key;
  };
  const std::vector<Case> cases = {
      {edited("scenarios/scenes/manchester_curve_1200.yaml", "radius: 1200", "radius: 0.001",
              "tiny_radius.yaml"),
       "tiny_radius.yaml", "radius"},
      {vehicle_copy("  cg_height: 1.8", "  cg_height: -1", "low_cg.yaml"), "low_cg.yaml",
       "cg_height"},
      {vehicle_copy("  secondary_height: 0.8275", "  secondary_height: -1", "low_secondary.yaml"),
       "low_secondary.yaml", "secondary_height"},
      {vehicle_copy("  poisson: 0.28\n", "  poisson: 0.28\n  contact_half_distance: -1\n",
                    "negative_e.yaml"),
       "negative_e.yaml", "contact_half_distance"},
      {edited(kHunting, "semi_axis_b:", "k11: 2\n  semi_axis_b:", "k11_two.yaml"), "k11_two.yaml",
       "k11"},
      {edited(kHunting, "mass: 1813", "mass: !python/object 1813", "tagged.yaml"), "tagged.yaml",
       "mass"},
  };
  for (const auto& c : cases) {
    const auto r = test::run_capture({test::ferrodyn_exe(), "validate", c.scene}, kRefusalSeconds);
    EXPECT_EQ(r.exit_code, 2) << c.scene << "\n" << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex(c.file_named + ":[0-9]+:[0-9]+: [^ ]*" +
                                                       c.key)))
        << c.scene << "\n"
        << r.output;
  }
}

TEST(StrictInput, a_huge_track_is_refused_instead_of_looping) {
  for (const std::string& key : {std::string("length: 600"), std::string("wavelength_max: 150")}) {
    const std::string huge = key.substr(0, key.find(':')) + ": 1.4e18";
    const std::string scene = edited(kVehicle, key, huge, "huge_track.yaml");
    for (const char* verb : {"validate", "run"}) {
      std::vector<std::string> args = {test::ferrodyn_exe(), verb, scene};
      if (verb == std::string("run")) {
        args.insert(args.end(), {"--no-plots", "-q", "-o", (scratch() / "huge.h5").string()});
      }
      const auto r = test::run_capture(args, kRefusalSeconds);
      EXPECT_EQ(r.exit_code, 2) << verb << " " << huge << "\n" << r.output;
      EXPECT_TRUE(std::regex_search(r.output, std::regex("huge_track.yaml:[0-9]+:[0-9]+: ")))
          << r.output;
    }
  }
}

TEST(StrictInput, the_spin_cannot_be_frozen_and_validate_says_so) {
  const std::string scene = edited("scenarios/scenes/thesis_derailment.yaml", "model:",
                                   "model:\n  frozen: [wheelset_1.spin]", "frozen_spin.yaml");
  for (const char* verb : {"validate", "run"}) {
    std::vector<std::string> args = {test::ferrodyn_exe(), verb, scene};
    if (verb == std::string("run")) {
      args.insert(args.end(), {"--no-plots", "-q", "-o", (scratch() / "spin.h5").string()});
    }
    const auto r = test::run_capture(args, kRefusalSeconds);
    EXPECT_EQ(r.exit_code, 2) << verb << "\n" << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("frozen_spin.yaml:[0-9]+:[0-9]+: model.frozen")))
        << r.output;
  }
}

TEST(StrictInput, a_vehicle_may_stand_still) {
  const std::string out = (scratch() / "standing.h5").string();
  fs::remove(out);
  // BDF (the scene's explicit fixed step is tuned for 55 m/s, not for rest).
  const auto r = test::run_capture({test::ferrodyn_exe(), "run", kVehicle, "--speed", "0",
                                    "--t-end", "0.5", "--integrator", "cvode_bdf", "--no-plots",
                                    "-q", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "completed");
  for (double v : f.read_vector("/signals/speed")) ASSERT_EQ(v, 0.0);
  // Standing still at its static equilibrium, the vehicle stays there: no creep forces, no
  // track moving under it; the wheelsets keep their lateral position to round-off (a running
  // vehicle moves by millimetres).
  const auto y = f.read_vector("/signals/wheelset_1.y");
  for (double v : y) ASSERT_NEAR(v, y.front(), 1e-12);
  const auto position = f.read_vector("/signals/position");
  for (double v : position) ASSERT_EQ(v, position.front());
}

TEST(StrictInput, fe_kij_refuses_its_output_and_bad_keys_before_computing) {
  const fs::path dir = scratch() / "fe_kij";
  fs::create_directories(dir);
  const std::string config = (dir / "study.yaml").string();
  std::string text = text_of("fe_contact/examples/thesis_layer_study.yaml");
  const auto out_at = text.find("\noutput:");
  ASSERT_NE(out_at, std::string::npos);
  text = text.substr(0, out_at + 1) + "output: kij.h5\nplots: false\n";
  std::ofstream(config) << text;
  std::ofstream(dir / "kij.h5") << "an earlier table";
  const auto exists = test::run_capture({test::ferrodyn_exe(), "fe-kij", config}, kRefusalSeconds);
  EXPECT_EQ(exists.exit_code, 2) << exists.output;
  EXPECT_NE(exists.output.find("exists; pass --overwrite"), std::string::npos) << exists.output;
  const std::string huge = edited(config, "elements_minor: 24", "elements_minor: 100000",
                                  "huge_grid.yaml", dir);
  const auto grid = test::run_capture({test::ferrodyn_exe(), "fe-kij", huge}, kRefusalSeconds);
  EXPECT_EQ(grid.exit_code, 2) << grid.output;
  EXPECT_TRUE(std::regex_search(grid.output,
                                std::regex("huge_grid.yaml:[0-9]+:[0-9]+: contact.elements_minor")))
      << grid.output;
}

}  // namespace
}  // namespace ferro::scenarios
