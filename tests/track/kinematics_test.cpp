// Track-frame kinematics: balance cant of Toumi eq. (148) reproduced by the frame's lateral
// acceleration; angular velocity and acceleration against time differences along a trajectory.

#include "ferro/track/kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ferro::track {
namespace {

TrackDesign curve_design(double radius, double cant) {
  TrackDesign d;
  d.sections = {{SectionKind::kStraight, 50.0},
                {SectionKind::kTransition, 60.0},
                {SectionKind::kCurve, 200.0, radius, cant},
                {SectionKind::kTransition, 60.0},
                {SectionKind::kStraight, 50.0}};
  return d;
}

// Eq. (148): D = 2e V^2 / (R g). With D from (148), sin(phi) = V^2 / (R g), so the frame's
// exact uncompensated acceleration V^2 k cos(phi) - g sin(phi) must equal -V^2 k (1 - cos phi):
// zero to first order in phi (the small-angle statement of the thesis), with the second-order
// residue known in closed form.
TEST(FrameKinematics, balance_cant_eq_148) {
  for (const double radius : {1000.0, -650.0, 3000.0}) {
    const double speed = 30.0 * std::sqrt(std::abs(radius) / 1000.0);  // V^2/R = 0.9 m/s^2
    const double b = 1.5;
    const double cant = balance_cant(1.0 / radius, speed, b);
    ASSERT_NEAR(std::abs(cant), 2 * 0.75 * speed * speed / (std::abs(radius) * kStandardGravity),
                1e-15);
    const Alignment a(curve_design(radius, cant));
    const TrackFrame f = a.frame(250.0);  // inside the curve
    const FrameKinematics k = frame_kinematics(f, speed);
    const double centripetal = speed * speed / radius;
    const double residue = -centripetal * (1.0 - std::cos(f.cant_angle));
    // Rounding of a difference of two ~1 m/s^2 terms.
    constexpr double kRounding = 1e-14;
    EXPECT_NEAR(k.uncompensated_lateral_acceleration, residue, kRounding);
    if (std::getenv("FERRO_TRACK_VERBOSE") != nullptr) {
      std::printf("R = %g m, V = %g m/s: D(148) = %.6f m, phi = %.6f rad, a_y = %.6e m/s^2 "
                  "(expected %.6e)\n",
                  radius, speed, cant, f.cant_angle, k.uncompensated_lateral_acceleration,
                  residue);
    }
    // Eq. (148) balances to within the second-order residue, < 0.5 % of V^2/R for phi < 0.1 rad.
    EXPECT_LT(std::abs(k.uncompensated_lateral_acceleration), 0.005 * std::abs(centripetal));
    // The EN 13803 cant deficiency is zero by construction of (148).
    EXPECT_NEAR(k.cant_deficiency, 0.0, 1e-15);
    // Yaw rate V / R; normal specific force close to g.
    EXPECT_NEAR(k.yaw_rate, speed / radius, 1e-15);
    EXPECT_NEAR(k.specific_force.z(), std::hypot(centripetal, kStandardGravity), 0.01);

    // Exact balance: tan(phi) = V^2 k / g leaves nothing.
    const Alignment exact(curve_design(radius, balance_cant_exact(1.0 / radius, speed, b)));
    const FrameKinematics ke = frame_kinematics(exact.frame(250.0), speed);
    EXPECT_NEAR(ke.uncompensated_lateral_acceleration, 0.0, kRounding);
    EXPECT_NEAR(balance_speed(exact.frame(250.0)), speed, 1e-12 * speed);
    // In the transitions cant and curvature ramp together, so balance holds all along them up
    // to sin/tan: with ramp fraction l, a_y = l V^2 k (cos(l phi_c) - cos(phi_c)) <=
    // 0.19 phi_c^2 V^2 k = 1.6e-3 V^2 k here (phi_c = 0.092 rad).
    for (double s = 50.0; s <= 110.0; s += 5.0) {
      EXPECT_NEAR(frame_kinematics(exact.frame(s), speed).uncompensated_lateral_acceleration, 0.0,
                  2e-3 * std::abs(centripetal))
          << "s = " << s;
    }
    // Above the balance speed the deficiency pushes outwards: a_y has the curvature's sign.
    EXPECT_GT(frame_kinematics(f, 1.2 * speed).uncompensated_lateral_acceleration * radius, 0.0);
  }
}

// Time derivatives along a trajectory s(t) = s0 + V0 t + a t^2 / 2 against the analytic ones.
TEST(FrameKinematics, rates_match_time_differences) {
  const Alignment a(curve_design(400.0, 0.1));
  const double v0 = 25.0, acc = -0.8;
  auto state = [&](double t) {
    const double s = 60.0 + v0 * t + 0.5 * acc * t * t;
    return frame_kinematics(a.frame(s), v0 + acc * t, acc);
  };
  constexpr double kDt = 1e-4;  // [s]; central difference error ~ dt^2 * third derivative
  for (double t = 0.0; t < 1.5; t += 0.1) {  // stays inside the entry transition
    const auto k = state(t), km = state(t - kDt), kp = state(t + kDt);
    const Eigen::Vector3d dw = (kp.angular_velocity - km.angular_velocity) / (2 * kDt);
    EXPECT_LT((dw - k.angular_acceleration).norm(), 1e-9) << t;
    // Origin acceleration: second difference of the centreline position, rotated to track axes.
    const double s = 60.0 + v0 * t + 0.5 * acc * t * t;
    auto pos = [&](double tt) { return a.position(60.0 + v0 * tt + 0.5 * acc * tt * tt); };
    const Eigen::Vector3d acc_ground =
        (pos(t + 1e-3) - 2.0 * pos(t) + pos(t - 1e-3)) / (1e-3 * 1e-3);
    const Eigen::Vector3d acc_track = a.frame(s).rotation.transpose() * acc_ground;
    EXPECT_LT((acc_track - k.origin_acceleration).norm(), 1e-5) << t;  // 2nd-difference rounding
  }
}

}  // namespace
}  // namespace ferro::track
