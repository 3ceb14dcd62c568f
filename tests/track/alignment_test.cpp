// Design alignment: closed-form positions (circle, Fresnel integrals for clothoids), continuity
// through transitions, consistency of every derivative with finite differences, validation.
//
// Oracles: Fresnel integrals by their power series (Abramowitz & Stegun 7.3.11, 7.3.13) checked
// against A&S Table 7.7; circle geometry; central differences.

#include "ferro/track/alignment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ferro::track {
namespace {

constexpr double kPi = std::numbers::pi;

// Fresnel integrals C(t) = int_0^t cos(pi x^2 / 2) dx, S(t) likewise with sin, by their power
// series (A&S 7.3.11, 7.3.13) in long double; converges for all t, used here for t <= 2.
void fresnel_series(double t, double& c, double& s) {
  long double sum_c = 0.0L, sum_s = 0.0L;
  const long double a = kPi / 2.0L;
  // int_0^t exp(i a x^2) dx = sum_n (i a)^n t^(2n+1) / (n! (2n+1)).
  long double power = t;  // a^n t^(2n+1) / n!
  for (int n = 0; n < 80; ++n) {
    const long double contrib = power / (2 * n + 1);
    switch (n % 4) {
      case 0:
        sum_c += contrib;
        break;
      case 1:
        sum_s += contrib;
        break;
      case 2:
        sum_c -= contrib;
        break;
      case 3:
        sum_s -= contrib;
        break;
    }
    power *= a * static_cast<long double>(t) * t / (n + 1);
  }
  c = static_cast<double>(sum_c);
  s = static_cast<double>(sum_s);
}

TEST(FresnelOracle, abramowitz_stegun_table_7_7) {
  // A&S Table 7.7 (10 decimals): C(1) = 0.7798934004, S(1) = 0.4382591474.
  double c = 0.0, s = 0.0;
  fresnel_series(1.0, c, s);
  constexpr double kTableTolerance = 1e-10;  // table gives 10 decimals
  EXPECT_NEAR(c, 0.7798934004, kTableTolerance);
  EXPECT_NEAR(s, 0.4382591474, kTableTolerance);
}

SectionSpec straight(double length) {
  return {SectionKind::kStraight, length};
}
SectionSpec transition(double length) {
  return {SectionKind::kTransition, length};
}
SectionSpec curve(double length, double radius, double cant = 0.0, double widening = 0.0) {
  return {SectionKind::kCurve, length, radius, cant, widening};
}

// Clothoid from a straight: heading theta(u) = c u^2 / 2 with c = 1 / (R L). Substituting
// c u^2 / 2 = pi t^2 / 2 gives x = sqrt(pi/c) C(u sqrt(c/pi)), y = sqrt(pi/c) S(...).
void expect_clothoid_from_straight(double radius, double length) {
  TrackDesign d;
  d.sections = {transition(length), curve(10.0, radius)};
  const Alignment a(d);
  const double c = 1.0 / (std::abs(radius) * length);
  const double scale = std::sqrt(kPi / c);
  double fc = 0.0, fs = 0.0;
  fresnel_series(length / scale, fc, fs);
  const auto p = a.frame(length).position;
  // Quadrature error is ~1e-15 relative (8-node Gauss per 0.5 rad panel); 1e-9 m leaves room
  // for the long-double series' rounding and is still 1e6 times below any physical effect.
  constexpr double kPositionTolerance = 1e-9;
  EXPECT_NEAR(p.x(), scale * fc, kPositionTolerance) << "R=" << radius << " L=" << length;
  EXPECT_NEAR(p.y(), std::copysign(scale * fs, radius), kPositionTolerance);
  EXPECT_NEAR(a.frame(length).heading, std::copysign(0.5 * c * length * length, radius), 1e-14);
}

TEST(Alignment, clothoid_endpoint_matches_fresnel) {
  expect_clothoid_from_straight(1000.0, 100.0);  // mainline transition, 0.05 rad turn
  expect_clothoid_from_straight(-300.0, 120.0);  // right-hand, 0.2 rad
  expect_clothoid_from_straight(20.0, 60.0);     // very sharp: 1.5 rad, 3 quadrature panels
}

// Clothoid between two curves of curvatures k1 -> k2 is the arc [k1/c, k2/c] of the unit
// clothoid of rate c: end displacement = rotated difference of two Fresnel points.
TEST(Alignment, clothoid_between_curves_matches_fresnel) {
  const double r1 = 800.0, r2 = 250.0, length = 90.0;
  TrackDesign d;
  d.start_heading = 0.3;
  d.sections = {curve(40.0, r1), transition(length), curve(40.0, r2)};
  const Alignment a(d);
  const double k1 = 1.0 / r1, k2 = 1.0 / r2, c = (k2 - k1) / length;
  const double scale = std::sqrt(kPi / c);
  const double ua = k1 / c, ub = k2 / c;  // unit-clothoid arc lengths of the ends
  double ca = 0.0, sa = 0.0, cb = 0.0, sb = 0.0;
  fresnel_series(ua / scale, ca, sa);
  fresnel_series(ub / scale, cb, sb);
  const double dx = scale * (cb - ca), dy = scale * (sb - sa);
  const TrackFrame f0 = a.frame(40.0), f1 = a.frame(40.0 + length);
  const double rot = f0.heading - 0.5 * c * ua * ua;  // unit-clothoid heading at ua is c ua^2/2
  const double ex = std::cos(rot) * dx - std::sin(rot) * dy;
  const double ey = std::sin(rot) * dx + std::cos(rot) * dy;
  constexpr double kPositionTolerance = 1e-9;  // as above
  EXPECT_NEAR(f1.position.x() - f0.position.x(), ex, kPositionTolerance);
  EXPECT_NEAR(f1.position.y() - f0.position.y(), ey, kPositionTolerance);
}

TEST(Alignment, circular_curve_points_lie_on_the_circle) {
  for (const double radius : {-450.0, 1200.0, 15.0}) {
    TrackDesign d;
    d.start_heading = -0.7;
    d.sections = {curve(3.0 * std::abs(radius), radius)};  // 3 rad of turn
    const Alignment a(d);
    const TrackFrame f0 = a.frame(0.0);
    // Centre: start point + R * left normal.
    const Eigen::Vector3d centre =
        f0.position + radius * Eigen::Vector3d(-std::sin(-0.7), std::cos(-0.7), 0.0);
    for (int i = 1; i <= 30; ++i) {
      const double s = a.end_s() * i / 30.0;
      const TrackFrame f = a.frame(s);
      // Closed form chord (sinc) in double: rounding ~1e-16 of R.
      const double kRadiusTolerance = 1e-12 * std::abs(radius) + 1e-12;
      EXPECT_NEAR((f.position - centre).norm(), std::abs(radius), kRadiusTolerance);
      EXPECT_NEAR(f.heading, -0.7 + s / radius, 1e-13);
    }
  }
}

TrackDesign fig_4_4_like() {
  // Toumi Fig. 4.4 layout: 50 m straight, 30 m transition, ~60 m curve, exit transition; then a
  // reverse curve with its own cant and gauge widening, and a straight.
  TrackDesign d;
  d.start_x = 10.0;
  d.start_heading = 0.1;
  d.sections = {straight(50.0),   transition(30.0),           curve(60.0, 300.0, 0.12, 0.01),
                transition(30.0), curve(40.0, -500.0, -0.08), transition(25.0),
                straight(20.0)};
  return d;
}

TEST(Alignment, continuous_through_transitions) {
  const Alignment a(fig_4_4_like());
  const int n = static_cast<int>(a.design().sections.size());
  constexpr double kDelta = 1e-8;  // half the step across each section boundary [m]
  for (int i = 1; i < n; ++i) {
    const double b = a.section_start(i);
    const TrackFrame lo = a.frame(b - kDelta), hi = a.frame(b + kDelta);
    // A continuous quantity changes by at most 2 delta max|f'| (< 2e-10) across the boundary; the
    // largest first derivatives here are |k| <= 1/300, |k'| <= 1/9000, |D'| <= 0.0067, |phi'| <=
    // 0.0045. Jumps to detect (a wrong ramp) are >= 1e-4, so 1e-9 separates cleanly.
    constexpr double kJump = 1e-9;
    EXPECT_NEAR(lo.heading, hi.heading, kJump) << "boundary " << i;
    EXPECT_NEAR(lo.curvature, hi.curvature, kJump) << "boundary " << i;
    EXPECT_NEAR(lo.cant, hi.cant, kJump) << "boundary " << i;
    EXPECT_NEAR(lo.cant_angle, hi.cant_angle, kJump) << "boundary " << i;
    EXPECT_NEAR(lo.gauge, hi.gauge, kJump) << "boundary " << i;
    EXPECT_NEAR((lo.position - hi.position).norm(), 2 * kDelta, kJump) << "boundary " << i;
    EXPECT_LT((lo.rotation - hi.rotation).norm(), kJump) << "boundary " << i;
  }
  // The curve values are reached: cant 0.12 and widening 0.01 over the first curve.
  const TrackFrame mid = a.frame(110.0);
  EXPECT_DOUBLE_EQ(mid.curvature, 1.0 / 300.0);
  EXPECT_DOUBLE_EQ(mid.cant, 0.12);
  EXPECT_DOUBLE_EQ(mid.gauge, 1.445);
  // Middle of the entry transition: half of everything.
  const TrackFrame ramp = a.frame(65.0);
  EXPECT_NEAR(ramp.curvature, 0.5 / 300.0, 1e-15);
  EXPECT_NEAR(ramp.cant, 0.06, 1e-15);
  EXPECT_NEAR(ramp.d_cant, 0.12 / 30.0, 1e-15);
  EXPECT_NEAR(ramp.d_curvature, 1.0 / 9000.0, 1e-18);
}

TEST(Alignment, derivatives_match_central_differences) {
  const Alignment a(fig_4_4_like());
  constexpr double kH = 1e-3;  // step [m]; central-difference error ~ h^2 f''' / 6
  for (double s = 0.5; s < a.end_s() - 0.5; s += 0.73) {
    const TrackFrame f = a.frame(s), fm = a.frame(s - kH), fp = a.frame(s + kH);
    if (fm.section != f.section || fp.section != f.section) continue;  // not across a kink
    // Heading is cubic-free (quadratic in s): difference exact to rounding ~1e-16 / 1e-3.
    constexpr double kTol = 1e-10;
    EXPECT_NEAR((fp.heading - fm.heading) / (2 * kH), f.curvature, kTol) << s;
    EXPECT_NEAR((fp.curvature - fm.curvature) / (2 * kH), f.d_curvature, kTol) << s;
    EXPECT_NEAR((fp.cant - fm.cant) / (2 * kH), f.d_cant, kTol) << s;
    EXPECT_NEAR((fp.cant_angle - fm.cant_angle) / (2 * kH), f.d_cant_angle, kTol) << s;
    EXPECT_NEAR((fp.d_cant_angle - fm.d_cant_angle) / (2 * kH), f.dd_cant_angle, kTol) << s;
    EXPECT_NEAR((fp.gauge - fm.gauge) / (2 * kH), f.d_gauge, kTol) << s;
    // Tangent = d position / ds (error h^2 k^2 / 6 ~ 2e-12).
    const Eigen::Vector3d tangent = (fp.position - fm.position) / (2 * kH);
    EXPECT_LT((tangent - f.rotation.col(0)).norm(), kTol) << s;
    // dR/ds = R [w]x with w the angular rate per length in track axes.
    const Eigen::Matrix3d dr = (fp.rotation - fm.rotation) / (2 * kH);
    const Eigen::Vector3d w = f.angular_rate_per_length();
    Eigen::Matrix3d wx;
    wx << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    EXPECT_LT((dr - f.rotation * wx).norm(), kTol) << s;
    const Eigen::Vector3d dw =
        (fp.angular_rate_per_length() - fm.angular_rate_per_length()) / (2 * kH);
    EXPECT_LT((dw - f.d_angular_rate_per_length()).norm(), kTol) << s;
    // Rotation stays orthonormal.
    EXPECT_LT((f.rotation.transpose() * f.rotation - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    // Rails: height difference is the cant, spacing the rail spacing.
    EXPECT_NEAR(f.right_rail_position().z() - f.left_rail_position().z(), f.cant, 1e-15);
  }
}

std::string validation_message(const TrackDesign& d) {
  try {
    d.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(TrackDesign, validate_names_the_field) {
  TrackDesign d;
  d.sections = {straight(10.0), transition(20.0), curve(30.0, 0.0)};
  EXPECT_EQ(validation_message(d).rfind("sections[2].radius: must be non-zero", 0), 0u)
      << validation_message(d);
  d.sections = {straight(10.0), SectionSpec{SectionKind::kCurve}};
  EXPECT_EQ(validation_message(d).rfind("sections[1].length:", 0), 0u) << validation_message(d);
  d.sections = {transition(10.0), transition(10.0)};
  EXPECT_EQ(validation_message(d).rfind("sections[1].kind: a transition cannot follow", 0), 0u);
  d.sections = {curve(10.0, 100.0, 1.6)};
  EXPECT_EQ(validation_message(d).rfind("sections[0].cant: |cant| must be smaller", 0), 0u);
  d.sections = {SectionSpec{SectionKind::kStraight, 5.0, 100.0}};
  EXPECT_EQ(validation_message(d).rfind("sections[0].radius: only a curve", 0), 0u);
  d.sections = {straight(5.0)};
  d.gauge = std::nan("");
  EXPECT_EQ(validation_message(d).rfind("gauge: must be positive", 0), 0u);
  d.gauge = 1.435;
  d.sections.clear();
  EXPECT_EQ(validation_message(d).rfind("sections: at least one", 0), 0u);
  d.sections = {straight(5.0), curve(10.0, 0.0)};
  try {
    d.validate("scene.track");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("scene.track.sections[1].radius:", 0), 0u) << e.what();
  }
  EXPECT_THROW((void)section_kind_from_string("spiral", "sections[3].kind"), std::invalid_argument);
  EXPECT_EQ(section_kind_from_string("clothoid"), SectionKind::kTransition);
}

TEST(Alignment, outside_the_design_throws) {
  TrackDesign d;
  d.start_s = 100.0;
  d.sections = {straight(10.0)};
  const Alignment a(d);
  EXPECT_NO_THROW((void)a.frame(100.0));
  EXPECT_NO_THROW((void)a.frame(110.0));
  EXPECT_THROW((void)a.frame(99.999), std::out_of_range);
  EXPECT_THROW((void)a.frame(110.001), std::out_of_range);
  EXPECT_THROW((void)a.frame(std::nan("")), std::out_of_range);
}

}  // namespace
}  // namespace ferro::track
