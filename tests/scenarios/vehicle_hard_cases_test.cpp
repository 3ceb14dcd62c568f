// Hard cases of the whole vehicle on real profiles, run from scene files: Manchester vehicle 1
// (S1002 / UIC60 through the multi-point contact table, chopaya) standing still and crawling at
// 0.5 m/s on a 1000 m curve with 160 mm cant. Oracles: Newton for the whole vehicle at rest
// (the wheel-rail forces carry the weight's components normal to and along the canted track
// plane) and the rigid-vehicle load transfer as a lower bound. Longer runs (flange contact in a
// 150 m curve, 400 km/h over a 10 mm alignment defect, tolerance convergence, crawling into the
// cant) are in slow/.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "vehicle_scene_run.hpp"

namespace ferro::scenarios {
namespace {

constexpr const char* kCantScene = "tests/scenarios/data/hard_cases/cant_160_curve_1000.yaml";
constexpr double kRadius = 1000.0;     // [m], as in the scene
constexpr double kCant = 0.160;        // [m]
constexpr double kRailSpacing = 1.5;   // [m], cant -> cant angle (track.rail_spacing default)
constexpr double kHalfSpacing = 0.75;  // [m], nominal lateral arm of a wheel load

// Static sums: the wheelsets' track frames at +-10.78 m differ in heading by ~11 mrad from the
// car body's, and each wheel's Y and Q are in its own wheelset's axes, so components of order
// yaw x force (1e-4 to 1e-3 of the sums) are not in them; the equilibrium residual itself is
// far smaller.
constexpr double kStaticSumTol = 1e-3;
// "Sits still": positions may not move by more than 1 um over the run (the static equilibrium
// is an exact steady state at rest; at 0.5 m/s on the constant curve it is steady too).
constexpr double kDriftTol = 1e-6;

struct Totals {
  double sum_q = 0.0;         // sum of wheel loads Q [N]
  double sum_lateral = 0.0;   // sum of lateral wheel forces along track +y (left, inner) [N]
  double low_minus_high = 0.0;  // sum Q of the left (low) wheels minus the right ones [N]
  double min_q = 1e300;
};

Totals totals(const test::SceneRun& run, std::size_t k) {
  Totals t;
  for (int w = 1; w <= 4; ++w) {
    const std::string p = "wheelset_" + std::to_string(w);
    const double ql = run.at(k, p + ".left.Q"), qr = run.at(k, p + ".right.Q");
    // Y is positive towards the track centre: -y on the left wheel, +y on the right one.
    t.sum_lateral += -run.at(k, p + ".left.Y") + run.at(k, p + ".right.Y");
    t.sum_q += ql + qr;
    t.low_minus_high += ql - qr;
    t.min_q = std::min({t.min_q, ql, qr});
  }
  return t;
}

TEST(VehicleHardCases, standing_still_and_crawling_on_160_mm_cant) {
  for (const double speed : {0.0, 0.5}) {
    Scene scene = test::load_test_scene(kCantScene);
    scene.simulation.speed = speed;
    const auto& cfg = scene.model.vehicle;
    const double g = cfg.gravity;
    double mass = 0.0, mass_height = 0.0;  // total mass [kg], sum m_i h_i [kg m]
    for (const auto& b : cfg.bodies) {
      mass += b.mass;
      mass_height += b.mass * b.position.z();
    }
    const double phi = std::asin(kCant / kRailSpacing);
    // Newton for the whole vehicle at rest in the canted frame (V^2/R terms: 2.5e-4 m/s^2 at
    // 0.5 m/s, kept): the rails carry the weight's component normal to the track plane and
    // push the vehicle up the cant against its in-plane component.
    const double centripetal = speed * speed / kRadius;
    const double expected_q = mass * (g * std::cos(phi) + centripetal * std::sin(phi));
    const double expected_lateral = mass * (centripetal * std::cos(phi) - g * std::sin(phi));
    // Rigid vehicle: the in-plane weight component at each body's centre-of-mass height, held
    // at rail level, transfers load to the low rail: dQ = g sin(phi) sum(m h) / (rail_spacing
    // / 2). The suspension lets the bodies lean and shift towards the low rail and the low
    // wheels run on their flange roots (contact points moved inwards): both only add to it, so
    // this is a lower bound.
    const double rigid_transfer = g * std::sin(phi) * mass_height / kHalfSpacing;

    const test::SceneRun run = test::run_scene_in_memory(scene);
    ASSERT_EQ(run.result.status, vehicle::IntegrationResult::Status::kCompleted)
        << "V " << speed << ": " << run.result.message;
    ASSERT_FALSE(run.samples.empty());

    // No drift: every position state stays where the equilibrium put it.
    double drift = 0.0;
    for (std::size_t i = 0; i < run.names.size(); ++i) {
      const std::string& n = run.names[i];
      const auto dot = n.rfind('.');
      const std::string dof = n.substr(dot + 1);
      if (dof != "y" && dof != "z" && dof != "roll" && dof != "pitch" && dof != "yaw") continue;
      for (const auto& row : run.samples) {
        drift = std::max(drift, std::abs(row[i] - run.samples.front()[i]));
      }
    }
    EXPECT_LT(drift, kDriftTol) << "V " << speed;

    const Totals first = totals(run, 0);
    const Totals last = totals(run, run.samples.size() - 1);
    for (const Totals& t : {first, last}) {
      EXPECT_NEAR(t.sum_q / expected_q, 1.0, kStaticSumTol) << "V " << speed;
      EXPECT_NEAR(t.sum_lateral / expected_lateral, 1.0, kStaticSumTol) << "V " << speed;
      EXPECT_GT(t.min_q, 0.0) << "V " << speed << ": a wheel lifted";
      EXPECT_GT(t.low_minus_high, rigid_transfer) << "V " << speed;
    }
    for (int w = 1; w <= 4; ++w) {
      const std::string p = "wheelset_" + std::to_string(w);
      EXPECT_GT(run.at(0, p + ".left.Q"), run.at(0, p + ".right.Q")) << p << ": low rail is left";
    }
    std::printf(
        "[ figures  ] V %.1f m/s on 160 mm cant, R %.0f m: sum Q / (M (g cos + V^2/R sin)) - 1 = "
        "%.1e, sum Y / (M (V^2/R cos - g sin)) - 1 = %.1e, load transfer %.1f kN = %.3f x rigid "
        "(%.1f kN), position drift %.1e m\n",
        speed, kRadius, last.sum_q / expected_q - 1.0, last.sum_lateral / expected_lateral - 1.0,
        last.low_minus_high / 1e3, last.low_minus_high / rigid_transfer, rigid_transfer / 1e3,
        drift);
  }
}

}  // namespace
}  // namespace ferro::scenarios
