// What a run's file says of values the model cannot give (docs/OUTPUT.md): a wheel lifted off its
// rail has no contact point, and every quantity of it (forces, creepages, contact angle and
// place) is 0, never NaN; and what a scene asks for that the model does not apply (a curve's gauge
// widening) is said as a warning and written into the file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "ferro/scenarios/h5_output.hpp"
#include "process.hpp"
#include "scene_edits.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ferro_file_contract_" + std::to_string(getpid()));
  fs::create_directories(dir);
  fs::remove(dir / name);
  return (dir / name).string();
}

TEST(FileContract, a_lifted_wheel_reads_zero_and_every_signal_is_finite) {
  // The Manchester vehicle at 150 m/s in the 1200 m curve with 150 mm cant, on the rigid track
  // with the error-controlled BDF solver: the leading wheelset climbs the outer rail and its
  // wheels lift off near 0.5 s.
  const std::string scene = test::edited_copy("scenarios/scenes/manchester_curve_1200.yaml",
                                              "\ntrack:\n", "\ntrack:\n  structure: rigid\n",
                                              "curve_rigid.yaml");
  const std::string out = scratch("lifted.h5");
  const auto r = test::run_capture({test::ferrodyn_exe(), "run", scene, "--speed", "150",
                                    "--t-end", "0.52", "--integrator", "cvode_bdf", "--rtol",
                                    "1e-5", "--atol", "1e-8", "--no-plots", "-q", "-o", out});
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << r.output;
  const H5File f = H5File::open_read(out);
  std::size_t lifted = 0;
  for (const std::string side : {"left", "right"}) {
    const std::string w = "/signals/wheelset_1." + side + ".";
    const auto points = f.read_vector(w + "points");
    const auto in_contact = f.read_vector(w + "in_contact");
    for (std::size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(in_contact[i], points[i] > 0.0 ? 1.0 : 0.0) << side << " " << i;
      if (points[i] == 0.0) ++lifted;
    }
    for (const char* zero : {"Y", "Q", "normal_force", "creepage_x", "creepage_y", "spin",
                             "contact_angle", "contact_y"}) {
      const auto v = f.read_vector(w + zero);
      for (std::size_t i = 0; i < points.size(); ++i) {
        ASSERT_TRUE(std::isfinite(v[i])) << zero << " " << i;
        if (points[i] == 0.0) ASSERT_EQ(v[i], 0.0) << zero << " " << i;
      }
    }
  }
  EXPECT_GT(lifted, 0u) << "the wheelset did not lift: the case tests nothing";
  // Every signal finite at every sample (the run ended without failure up to its last sample).
  for (const auto& name : f.members("/signals")) {
    for (const double v : f.read_vector("/signals/" + name)) ASSERT_TRUE(std::isfinite(v)) << name;
  }
  // The contract is written down.
  const std::string doc = test::text_of("docs/OUTPUT.md");
  EXPECT_NE(doc.find("Every signal is finite at every sample of a run that did not fail"),
            std::string::npos);
}

TEST(FileContract, what_the_vehicle_model_does_not_apply_is_said_and_recorded) {
  // Widening a curve's gauge moves no rail: said by validate and run, and recorded in the file.
  const std::string scene = test::edited_copy("scenarios/scenes/manchester_curve_1200.yaml",
                                              "cant_mm: 150}", "cant_mm: 150, gauge_widening: 0.01}",
                                              "widened.yaml");
  const auto v = test::run_capture({test::ferrodyn_exe(), "validate", scene});
  EXPECT_EQ(v.exit_code, 0) << v.output;
  EXPECT_NE(v.output.find("warning: track.sections[2].gauge_widening"), std::string::npos)
      << v.output;
  const std::string out = scratch("widened.h5");
  const auto r = test::run_capture({test::ferrodyn_exe(), "run", scene, "--t-end", "0.01",
                                    "--no-plots", "-q", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: track.sections[2].gauge_widening"), std::string::npos)
      << r.output;
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.number_attribute("/", "warning_count"), 1.0);
  EXPECT_NE(f.string_attribute("/", "warnings").find("gauge widening"), std::string::npos);
  // The gauge irregularity channel moves the rails apart: the ERRI scenes warn of nothing.
  const auto erri = test::run_capture(
      {test::ferrodyn_exe(), "validate", "scenarios/scenes/manchester_straight_erri.yaml"});
  EXPECT_EQ(erri.exit_code, 0) << erri.output;
  EXPECT_EQ(erri.output.find("warning"), std::string::npos) << erri.output;
}

}  // namespace
}  // namespace ferro::scenarios
