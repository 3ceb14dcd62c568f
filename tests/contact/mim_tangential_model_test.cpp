// The MIM solver behind the tangential-model interface ("mim"): linear limit against Kalker's
// table, Coulomb saturation, agreement with FASTSIM, and the full-gap (semi-Hertz) path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ferro/contact/normal/normal_model.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/contact/tangential/mim_model.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"

namespace fc = ferro::contact;

namespace {

const fc::Material kSteel = fc::Material::from_young(210.0e9, 0.28);

fc::TangentialProblem problem(const fc::ContactPatch& patch, fc::Creepage c, double mu) {
  fc::TangentialProblem p;
  p.patch = &patch;
  p.creepage = c;
  p.friction = mu;
  p.body1 = kSteel;
  p.body2 = kSteel;
  return p;
}

}  // namespace

// Kalker's linear theory (Toumi eqs. 38-40, annex A.2 at nu = 0.28): at a micro-creepage the
// model must give C11, C22, C23 and the signs of kalker_linear. Tolerance 4 %: at 30 elements
// across the short axis the MIM's first-order discretisation error is +1 ... +3 % (-0.4 %
// only after Richardson extrapolation from 40/80 elements).
TEST(mim_tangential_model, kalker_linear_limit) {
  constexpr double kTolSlope = 0.04;
  const auto mim = fc::make_tangential_model("mim", {{"elements", "30"}});
  const auto linear = fc::make_tangential_model("kalker_linear");
  EXPECT_EQ(mim->name(), "mim");
  for (double ratio : {1.0, 0.5, 2.0}) {
    const double b = 4.0e-3, a = ratio * b;
    const fc::ContactPatch patch = fc::elliptic_patch(a, b, 60.0e3);
    const double spin = 1.0e-6 / std::sqrt(a * b);
    for (fc::Creepage c : {fc::Creepage{1e-6, 0, 0}, fc::Creepage{0, 1e-6, 0},
                           fc::Creepage{0, 0, spin}}) {
      const fc::TangentialSolution m = mim->solve(problem(patch, c, 0.3));
      const fc::TangentialSolution l = linear->solve(problem(patch, c, 0.3));
      const double fm = c.longitudinal != 0.0 ? m.force_x : m.force_y;
      const double fl = c.longitudinal != 0.0 ? l.force_x : l.force_y;
      std::printf("a/b %.1f creepage (%g, %g, %g): mim %.6g N, kalker %.6g N, ratio %.4f\n", ratio,
                  c.longitudinal, c.lateral, c.spin, fm, fl, fm / fl);
      EXPECT_NEAR(fm / fl, 1.0, kTolSlope) << "a/b " << ratio;
      EXPECT_GT(m.adhesion_fraction, 0.95);  // micro-creepage: (almost) all adhesion
    }
  }
}

// Coulomb: beyond saturation |F_t| = mu F_n, opposite to the rigid slip (force on the wheel).
// Tolerance 0.5 %: a few elements at the leading edge may still stick (measured 0.02 %
// at 20 per mille on the sphere case).
TEST(mim_tangential_model, saturation_at_mu_fn) {
  constexpr double kTolCoulomb = 0.005;
  const auto mim = fc::make_tangential_model("mim", {{"elements", "24"}});
  const fc::ContactPatch patch = fc::elliptic_patch(6.0e-3, 4.0e-3, 80.0e3);
  const double mu = 0.3;
  for (fc::Creepage c : {fc::Creepage{0.03, 0, 0}, fc::Creepage{0, -0.03, 0},
                         fc::Creepage{0.02, 0.025, 0}}) {
    const fc::TangentialSolution s = mim->solve(problem(patch, c, mu));
    const double ft = std::hypot(s.force_x, s.force_y);
    EXPECT_NEAR(ft / (mu * patch.normal_force), 1.0, kTolCoulomb);
    const double cos_angle = -(s.force_x * c.longitudinal + s.force_y * c.lateral) /
                             (ft * std::hypot(c.longitudinal, c.lateral));
    EXPECT_GT(cos_angle, std::cos(1.0 * M_PI / 180.0));
  }
}

// FASTSIM (Kalker's simplified theory, fine 100 x 100 grid) against the exact theory: for pure
// creepage Kalker (1990, "Three-dimensional elastic bodies in rolling contact", ch. 5) and
// Vollebregt & Wilders (2011, "FASTSIM2") report creep-force errors of up to ~10 % of mu F_n
// in the transition region. Tolerance kTolFastsim = 0.10 mu F_n at every point of pure
// longitudinal and lateral creep curves from micro-slip to full slip.
TEST(mim_tangential_model, fastsim_within_published_error) {
  constexpr double kTolFastsim = 0.10;
  const auto mim = fc::make_tangential_model("mim", {{"elements", "30"}});
  const auto fastsim = fc::make_tangential_model("fastsim", {{"mx", "100"}, {"my", "100"}});
  const fc::ContactPatch patch = fc::elliptic_patch(6.0e-3, 4.5e-3, 70.0e3);
  const double mu = 0.3;
  const double g = fc::combine(kSteel, kSteel).shear_modulus;
  const double c11 = fc::kalker_coefficients_table(6.0e-3, 4.5e-3, 0.28).c11;
  const double xi_sat = mu * patch.normal_force / (g * 6.0e-3 * 4.5e-3 * c11);  // linear = mu Fn
  double worst = 0.0;
  for (double t : {0.1, 0.3, 0.6, 1.0, 1.5, 2.5, 4.0}) {
    for (int dir = 0; dir < 2; ++dir) {
      const fc::Creepage c = dir == 0 ? fc::Creepage{t * xi_sat, 0, 0}
                                      : fc::Creepage{0, t * xi_sat, 0};
      const fc::TangentialSolution m = mim->solve(problem(patch, c, mu));
      const fc::TangentialSolution f = fastsim->solve(problem(patch, c, mu));
      const double err = (dir == 0 ? m.force_x - f.force_x : m.force_y - f.force_y) /
                         (mu * patch.normal_force);
      std::printf("xi/xi_sat %.1f %s: mim %.4f, fastsim %.4f mu Fn, diff %+.4f\n", t,
                  dir == 0 ? "x" : "y",
                  (dir == 0 ? m.force_x : m.force_y) / (mu * patch.normal_force),
                  (dir == 0 ? f.force_x : f.force_y) / (mu * patch.normal_force), err);
      worst = std::max(worst, std::abs(err));
    }
  }
  EXPECT_LT(worst, kTolFastsim);
  EXPECT_GT(worst, 1e-3);  // the two theories do differ (not the same code path)
}

// Full-gap path: a semi-Hertz patch from the quadratic lateral gap B y^2 (sampled) must give
// the forces of the elliptic (Hertzian) path, since the gap is the same. Tolerance 3 % of the
// force: different grids (strip extent vs ellipse) and staircase boundaries at 30 elements.
TEST(mim_tangential_model, full_gap_matches_hertz_path) {
  constexpr double kTolPaths = 0.03;
  fc::NormalProblem gap;
  gap.body1 = gap.body2 = kSteel;
  gap.curvature_x = 1.0 / (2.0 * 0.46);
  gap.curvature_y = 1.0 / 0.6;
  gap.normal_force = 70.0e3;
  for (int i = 0; i <= 600; ++i) {
    const double y = -0.03 + 0.06 * i / 600.0;
    gap.gap_y.push_back(y);
    gap.gap_z.push_back(gap.curvature_y * y * y + 1e-4);
  }
  const fc::NormalSolution hertz = fc::make_normal_model("hertz")->solve(gap);
  const fc::NormalSolution semi = fc::make_normal_model("semi_hertz")->solve(gap);
  ASSERT_EQ(semi.patches.size(), 1u);
  const auto mim = fc::make_tangential_model("mim", {{"elements", "30"}});
  for (fc::Creepage c : {fc::Creepage{1.0e-3, 0, 0}, fc::Creepage{0, 1.0e-3, 0}}) {
    fc::TangentialProblem ph = problem(hertz.patches[0], c, 0.3);
    fc::TangentialProblem ps = problem(semi.patches[0], c, 0.3);
    ps.gap = &gap;
    fc::TractionMap map;
    ps.map = &map;
    const fc::TangentialSolution h = mim->solve(ph);
    const fc::TangentialSolution s = mim->solve(ps);
    const double fh = std::hypot(h.force_x, h.force_y), fs = std::hypot(s.force_x, s.force_y);
    std::printf("creepage (%g, %g): hertz path %.6g N, full gap %.6g N\n", c.longitudinal,
                c.lateral, fh, fs);
    EXPECT_NEAR(fs / fh, 1.0, kTolPaths);
    ASSERT_FALSE(map.pressure.empty());
    double load = 0.0;
    for (std::size_t k = 0; k < map.pressure.size(); ++k) load += map.pressure[k] * map.dx[k] * map.dy[k];
    EXPECT_NEAR(load / gap.normal_force, 1.0, 1e-6);
  }
}

TEST(mim_tangential_model, options_are_checked) {
  EXPECT_THROW((void)fc::make_tangential_model("mim", {{"elements", "2"}}), std::invalid_argument);
  EXPECT_THROW((void)fc::make_tangential_model("mim", {{"mx", "20"}}), std::invalid_argument);
  const auto mim = fc::make_tangential_model("mim");
  const fc::ContactPatch patch = fc::elliptic_patch(6.0e-3, 4.0e-3, 80.0e3);
  fc::TangentialProblem p = problem(patch, {1e-3, 0, 0}, 0.3);
  p.reduction = fc::ReductionFactors::uniform(0.5);
  EXPECT_THROW((void)mim->solve(p), std::invalid_argument);
}
