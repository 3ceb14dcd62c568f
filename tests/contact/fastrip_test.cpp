// FaStrip (fastrip.hpp) against closed forms: Kalker's linear theory at small creepage, Coulomb at
// full slip, and the strip-theory integral of Carter's two-dimensional solution (pure
// creepage) evaluated independently by quadrature over the strips.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "ferro/contact/tangential/tangential_model.hpp"
#include "reference_tangential_case.hpp"

namespace fc = ferro::contact;

namespace {

// The reference set (support/reference_tangential_case.hpp).
constexpr double kFn = ferro::test::kRefNormalForce, kMu = ferro::test::kRefFriction,
                 kG = ferro::test::kRefShearModulus, kNu = ferro::test::kRefPoisson;
using Case = ferro::test::ReferenceCase;

fc::TangentialSolution solve(const fc::ModelOptions& o, const fc::TangentialProblem& p) {
  return fc::make_tangential_model("fastrip", o)->solve(p);
}

// Semi-axes at c = sqrt(ab) = 6 mm.
double semi_a(double ratio) {
  return 6e-3 * std::sqrt(ratio);
}
double semi_b(double ratio) {
  return 6e-3 / std::sqrt(ratio);
}

}  // namespace

// At small creepage the forces are Kalker's linear theory: F_x = -G a b C11 xi_x,
// F_y = -G a b C22 xi_y and F_y = -G (ab)^1.5 C23 phi. The creepages give a linear force of
// 1e-4 mu F_n, where Carter's quadratic term is ~1e-4 relative; kTolLinear = 1e-3 relative
// (the slopes are normalised exactly at any grid, so this also holds at 8 x 8).
TEST(fastrip_linear, slopes_equal_kalker) {
  constexpr double kTolLinear = 1e-3;
  for (const double ratio : {0.2, 1.0, 5.0}) {
    for (const int n : {8, 12, 30}) {
      const fc::ModelOptions o{{"mx", std::to_string(n)}, {"my", std::to_string(n)}};
      const double a = semi_a(ratio), b = semi_b(ratio);
      const fc::KalkerCoefficients c = fc::kalker_coefficients_table(a, b, kNu);
      const double f = 1e-4 * kMu * kFn;
      const double xi = f / (kG * a * b * c.c11), eta = f / (kG * a * b * c.c22);
      const double phi = f / (kG * std::pow(a * b, 1.5) * c.c23);
      const Case cx(a, b, {xi, 0.0, 0.0}), cy(a, b, {0.0, eta, 0.0}), cs(a, b, {0.0, 0.0, phi});
      EXPECT_NEAR(solve(o, cx.problem).force_x / -f, 1.0, kTolLinear) << ratio << " " << n;
      EXPECT_NEAR(solve(o, cy.problem).force_y / -f, 1.0, kTolLinear) << ratio << " " << n;
      EXPECT_NEAR(solve(o, cs.problem).force_y / -f, 1.0, kTolLinear) << ratio << " " << n;
    }
  }
}

// Full slip: every element carries mu p along the slip, so |F| = mu F_n (Coulomb) to round-off
// along an axis (kTolCoulomb = 1e-9 relative: the element pressures are exact averages whose sum
// is F_n) and never above it; for combined creepage the leading element of each strip starts
// along Kalker's weighted direction, not the slip's, so |F| falls short by up to
// kTolCombined = 1e-3 and the force opposes the creepage within kTolDirection = 0.01 rad.
TEST(fastrip_coulomb, full_slip_is_mu_fn_never_above) {
  constexpr double kTolCoulomb = 1e-9, kTolCombined = 1e-3, kTolDirection = 0.01;
  for (const double ratio : {0.2, 1.0, 5.0}) {
    const double a = semi_a(ratio), b = semi_b(ratio);
    for (const double angle : {0.0, 0.5, 0.5 * std::numbers::pi, 2.0}) {
      const double xi = 0.2 * std::cos(angle), eta = 0.2 * std::sin(angle);
      const Case k(a, b, {xi, eta, 0.0});
      const fc::TangentialSolution f = solve({}, k.problem);
      const double ft = std::hypot(f.force_x, f.force_y) / (kMu * kFn);
      const bool axis = angle == 0.0 || angle == 0.5 * std::numbers::pi;
      EXPECT_NEAR(ft, 1.0, axis ? kTolCoulomb : kTolCombined) << ratio << " " << angle;
      EXPECT_LE(ft, 1.0 + kTolCoulomb) << ratio << " " << angle;
      EXPECT_NEAR(std::atan2(-f.force_y, -f.force_x), angle, kTolDirection) << ratio;
      for (const double phi : {2.0, 20.0, 200.0}) {
        const Case s(a, b, {xi * 1e-2, eta * 1e-2, phi});
        const fc::TangentialSolution g = solve({{"mx", "20"}, {"my", "9"}}, s.problem);
        EXPECT_LE(std::hypot(g.force_x, g.force_y), kMu * kFn * (1.0 + kTolCoulomb)) << ratio;
      }
    }
  }
}

// Strip theory (Haines & Ollerton; Kalker): strip y of the ellipse is Carter's two-dimensional
// solution, force mu P(y) (1 - (1 - tau(y))^2), with P(y) = (pi/2) p0 a (1 - y^2/b^2) and
// tau(y) = tau_c / sqrt(1 - y^2/b^2) (Carter's saturation creepage is proportional to the
// strip's peak pressure); tau_c = w 8 / (3 pi) makes the linear slope Kalker's,
// w = G a b C11 xi / (2 mu F_n). The model follows Carter exactly on strips with tau <= 1/2
// (their slip zone lies where the bound decreases); on strips past it (the patch's lateral
// edges, little load at small w) its slip zone lags the bound as FASTSIM's does.
// (1) the total force at w <= 0.2 against the strip integral by Simpson's rule (20000 panels in
// y = b sin(theta)), kTolStrip = 1e-3 mu F_n (the edge strips), on a 400 x 200 grid: at coarse
// mx the element that ends the adhesion zone lags the bound in the next ones, an O(dx) effect
// (0.006 mu F_n at w = 0.2 on 12 x 200);
// (2) the centre strip's element tractions against element averages of Carter's traction
// mu p0 (sqrt(1 - s^2) - u sqrt(1 - s'^2)), u = 1 - tau, s' = (s - 1 + u)/u, integrated here by
// the midpoint rule on 2000 sub-intervals per element: kTolCarter = 1e-4 mu p0.
TEST(fastrip_strip_theory, pure_creepage_is_carter_on_every_strip) {
  constexpr double kTolStrip = 1e-3, kTolCarter = 1e-4;
  constexpr double kPi = std::numbers::pi;
  for (const double ratio : {0.2, 1.0, 5.0}) {
    const double a = semi_a(ratio), b = semi_b(ratio);
    const fc::KalkerCoefficients c = fc::kalker_coefficients_table(a, b, kNu);
    for (const double w : {0.05, 0.1, 0.2}) {
      const double xi = w * 2.0 * kMu * kFn / (kG * a * b * c.c11);
      const double tau_c = w * 8.0 / (3.0 * kPi);
      // F / (mu F_n) = (3/4) integral over theta in [-pi/2, pi/2] of cos^3 g(tau_c / cos), with
      // g(t) = 1 - (1 - t)^2 (t < 1), 1 otherwise: P(y) dy / F_n = (3/4) cos^3(theta) dtheta.
      const int panels = 20000;
      const double h = kPi / panels;
      double sum = 0.0;
      for (int i = 0; i <= panels; ++i) {
        const double th = -0.5 * kPi + i * h;
        const double cth = std::cos(th);
        double v = 0.0;
        if (cth > 0.0) {
          const double t = tau_c / cth;
          v = cth * cth * cth * (t < 1.0 ? 1.0 - (1.0 - t) * (1.0 - t) : 1.0);
        }
        sum += v * (i == 0 || i == panels ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
      }
      const double expected = 0.75 * sum * h / 3.0;
      const Case k(a, b, {xi, 0.0, 0.0});
      const double got = -solve({{"mx", "400"}, {"my", "200"}}, k.problem).force_x / (kMu * kFn);
      EXPECT_NEAR(got, expected, kTolStrip) << "a/b " << ratio << " w " << w;
    }
    // Centre strip of an odd strip count (y = 0): tau = tau_c / r_0 with r_0 = 1 here.
    const int my = 201, mx = 16;
    const double w = 0.4 * 3.0 * kPi / 8.0;  // tau_c = 0.4 on the continuum
    fc::TractionMap map;
    Case k(a, b, {w * 2.0 * kMu * kFn / (kG * a * b * c.c11), 0.0, 0.0});
    k.problem.map = &map;
    (void)solve({{"mx", std::to_string(mx)}, {"my", std::to_string(my)}}, k.problem);
    // The model's tau_c on its midpoint strips: sum r^2 / sum r over the strips, times w.
    double s2 = 0.0, s1 = 0.0;
    for (int j = 0; j < my; ++j) {
      const double y = -1.0 + (j + 0.5) * 2.0 / my;
      s2 += 1.0 - y * y;
      s1 += std::sqrt(1.0 - y * y);
    }
    const double u = 1.0 - w * s2 / s1;
    const double p0 = 2.0 * kFn / (kPi * a * 2.0 * b / my * s2);  // strip loads sum to F_n
    const std::size_t first = static_cast<std::size_t>((my / 2) * mx);
    for (int e = 0; e < mx; ++e) {
      const int sub = 2000;
      double avg = 0.0;
      for (int q = 0; q < sub; ++q) {
        const double s = 1.0 - (e + (q + 0.5) / sub) * 2.0 / mx;
        const double sp = (s - 1.0 + u) / u;
        avg += std::sqrt(1.0 - s * s) - (std::abs(sp) < 1.0 ? u * std::sqrt(1.0 - sp * sp) : 0.0);
      }
      avg *= kMu * p0 / sub;
      EXPECT_NEAR(-map.traction_x[first + static_cast<std::size_t>(e)], avg, kTolCarter * kMu * p0)
          << "a/b " << ratio << " element " << e;
    }
  }
}

// The traction map: element pressures sum to F_n, no element exceeds mu p, adhesion at the
// leading edge at small creepage and slip everywhere at large creepage.
TEST(fastrip_map, bound_and_adhesion_zones) {
  fc::TractionMap map;
  Case k(6e-3, 4e-3, {2e-4, 1e-4, 0.3});
  k.problem.map = &map;
  const fc::TangentialSolution f = solve({}, k.problem);
  ASSERT_EQ(map.x.size(), 144U);
  double load = 0.0;
  for (std::size_t i = 0; i < map.x.size(); ++i) {
    load += map.pressure[i] * map.dx[i] * map.dy[i];
    EXPECT_LE(std::hypot(map.traction_x[i], map.traction_y[i]),
              kMu * map.pressure[i] * (1 + 1e-12));
  }
  EXPECT_NEAR(load, kFn, 1e-9 * kFn);
  EXPECT_GT(f.adhesion_fraction, 0.0);
  EXPECT_LT(f.adhesion_fraction, 1.0);
  EXPECT_EQ(map.slip.front(), 0);  // leading element of the first strip
  Case s(6e-3, 4e-3, {0.1, 0.0, 0.0});
  EXPECT_EQ(solve({}, s.problem).adhesion_fraction, 0.0);
}

// A semi-Hertz patch built as the strips of an ellipse gives the ellipse's forces in the linear
// range (kTolSemiHertz = 1 %: midpoint strips without the y normalisation of the ellipse path).
TEST(fastrip_semi_hertz, strips_of_an_ellipse_match_the_ellipse) {
  constexpr double kTolSemiHertz = 0.01;
  const double a = 6e-3, b = 4e-3;
  Case e(a, b, {1e-4, 5e-5, 0.05});
  fc::ContactPatch semi = e.patch;
  const int n = 200;
  const double p0 = 1.5 * kFn / (std::numbers::pi * a * b);
  for (int j = 0; j < n; ++j) {
    const double y = -b + (j + 0.5) * 2.0 * b / n;
    const double r = std::sqrt(1.0 - (y / b) * (y / b));
    semi.strips.push_back({y, 2.0 * b / n, 0.0, a * r, p0 * r});
  }
  fc::TangentialProblem ps = e.problem;
  ps.patch = &semi;
  const fc::ModelOptions o{{"my", "200"}};
  const fc::TangentialSolution fe = solve(o, e.problem), fs = solve(o, ps);
  const double scale = std::hypot(fe.force_x, fe.force_y);
  EXPECT_NEAR(fs.force_x, fe.force_x, kTolSemiHertz * scale);
  EXPECT_NEAR(fs.force_y, fe.force_y, kTolSemiHertz * scale);
}

// The forces are continuous in the creepages (a vehicle integrator needs it): over a fine sweep of
// xi_x (with xi_y and spin) no step of F_x exceeds kLipschitz = 1.5 times the step of Kalker's
// linear force G a b C11 d(xi_x) (the creep curve is never steeper than its linear slope; a
// jump where the adhesion zone's end crosses an element boundary would be ~30 times that).
TEST(fastrip_continuity, forces_continuous_in_creepage) {
  constexpr double kLipschitz = 1.5;
  const double a = 6e-3, b = 6e-3;
  const fc::KalkerCoefficients c = fc::kalker_coefficients_table(a, b, kNu);
  const auto model = fc::make_tangential_model("fastrip");
  for (const auto& [eta_ratio, phi] :
       {std::pair{0.3, 0.05}, {1.0, 0.2}, {-0.5, 0.3}, {2.0, -0.1}}) {
    Case k(a, b, {0.0, 0.0, phi});
    const int n = 20000;
    const double step = 3e-3 / n;
    const double linear_step = kG * a * b * c.c11 * step;
    double prev = 0.0, largest = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double xi = step * i;
      k.problem.creepage = {xi, eta_ratio * xi, phi};
      const double fx = model->solve(k.problem).force_x;
      if (i > 0) largest = std::max(largest, std::abs(fx - prev));
      prev = fx;
    }
    EXPECT_LE(largest, kLipschitz * linear_step) << eta_ratio << " " << phi;
  }
}

TEST(fastrip_registry, options_and_errors) {
  EXPECT_EQ(fc::make_tangential_model("fastrip")->name(), "fastrip");
  for (const char* v : {"longitudinal", "weighted", "three"}) {
    EXPECT_NO_THROW((void)fc::make_tangential_model("fastrip", {{"slip_flexibility", v}}));
  }
  EXPECT_THROW((void)fc::make_tangential_model("fastrip", {{"slip_flexibility", "x"}}),
               std::invalid_argument);
  EXPECT_THROW((void)fc::make_tangential_model("fastrip", {{"mx", "0"}}), std::invalid_argument);
  EXPECT_THROW((void)fc::make_tangential_model("fastrip", {{"bound", "elliptic"}}),
               std::invalid_argument);
}
