// Track = alignment + irregularities: rail points and twist.

#include "ferro/track/track.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

namespace ferro::track {
namespace {

TrackDesign ramp_design() {
  TrackDesign d;
  d.sections = {{SectionKind::kStraight, 20.0},
                {SectionKind::kTransition, 60.0},
                {SectionKind::kCurve, 100.0, 500.0, 0.15}};
  return d;
}

TEST(Track, twist_of_a_cant_ramp_and_a_cross_level_defect) {
  // EN 13848 twist over a 3 m base. On a linear ramp it is the ramp gradient 0.15/60 = 2.5 mm/m.
  const Track perfect{Alignment(ramp_design())};
  EXPECT_NEAR(perfect.twist(50.0, 3.0), 0.15 / 60.0, 1e-15);
  EXPECT_NEAR(perfect.twist(19.0, 3.0), 0.0, 1e-15);
  // A 1-cos cross-level defect of -12 mm over 6 m on the ramp (Toumi Fig. 4.4's exit defect
  // accentuating the twist) adds its own chord gradient (c(x) - c(x - 3)) / 3 with
  // c(x) = A/2 (1 - cos(2 pi x / 6)) on 0 < x < 6, evaluated in closed form below.
  IsolatedDefectSpec spec;
  spec.channel = IrregularityChannel::kCrossLevel;
  spec.amplitude = -0.012;
  spec.wavelength = 6.0;
  spec.start_s = 40.0;
  const Track t{Alignment(ramp_design()), std::make_shared<IsolatedDefect>(spec)};
  auto c = [&](double x) {
    return (x > 0.0 && x < 6.0)
               ? 0.5 * spec.amplitude * (1.0 - std::cos(std::numbers::pi * x / 3.0))
               : 0.0;
  };
  for (const double x : {1.0, 3.0, 4.5, 7.0}) {
    const double expected = 0.15 / 60.0 + (c(x) - c(x - 3.0)) / 3.0;
    EXPECT_NEAR(t.twist(40.0 + x, 3.0), expected, 1e-15) << x;
  }
  EXPECT_THROW((void)t.twist(50.0, 0.0), std::invalid_argument);
}

TEST(Track, rail_points_carry_gauge_cant_and_alignment) {
  IsolatedDefectSpec lateral;
  lateral.amplitude = 0.01;
  lateral.wavelength = 10.0;
  lateral.start_s = 145.0;  // in the curve; peak at 150
  IsolatedDefectSpec gauge = lateral;
  gauge.channel = IrregularityChannel::kGauge;
  gauge.amplitude = 0.004;
  auto sum = std::make_shared<IrregularitySum>();
  sum->add(std::make_shared<IsolatedDefect>(lateral));
  sum->add(std::make_shared<IsolatedDefect>(gauge));
  const Track t{Alignment(ramp_design()), sum};
  const TrackPoint p = t.at(150.0);
  const Eigen::Vector3d l = p.left_rail_position(), r = p.right_rail_position();
  // Distance between the rail points: rail spacing + gauge irregularity (in the cant plane).
  EXPECT_NEAR((l - r).norm(), 1.5 + 0.004, 1e-14);
  // Height difference is the cant (no cross-level irregularity here).
  EXPECT_NEAR(r.z() - l.z(), 0.15 * (1.0 + 0.004 / 1.5), 1e-14);
  // Midpoint displaced by the alignment defect along the track's lateral axis.
  const Eigen::Vector3d mid = 0.5 * (l + r);
  EXPECT_NEAR((mid - p.frame.position).dot(p.frame.rotation.col(1)), 0.01, 1e-14);
  EXPECT_NEAR(p.gauge(), 1.435 + 0.004, 1e-15);
  EXPECT_DOUBLE_EQ(p.cross_level(), 0.15);
}

}  // namespace
}  // namespace ferro::track
