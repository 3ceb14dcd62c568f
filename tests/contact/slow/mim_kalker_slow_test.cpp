// Grid-converged MIM checks (slow): Kalker's creep coefficients over a/b = 0.2..5 and the
// thesis's sphere rolling cases under grid refinement.
#include "ferro/contact/kalker_coefficients.hpp"
#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/contact/mim/normal_solver.hpp"
#include "ferro/contact/mim/tangential_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace ferro::contact;
using namespace ferro::contact::mim;

namespace {

const Material kSteel = Material::from_young(210.0e9, 0.28);

KalkerCoefficients mim_creep_coefficients(double a, double b, int elements) {
  const CombinedMaterial m = combine(kSteel, kSteel);
  const double fn = 1.0e5;
  const HertzGap hg = hertz_gap_for_ellipse(a, b, fn, m.contact_modulus);
  const Grid grid = grid_for_ellipse(a, b, elements, 0.04);
  InfluenceOperator op(grid, m);
  const NormalSolution s =
      solve_normal_force(op, quadratic_gap(grid, hg.curvature_x, hg.curvature_y), fn);
  const double g = m.shear_modulus, c = a * b, tiny = 1.0e-6, mu = 1.0e6;
  KalkerCoefficients k;
  k.c11 = -solve_steady_rolling(op, s.pressure, RollingInput{tiny, 0.0, 0.0, mu}).force_x / (g * c * tiny);
  k.c22 = -solve_steady_rolling(op, s.pressure, RollingInput{0.0, tiny, 0.0, mu}).force_y / (g * c * tiny);
  const double spin = tiny / std::sqrt(c);
  k.c23 = -solve_steady_rolling(op, s.pressure, RollingInput{0.0, 0.0, spin, mu}).force_y /
          (g * std::pow(c, 1.5) * spin);
  return k;
}

}  // namespace

// Kalker's C11, C22, C23 (annex A.2, nu = 0.28 interpolated) for a/b = 0.2 .. 5: full-adhesion
// MIM runs with 48 and 96 elements across the shorter axis, Richardson-extrapolated for the
// first-order difference of eq. (113): C = 2 C(h/2) - C(h). Tolerance 2 % (issue #4; measured
// within 1.2 %, the residual being the staircase boundary of the patch).
class MimKalkerSweep : public ::testing::TestWithParam<double> {};

TEST_P(MimKalkerSweep, kalker_coefficients_grid_converged) {
  constexpr double kTol = 0.02;
  const double ratio = GetParam();
  const double a = ratio <= 1.0 ? 6.0e-3 * ratio : 6.0e-3;
  const double b = ratio <= 1.0 ? 6.0e-3 : 6.0e-3 / ratio;
  const KalkerCoefficients h1 = mim_creep_coefficients(a, b, 48);
  const KalkerCoefficients h2 = mim_creep_coefficients(a, b, 96);
  const KalkerCoefficients ref = kalker_coefficients_table(a, b, 0.28);
  const double c11 = 2.0 * h2.c11 - h1.c11, c22 = 2.0 * h2.c22 - h1.c22, c23 = 2.0 * h2.c23 - h1.c23;
  std::printf("a/b = %.2f  C11 %.4f (table %.4f, %+.2f %%)  C22 %.4f (%.4f, %+.2f %%)  C23 %.4f (%.4f, %+.2f %%)\n",
              ratio, c11, ref.c11, 100.0 * (c11 / ref.c11 - 1.0), c22, ref.c22,
              100.0 * (c22 / ref.c22 - 1.0), c23, ref.c23, 100.0 * (c23 / ref.c23 - 1.0));
  EXPECT_NEAR(c11 / ref.c11, 1.0, kTol);
  EXPECT_NEAR(c22 / ref.c22, 1.0, kTol);
  EXPECT_NEAR(c23 / ref.c23, 1.0, kTol);
}

INSTANTIATE_TEST_SUITE_P(EllipseRatios, MimKalkerSweep, ::testing::Values(0.2, 0.5, 1.0, 2.0, 5.0));

// The thesis's sphere rolling cases (xi_x = 3 per mille, xi_y = 3 mrad, phi = 0.0006 /mm,
// mu = 0.2, delta = 0.4 mm) on dx = 0.5, 0.25, 0.125 mm: the forces must converge (successive
// differences shrinking, first order) and the grid-converged values are printed for the report.
// Tolerance: the Richardson estimate from (0.25, 0.125) within 1 % of the 0.125 mm value.
TEST(MimRollingSlow, thesis_sphere_cases_grid_convergence) {
  const CombinedMaterial m = combine(kSteel, kSteel);
  const double r_rel = 1.0 / (1.0 / 0.300 + 1.0 / 0.460);
  const RollingInput cases[3] = {{3.0e-3, 0.0, 0.0, 0.2}, {0.0, 3.0e-3, 0.0, 0.2}, {0.0, 0.0, 0.6, 0.2}};
  double f[3][3];
  double mufn[3];
  const double dxs[3] = {0.5e-3, 0.25e-3, 0.125e-3};
  for (int k = 0; k < 3; ++k) {
    int n = static_cast<int>(std::round(18.0e-3 / dxs[k]));
    if (n % 2 == 0) ++n;
    const Grid grid = Grid::centred(n, n, dxs[k], dxs[k]);
    InfluenceOperator op(grid, m);
    const Field gap = sample(grid, [&](double x, double y) { return (x * x + y * y) / (2.0 * r_rel); });
    const NormalSolution s = solve_normal_approach(op, gap, 0.4e-3);
    mufn[k] = 0.2 * s.normal_force;
    for (int c = 0; c < 3; ++c) {
      const TangentialSolution t = solve_steady_rolling(op, s.pressure, cases[c]);
      ASSERT_TRUE(t.converged);
      f[c][k] = (c == 0 ? t.force_x : t.force_y) / mufn[k];
    }
  }
  const char* names[3] = {"xi_x = 3 per mille, Fx", "xi_y = 3 mrad, Fy", "phi = 0.0006 /mm, Fy"};
  for (int c = 0; c < 3; ++c) {
    const double richardson = 2.0 * f[c][2] - f[c][1];
    std::printf("%s / mu Fn: dx 0.5 %.5f, 0.25 %.5f, 0.125 %.5f, extrapolated %.5f\n", names[c],
                f[c][0], f[c][1], f[c][2], richardson);
    EXPECT_LT(std::abs(f[c][2] - f[c][1]), std::abs(f[c][1] - f[c][0]) + 1.0e-4);
    EXPECT_NEAR(richardson / f[c][2], 1.0, 0.01);
  }
}
