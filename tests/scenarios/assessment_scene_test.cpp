// The assessment of shipped scenes against Newton: in the steady part of the R 1200 m curve the
// track-shift forces of the four axles (quasi-static values, 50 % of each axle's 2 m mean in the
// circular curve) add up to the net lateral force M (V^2/R cos(phi) - g sin(phi)) in the canted
// track plane.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "ferro/scenarios/analysis/assessment.hpp"
#include "ferro/scenarios/run.hpp"
#include "ferro/scenarios/scene.hpp"

namespace ferro::scenarios::analysis {
namespace {

TEST(AssessScene, R1200TrackShiftForcesSumToTheNetLateralForce) {
  const Scene scene =
      load_scene(std::string(FERRO_SOURCE_DIR) + "/scenarios/scenes/manchester_curve_1200.yaml");
  RunOptions ro;
  ro.output_file = (std::filesystem::temp_directory_path() / "ferro_assess_r1200.h5").string();
  const auto summary = run_scene(scene, ro);
  ASSERT_EQ(summary.status_text, "completed") << summary.message;
  const auto a = assess_run(ro.output_file, {});
  double total = 0.0;
  int axles = 0;
  for (const auto& r : a.rows) {
    if (r.quantity != "sum Y 2 m" || r.section.find("curve") == std::string::npos) continue;
    total += r.stats.p_median;
    ++axles;
  }
  ASSERT_EQ(axles, 4);
  double mass = 0.0;
  for (const auto& b : scene.model.vehicle.bodies) mass += b.mass;
  const double v = scene.simulation.speed, radius = 1200.0, g = scene.model.vehicle.gravity;
  const double sin_phi = 0.150 / 1.5, cos_phi = std::sqrt(1.0 - sin_phi * sin_phi);
  const double newton = mass * (v * v / radius * cos_phi - g * sin_phi);  // 67.93 kN
  std::printf("sum over the axles of sum Y: %.1f N, Newton %.1f N (%+.2e)\n", total, newton,
              (total - newton) / newton);
  // The requirement: 0.5 %.
  EXPECT_NEAR(total, newton, 5e-3 * newton);
  EXPECT_TRUE(a.pass);
  std::filesystem::remove(ro.output_file);
}

}  // namespace
}  // namespace ferro::scenarios::analysis
