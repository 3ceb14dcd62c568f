// Contact geometry sources and the normal patch from a penetration: Hertz at a given approach
// against the closed-form sphere and the load-driven exact solve, the reference-state scaling of
// imported tables, the conical wheelset against an independent point-inversion of the cone
// surface, the online search source against the vertical-load solve.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "a22_pair.hpp"
#include "ferro/contact/geometry/conical_source.hpp"
#include "ferro/contact/geometry/point_normal_contact.hpp"
#include "ferro/contact/geometry/search_source.hpp"
#include "ferro/contact/normal/hertz.hpp"

namespace fc = ferro::contact;

namespace {

const std::string kData = FERRO_DATA_DIR;

// Relative error of the tabulated approach relation against the exact solve: cubic interpolation
// on a 4096-node grid of ln(rho) over [0, ln 1e6] (step 3.4e-3) is good to ~1e-9 (measured); 1e-7
// leaves room.
constexpr double kRelationTol = 1e-7;

double a22_contact_modulus() {
  const double e = 2.0 * 82.0e9 * 1.28;
  return e / (2.0 * (1.0 - 0.28 * 0.28));
}

using ferro::test::a22_pair;

}  // namespace

TEST(hertz_from_approach, sphere_closed_form) {
  // Sphere of radius R on a plane: F = 4/3 E* sqrt(R) delta^1.5, a = b = sqrt(R delta),
  // p0 = 3F/(2 pi a^2) (Johnson eqs. 4.22-4.23). Relative tolerance: the table error.
  const double estar = 114.0e9, r = 0.3, delta = 50e-6;
  const fc::HertzSolution h = fc::hertz_solve_from_approach(0.5 / r, 0.5 / r, delta, estar);
  const double f = 4.0 / 3.0 * estar * std::sqrt(r) * std::pow(delta, 1.5);
  EXPECT_NEAR(h.normal_force / f, 1.0, kRelationTol);
  EXPECT_NEAR(h.semi_axis_x / std::sqrt(r * delta), 1.0, kRelationTol);
  EXPECT_NEAR(h.semi_axis_y / std::sqrt(r * delta), 1.0, kRelationTol);
  EXPECT_NEAR(h.peak_pressure / (3.0 * f / (2.0 * std::numbers::pi * r * delta)), 1.0,
              kRelationTol);
  EXPECT_EQ(h.approach, delta);
}

TEST(hertz_from_approach, agrees_with_the_exact_load_solve_over_all_curvature_ratios) {
  // Inverse check: the load found at approach delta, given to the exact load-driven solve
  // (Newton on the elliptic integrals, no table), must give back delta, a and b. Covers ratios
  // 1 .. 1e7 (beyond the table: exact path) in both orientations, off the table nodes.
  const double estar = a22_contact_modulus();
  for (double lnrho = 0.0; lnrho < 16.0; lnrho += lnrho < 0.01 ? 0.00043 : 0.0937) {
    const double rho = std::exp(lnrho);
    for (const bool swap : {false, true}) {
      const double a = swap ? 2.0 * rho : 2.0, b = swap ? 2.0 : 2.0 * rho;
      const double delta = 30e-6;
      const fc::HertzSolution h = fc::hertz_solve_from_approach(a, b, delta, estar);
      const fc::HertzSolution e = fc::hertz_solve(a, b, h.normal_force, estar);
      EXPECT_NEAR(e.approach / delta, 1.0, kRelationTol) << "rho " << rho;
      EXPECT_NEAR(e.semi_axis_x / h.semi_axis_x, 1.0, kRelationTol) << "rho " << rho;
      EXPECT_NEAR(e.semi_axis_y / h.semi_axis_y, 1.0, kRelationTol) << "rho " << rho;
      EXPECT_NEAR(e.peak_pressure / h.peak_pressure, 1.0, kRelationTol) << "rho " << rho;
    }
  }
}

TEST(hertz_from_approach, conformal_curvature_has_one_documented_treatment) {
  // B <= 0 is raised to kHertzMinCurvatureRatio A, in both the load- and approach-driven solves;
  // the larger curvature must be > 0.
  const double estar = a22_contact_modulus(), a = 1.5;
  const double b_floor = fc::kHertzMinCurvatureRatio * a;
  const fc::HertzSolution neg = fc::hertz_solve_from_approach(a, -3.0, 20e-6, estar);
  const fc::HertzSolution flo = fc::hertz_solve_from_approach(a, b_floor, 20e-6, estar);
  EXPECT_EQ(neg.normal_force, flo.normal_force);
  const fc::HertzSolution neg_f = fc::hertz_solve(a, -3.0, 1e4, estar);
  const fc::HertzSolution flo_f = fc::hertz_solve(a, b_floor, 1e4, estar);
  EXPECT_EQ(neg_f.approach, flo_f.approach);
  EXPECT_THROW((void)fc::hertz_solve_from_approach(-1.0, -1.0, 1e-6, estar),
               std::invalid_argument);
  EXPECT_THROW((void)fc::hertz_solve(-1.0, 0.0, 1e3, estar), std::invalid_argument);
}

TEST(hertz_patch_from_penetration, reference_state_power_laws) {
  // Imported tables: F = F0 (d/d0)^1.5, a, b scale as (F/F0)^(1/3), p0 = 3F/(2 pi a b).
  fc::WheelRailContact c;
  c.ref_normal_force = 60e3;
  c.ref_penetration = 80e-6;
  c.ref_semi_axis_a = 6e-3;
  c.ref_semi_axis_b = 4e-3;
  c.penetration = 2.0 * c.ref_penetration;
  const fc::ContactPatch p = fc::hertz_patch_from_penetration(c, a22_contact_modulus());
  EXPECT_DOUBLE_EQ(p.normal_force, 60e3 * std::pow(2.0, 1.5));
  EXPECT_DOUBLE_EQ(p.semi_axis_x, 6e-3 * std::cbrt(std::pow(2.0, 1.5)));
  EXPECT_DOUBLE_EQ(p.semi_axis_y, 4e-3 * std::cbrt(std::pow(2.0, 1.5)));
  EXPECT_NEAR(p.peak_pressure,
              3.0 * p.normal_force / (2.0 * std::numbers::pi * p.semi_axis_x * p.semi_axis_y),
              1e-6);
  c.penetration = -1e-6;  // lift: no force, no patch
  const fc::ContactPatch lift = fc::hertz_patch_from_penetration(c, a22_contact_modulus());
  EXPECT_EQ(lift.normal_force, 0.0);
  EXPECT_EQ(lift.semi_axis_x, 0.0);
}

TEST(hertz_patch_from_penetration, curvature_state_is_the_hertz_solution) {
  // Without a reference state the patch is Hertz's for the curvatures: its load, given to the
  // exact load-driven solve, reproduces the approach.
  fc::WheelRailContact c;
  c.curvature_a = 1.09;
  c.curvature_b = 3.3;
  c.penetration = 70e-6;
  const fc::ContactPatch p = fc::hertz_patch_from_penetration(c, a22_contact_modulus());
  const fc::HertzSolution e = fc::hertz_solve(1.09, 3.3, p.normal_force, a22_contact_modulus());
  EXPECT_NEAR(e.approach / 70e-6, 1.0, kRelationTol);
  EXPECT_NEAR(p.semi_axis_x / e.semi_axis_x, 1.0, kRelationTol);
  EXPECT_EQ(p.approach, 70e-6);
}

namespace {

// Independent point inversion of the conical wheel: the track point (0, y, z) is on the cone
// surface of wheel s when its wheelset-frame distance from the axle equals r(y_w). Bisection on z.
double cone_surface_z(const fc::ConicalContactParams& q, const fc::WheelsetPose& pose, double s,
                      double y) {
  const double cphi = std::cos(pose.roll), sphi = std::sin(pose.roll);
  auto residual = [&](double z) {
    const double dy = y - pose.lateral;
    const double dz = z - (-q.nominal_radius + pose.vertical);
    const double yw = cphi * dy + sphi * dz;  // Rx(phi)^T
    const double zw = -sphi * dy + cphi * dz;
    const double r = q.nominal_radius + q.conicity * (q.contact_half_distance - s * yw);
    return zw - r;  // < 0 above the lowest point of the wheel
  };
  double lo = -0.1, hi = 0.1;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (residual(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

fc::ConicalContactParams cone() {
  fc::ConicalContactParams q;
  q.conicity = 0.2;
  q.contact_half_distance = 0.7465;
  q.nominal_radius = 0.46;
  q.curvature_a = 1.087;
  q.curvature_b = 1.67;
  return q;
}

}  // namespace

TEST(conical_contact_source, linear_theory_rolling_radii_at_zero_roll) {
  // Zero roll: r = r0 +- gamma y exactly, penetration (v +- gamma y) cos(atan gamma) (right +).
  const fc::ConicalContactSource src(cone());
  const double g = 0.2, y = 3e-3, v = 1e-3;
  std::vector<fc::WheelRailContact> out;
  src.contacts(fc::WheelsetPose{y, v, 0.0, 0.0}, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].side, fc::Side::left);
  EXPECT_NEAR(out[0].rolling_radius, 0.46 - g * y, 1e-15);
  EXPECT_NEAR(out[1].rolling_radius, 0.46 + g * y, 1e-15);
  EXPECT_NEAR(out[0].penetration, (v - g * y) * std::cos(std::atan(g)), 1e-15);
  EXPECT_NEAR(out[1].penetration, (v + g * y) * std::cos(std::atan(g)), 1e-15);
  EXPECT_NEAR(out[1].y, 0.7465, 0.0);
  // Lift: a large shift to the right lifts the left wheel.
  src.contacts(fc::WheelsetPose{10e-3, v, 0.0, 0.0}, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].side, fc::Side::right);
}

TEST(conical_contact_source, rolled_wheelset_against_point_inversion_of_the_cone) {
  // Large roll (0.05 rad) and shift: gap from the closed-form section against bisection on the
  // cone surface (1e-12 m: bisection resolution); contact angle atan(gamma) -+ roll against the
  // numerical gradient of the cone surface along the crown (1e-6 rad: central difference).
  const fc::ConicalContactParams q = cone();
  const fc::ConicalContactSource src(q);
  const fc::WheelsetPose pose{4e-3, 2e-3, 0.05, 0.0};
  for (const fc::Side side : {fc::Side::left, fc::Side::right}) {
    const double s = side == fc::Side::right ? 1.0 : -1.0;
    const fc::WheelRailContact c = src.wheel_point(pose, side);
    const double y = s * q.contact_half_distance;
    EXPECT_NEAR(-c.vertical_gap, cone_surface_z(q, pose, s, y), 1e-12);
    // Contact angle: -atan(s dz/dy) of the wheel surface along the crown (z down, + towards the
    // track centre).
    const double h = 1e-5;
    const double slope =
        (cone_surface_z(q, pose, s, y + h) - cone_surface_z(q, pose, s, y - h)) / (2.0 * h);
    EXPECT_NEAR(c.contact_angle, -std::atan(s * slope), 1e-6) << "side " << s;
    EXPECT_NEAR(c.contact_angle, std::atan(q.conicity) - s * pose.roll, 1e-12);
  }
}

TEST(search_contact_source, normal_forces_balance_the_vertical_load) {
  // The vertical-load solve (Hertz springs, own stiffness path) finds the drop carrying 100 kN;
  // the search source at that pose with hertz_patch_from_penetration must carry the same load
  // (sum F_n cos(gamma)). Tolerance: the table relation (1e-7) plus the bisection (1e-13 m).
  const auto pair = a22_pair();
  const double estar = a22_contact_modulus(), load = 100e3;
  for (const double y : {0.0, 4e-3, 7e-3}) {
    const fc::LoadedWheelset lw = fc::solve_vertical_load(*pair, {y, 0.0, 0.0, 0.0}, load, estar);
    const fc::SearchContactSource src(pair);
    std::vector<fc::WheelRailContact> out;
    src.contacts(lw.pose, out);
    ASSERT_EQ(out.size(), lw.points.size());
    double total = 0.0;
    for (const fc::WheelRailContact& c : out) {
      total += fc::hertz_patch_from_penetration(c, estar).normal_force * std::cos(c.contact_angle);
    }
    EXPECT_NEAR(total / load, 1.0, 1e-6) << "y " << y;
  }
}
