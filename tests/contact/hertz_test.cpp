// Hertz normal contact against closed forms, the thesis's annex A.1 table and Table 3.7.
#include "ferro/contact/normal/hertz.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ferro/contact/material.hpp"
#include "ferro/contact/normal/elliptic.hpp"
#include "ferro/contact/normal/normal_model.hpp"

namespace fc = ferro::contact;
constexpr double kPi = std::numbers::pi;

// K(k), E(k) by the arithmetic-geometric mean (complete_elliptic_integrals, used by the Hertz
// solution) against closed forms that owe nothing to an AGM: the lemniscatic case
// k = 1/sqrt(2), where K = Gamma(1/4)^2 / (4 sqrt(pi)) and E = (K^2 + pi/2) / (2 K), K(0) =
// E(0) = pi/2, and Legendre's relation E K' + E' K - K K' = pi/2 (primes: complementary
// modulus sqrt(1 - k^2)) from k = 1e-8 to 1 - 1e-12; against 20-digit values from mpmath
// (30-digit arithmetic: ellipk, ellipe at m = k^2) to 1e-15; and against libstdc++'s Carlson
// forms (std::comp_ellint_1/2), an independent implementation whose own error near k -> 1 is
// up to 7e-13 (against the same mpmath values), hence that comparison's 1e-12.
TEST(elliptic_integrals, agm_against_closed_forms_mpmath_and_carlson) {
  constexpr double kTol = 1e-13;
  constexpr double kCarlsonRelTol = 1e-12;
  constexpr double kMpmathRelTol = 1e-15;
  struct Reference {
    double k, big_k, big_e;
  };
  for (const Reference& r : {Reference{0.9, 2.2805491384227703005, 1.1716970527816141138},
                             Reference{0.99, 3.3566005233611919425, 1.0284758090288040219},
                             Reference{0.999999, 7.9474797735479670327, 1.0000074474777243921}}) {
    const auto ke = fc::complete_elliptic_integrals(r.k);
    EXPECT_NEAR(ke.first / r.big_k, 1.0, kMpmathRelTol) << "k=" << r.k;
    EXPECT_NEAR(ke.second / r.big_e, 1.0, kMpmathRelTol) << "k=" << r.k;
  }
  const double k_lemn = 1.0 / std::sqrt(2.0);
  const double big_k = std::pow(std::tgamma(0.25), 2) / (4.0 * std::sqrt(kPi));
  const auto lemn = fc::complete_elliptic_integrals(k_lemn);
  EXPECT_NEAR(lemn.first / big_k, 1.0, kTol);
  EXPECT_NEAR(lemn.second / ((big_k * big_k + 0.5 * kPi) / (2.0 * big_k)), 1.0, kTol);
  const auto zero = fc::complete_elliptic_integrals(0.0);
  EXPECT_DOUBLE_EQ(zero.first, 0.5 * kPi);
  EXPECT_DOUBLE_EQ(zero.second, 0.5 * kPi);
  for (double k : {1e-8, 0.01, 0.1, 0.5, 0.9, 0.99, 0.999999, 1.0 - 1e-12}) {
    const double kc = std::sqrt((1.0 - k) * (1.0 + k));
    const auto ke = fc::complete_elliptic_integrals(k);
    const auto ke1 = fc::complete_elliptic_integrals(kc);
    EXPECT_NEAR((ke.second * ke1.first + ke1.second * ke.first - ke.first * ke1.first) /
                    (0.5 * kPi),
                1.0, 1e3 * kTol)
        << "k=" << k;
    EXPECT_NEAR(ke.first / std::comp_ellint_1(k), 1.0, kCarlsonRelTol) << "k=" << k;
    EXPECT_NEAR(ke.second / std::comp_ellint_2(k), 1.0, kCarlsonRelTol) << "k=" << k;
  }
  EXPECT_THROW((void)fc::complete_elliptic_integrals(1.0), std::invalid_argument);
  EXPECT_THROW((void)fc::complete_elliptic_integrals(-0.1), std::invalid_argument);
}

// A curvature ratio beyond what the elliptic solution resolves never surfaces as an elliptic
// modulus error: hertz_curvatures' one documented treatment bounds the curvatures
// (kHertzMaxCurvature, then kHertzMinCurvatureRatio), and the solution is Hertz's at the bounded
// curvatures. The axis-ratio relation itself refuses ratios it cannot resolve as a line contact.
TEST(hertz_ellipse, extreme_curvature_ratio_is_bounded) {
  const fc::Material steel = fc::Material::from_young(210e9, 0.28);
  const double e_star = fc::combine(steel, steel).contact_modulus;
  const fc::HertzCurvatures cv = fc::hertz_curvatures(1.0, 1e13);
  EXPECT_DOUBLE_EQ(cv.y, fc::kHertzMaxCurvature);
  EXPECT_DOUBLE_EQ(cv.x, fc::kHertzMinCurvatureRatio * fc::kHertzMaxCurvature);
  const fc::HertzSolution h = fc::hertz_solve(1.0, 1e13, 1e4, e_star);
  const fc::HertzSolution bounded = fc::hertz_solve(cv.x, cv.y, 1e4, e_star);
  EXPECT_TRUE(std::isfinite(h.semi_axis_x) && std::isfinite(h.semi_axis_y));
  EXPECT_DOUBLE_EQ(h.semi_axis_x, bounded.semi_axis_x);
  EXPECT_DOUBLE_EQ(h.semi_axis_y, bounded.semi_axis_y);
  try {
    (void)fc::hertz_axis_ratio(1e13);
    ADD_FAILURE() << "axis ratio for curvature ratio 1e13 accepted";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("line contact"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("modulus"), std::string::npos) << msg;
  }
  // Within the resolved range the axis-ratio relation inverts (Johnson 3.69).
  EXPECT_NEAR(fc::hertz_curvature_ratio(fc::hertz_axis_ratio(1e9)) / 1e9, 1.0, 1e-6);
}

// Spheres R1 = 300 mm, R2 = 460 mm, E = 210 GPa, nu = 0.28 (Toumi eqs. 88-91):
// a = (3 F R / 4E*)^(1/3), delta = a^2/R, p_max = 3F/(2 pi a^2), 1/R = 1/R1 + 1/R2.
TEST(hertz_spheres, closed_form) {
  constexpr double kTol = 1e-6;  // issue requirement; the solver is exact to ~1e-14
  const fc::Material steel = fc::Material::from_young(210e9, 0.28);
  const fc::CombinedMaterial m = fc::combine(steel, steel);
  const double r1 = 0.300, r2 = 0.460;
  const double r = 1.0 / (1.0 / r1 + 1.0 / r2);
  const double curvature = 0.5 * (1.0 / r1 + 1.0 / r2);  // A = B (eqs. 6-7)
  for (double force : {1e3, 1e4, 1e5}) {
    const fc::HertzSolution h = fc::hertz_solve(curvature, curvature, force, m.contact_modulus);
    const double a = std::cbrt(3.0 * force * r / (4.0 * m.contact_modulus));
    EXPECT_NEAR(h.semi_axis_x / a, 1.0, kTol);
    EXPECT_NEAR(h.semi_axis_y / a, 1.0, kTol);
    EXPECT_NEAR(h.approach / (a * a / r), 1.0, kTol);
    EXPECT_NEAR(h.peak_pressure / (3.0 * force / (2.0 * kPi * a * a)), 1.0, kTol);
    // F = 4/3 E* sqrt(R) delta^1.5 (eq. 90).
    EXPECT_NEAR(4.0 / 3.0 * m.contact_modulus * std::sqrt(r) * std::pow(h.approach, 1.5) / force,
                1.0, kTol);
    // p(r) = 1.5 p_mean sqrt(1 - r^2/a^2) at r = a/2.
    const double p_mean = force / (kPi * a * a);
    EXPECT_NEAR(h.pressure(0.3 * a, 0.4 * a) / (1.5 * p_mean * std::sqrt(0.75)), 1.0, kTol);
  }
}

// A nearly spherical ellipse must be continuous with the sphere (no 0/0 trouble).
TEST(hertz_spheres, continuity_near_circle) {
  const double e_star = 1.15e11;
  const fc::HertzSolution s = fc::hertz_solve(1.0, 1.0, 1e4, e_star);
  const fc::HertzSolution n = fc::hertz_solve(1.0, 1.0 + 1e-9, 1e4, e_star);
  EXPECT_NEAR(n.semi_axis_x / s.semi_axis_x, 1.0, 1e-8);
  EXPECT_NEAR(n.approach / s.approach, 1.0, 1e-8);
}

// The elliptic solution satisfies Johnson's (3.69)-(3.70) with std::comp_ellint (independent
// special functions) and carries the load: F = (2/3) p_max pi a b.
TEST(hertz_ellipse, curvatures_recovered_with_std_special_functions) {
  constexpr double kTol = 1e-10;
  const double e_star = 1.15e11, force = 7.5e4;
  for (double ratio : {1.5, 4.0, 30.0, 300.0}) {
    const double a_curv = 1.0, b_curv = ratio;  // B > A: major axis along x
    const fc::HertzSolution h = fc::hertz_solve(a_curv, b_curv, force, e_star);
    const double big = h.semi_axis_x, small = h.semi_axis_y;
    const double e = std::sqrt(1.0 - (small / big) * (small / big));
    const double kk = std::comp_ellint_1(e), ee = std::comp_ellint_2(e);
    const double p0 = h.peak_pressure;
    const double coef = p0 / e_star * small / (e * e * big * big);
    EXPECT_NEAR(coef * (kk - ee) / a_curv, 1.0, kTol) << ratio;
    EXPECT_NEAR(coef * ((big * big) / (small * small) * ee - kk) / b_curv, 1.0, kTol) << ratio;
    EXPECT_NEAR(p0 * small / e_star * kk / h.approach, 1.0, kTol) << ratio;
    EXPECT_NEAR(2.0 / 3.0 * p0 * kPi * big * small / force, 1.0, kTol);
    // Swapping the curvatures swaps the axes.
    const fc::HertzSolution t = fc::hertz_solve(b_curv, a_curv, force, e_star);
    EXPECT_NEAR(t.semi_axis_y / h.semi_axis_x, 1.0, 1e-14);
    EXPECT_NEAR(t.semi_axis_x / h.semi_axis_y, 1.0, 1e-14);
  }
}

// Annex A.1: m, n, r against theta, printed to 2 decimals (r to 1 decimal at 10 and 20 deg).
// Tolerance: half a unit of the last printed digit. Two conventions/defects of the printed table:
// (1) its r column is 2K(e)/pi, i.e. r of eq. (10) times m (delta = r c^2 (A+B) / m with the
// printed r); we compare r_eq10 * m. (2) Three entries miss their printed precision: m(20) = 3.78
// (exact 3.816), n(10) = 0.32 (exact 0.311), m(70) = 1.28 (exact 1.2851). The exact values are
// checked against Johnson's closed forms above; the printed m(20) and n(20) are not even
// consistent with each other (their ratio n/m = 0.1085 gives theta = 20.0 deg only with m = 3.816).
// Those entries are held to kHistoricTol instead.
TEST(hertz_annex_a1, m_n_r_table) {
  struct Row {
    double theta_deg, m, n, r, r_tol;
  };
  const Row rows[] = {
      {10, 6.61, 0.32, 2.8, 0.05},   {20, 3.78, 0.41, 2.3, 0.05},   {30, 2.73, 0.49, 1.98, 0.005},
      {40, 2.14, 0.57, 1.74, 0.005}, {50, 1.75, 0.64, 1.55, 0.005}, {60, 1.49, 0.72, 1.39, 0.005},
      {70, 1.28, 0.80, 1.25, 0.005}, {80, 1.13, 0.89, 1.12, 0.005}, {90, 1.0, 1.0, 1.0, 0.005}};
  constexpr double kHalfUnit = 0.005 + 1e-12;
  constexpr double kHistoricTol = 0.03;  // relative, for the three defective entries only
  // The r column is off by up to 0.37 % (40 and 50 deg: 1.746 and 1.556 printed 1.74 and 1.55).
  constexpr double kRTol = 0.004;
  for (const Row& row : rows) {
    const fc::HertzCoefficients c = fc::hertz_coefficients(row.theta_deg * kPi / 180.0);
    if (row.theta_deg == 20 || row.theta_deg == 70) {
      EXPECT_NEAR(c.m / row.m, 1.0, kHistoricTol) << "theta=" << row.theta_deg;
      EXPECT_GT(std::abs(c.m - row.m), kHalfUnit) << "entry now within precision: update the note";
    } else {
      EXPECT_NEAR(c.m, row.m, kHalfUnit) << "theta=" << row.theta_deg;
    }
    if (row.theta_deg == 10) {
      EXPECT_NEAR(c.n / row.n, 1.0, kHistoricTol) << "theta=" << row.theta_deg;
    } else {
      EXPECT_NEAR(c.n, row.n, kHalfUnit) << "theta=" << row.theta_deg;
    }
    EXPECT_NEAR(c.r * c.m, row.r, std::max(row.r_tol + 1e-12, kRTol * row.r))
        << "theta=" << row.theta_deg;
  }
}

// Thesis chapter 3 case (Table 3.1/3.7): wheel diameter 920 mm with a 1/10 conical tread
// (transversally straight), UIC60 rail crown radius 300 mm, inclined 1/10, E = 210 GPa,
// nu = 0.28, wheel load 7.5 t. Hertz row: a = 6.66 mm, b = 5.05 mm, area 104.7 mm^2,
// p_max = 1160 MPa. The thesis's row is not self-consistent (p_max 2 pi a b / 3 = 81.7 kN for a
// 73.6 kN load), hence the 5 % tolerance.
TEST(thesis_table_3_7, hertz_row) {
  constexpr double kTol = 0.05;
  const fc::Material steel = fc::Material::from_young(210e9, 0.28);
  fc::NormalProblem p;
  const double gamma = std::atan(0.1);
  p.curvature_x = std::cos(gamma) / (2.0 * 0.460);  // eqs. (6), (14): rail straight along x
  p.curvature_y = 1.0 / (2.0 * 0.300);              // eqs. (7), (15)-(16): conical tread
  p.normal_force = 7.5e3 * 9.81;
  p.body1 = steel;
  p.body2 = steel;
  const auto model = fc::make_normal_model("hertz");
  const fc::NormalSolution s = model->solve(p);
  ASSERT_EQ(s.patches.size(), 1u);
  const fc::ContactPatch& c = s.patches[0];
  EXPECT_NEAR(c.semi_axis_x / 6.66e-3, 1.0, kTol) << c.semi_axis_x;
  EXPECT_NEAR(c.semi_axis_y / 5.05e-3, 1.0, kTol) << c.semi_axis_y;
  EXPECT_NEAR(kPi * c.semi_axis_x * c.semi_axis_y / 104.7e-6, 1.0, 2.0 * kTol);
  EXPECT_NEAR(c.peak_pressure / 1160e6, 1.0, kTol) << c.peak_pressure;
  RecordProperty("a_mm", std::to_string(c.semi_axis_x * 1e3));
  RecordProperty("b_mm", std::to_string(c.semi_axis_y * 1e3));
  RecordProperty("p_max_MPa", std::to_string(c.peak_pressure * 1e-6));
}

TEST(normal_registry, names_and_errors) {
  EXPECT_EQ(fc::make_normal_model("hertz")->name(), "hertz");
  EXPECT_EQ(fc::make_normal_model("semi_hertz", {{"strips", "50"}})->name(), "semi_hertz");
  try {
    (void)fc::make_normal_model("hertzz");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("semi_hertz"), std::string::npos);
  }
  EXPECT_THROW((void)fc::make_normal_model("semi_hertz", {{"stripes", "5"}}),
               std::invalid_argument);
  EXPECT_THROW((void)fc::make_normal_model("semi_hertz", {{"strips", "x"}}), std::invalid_argument);
}

