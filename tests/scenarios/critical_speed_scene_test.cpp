// Critical-speed analyses on the shipped linear wheelset scene, against the closed form
// eq. (151) (Toumi 2016): for a linear model the periodic branch degenerates -- oscillations
// grow above the Hopf speed and decay below -- so the fold bracket must contain eq. (151)'s Vc,
// and a slow ramp's envelope peaks where the growth rate crosses zero, at Vc.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/scene_analysis.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/vehicle/suspended_wheelset.hpp"

namespace ferro::scenarios::analysis {
namespace {

Scene hunting_scene() {
  return load_scene(std::string(FERRO_SOURCE_DIR) + "/scenarios/scenes/wheelset_hunting.yaml");
}

double closed_form_vc(const Scene& s) {
  return vehicle::analytic_critical_speed(s.model.wheelset,
                                          vehicle::creep_coefficients(s.contact.creep));
}

TEST(WheelsetCriticalSpeed, RampEnvelopePeaksAtHopfSpeed) {
  const Scene s = hunting_scene();
  const double vc = closed_form_vc(s);
  RampOptions o;
  o.speed_initial = 40.0;
  o.deceleration = 0.1;
  o.speed_final = 37.5;
  o.hold = 0.1;
  o.threshold = 1e-5;
  o.solver = s.solver;
  const auto family = speed_family(s);
  const auto probe = family(o.speed_initial);
  o.observed = lateral_states(*probe).index;
  const auto x0 = disturbed_state(s, *probe, 1e-4);
  const auto r = ramp_down(family, x0, o);
  ASSERT_TRUE(r.completed) << r.message;
  std::printf("[ figures  ] ramp envelope peak %.4f m/s, eq. (151) %.4f m/s\n", r.peak_speed, vc);
  // Crests come every half period (~0.1 s at 4.7 Hz), i.e. every 0.01 m/s of the ramp, and the
  // speed is held in 0.01 m/s pieces: a few of those.
  constexpr double kCrestResolution = 0.05;  // [m/s]
  EXPECT_NEAR(r.peak_speed, vc, kCrestResolution);
}

TEST(WheelsetCriticalSpeed, FoldBracketContainsHopfSpeed) {
  const Scene s = hunting_scene();
  const double vc = closed_form_vc(s);
  BranchOptions o;
  o.speed_start = 44.0;
  o.speed_stop = 34.0;
  o.speed_step = 2.0;
  o.bracket = 0.1;
  o.settle.solver = s.solver;
  o.settle.segment = 10.0;
  o.settle.max_time = 40.0;
  const auto family = speed_family(s);
  const auto probe = family(o.speed_start);
  o.settle.observed = lateral_states(*probe).index;
  const auto b = follow_periodic_branch(family, disturbed_state(s, *probe, 1e-3), o);
  ASSERT_TRUE(b.fold_found);
  std::printf("[ figures  ] linear wheelset fold bracket [%.4f, %.4f] m/s, eq. (151) %.4f m/s\n",
              b.bracket_low, b.bracket_high, vc);
  EXPECT_LE(b.bracket_high - b.bracket_low, o.bracket);
  EXPECT_LE(b.bracket_low, vc);
  EXPECT_GE(b.bracket_high, vc);
}

TEST(WheelsetCriticalSpeed, ReductionFactorsReachTheModel) {
  const Scene s = hunting_scene();
  const auto k = with_reduction(s, contact::ReductionFactors::following_k22(0.5, 0.7));
  const auto c1 = vehicle::creep_coefficients(s.contact.creep);
  const auto c2 = vehicle::creep_coefficients(k.contact.creep);
  EXPECT_DOUBLE_EQ(c2.f11, 0.5 * c1.f11);
  EXPECT_DOUBLE_EQ(c2.f22, 0.7 * c1.f22);
  EXPECT_THROW((void)with_reduction(s, contact::ReductionFactors::following_k22(0.0, 1.0)),
               std::invalid_argument);
  EXPECT_THROW((void)with_reduction(s, contact::ReductionFactors::following_k22(1.0, 1.2)),
               std::invalid_argument);
  EXPECT_EQ(k.model.vehicle.wheel_rail.reduction,
            (contact::ReductionFactors{0.5, 0.7, 0.7, 0.7}));  // K23, K33 follow K22
  const auto u = with_reduction(s, contact::ReductionFactors::uniform(0.6));
  EXPECT_EQ(u.model.vehicle.wheel_rail.reduction, contact::ReductionFactors::uniform(0.6));
}

}  // namespace
}  // namespace ferro::scenarios::analysis
