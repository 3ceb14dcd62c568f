// MIM steady rolling: Kalker's linear theory, saturation, the thesis's sphere cases and creep
// curve (Toumi 2016 section 2.2.4.4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/contact/mim/mim.hpp"
#include "ferro/contact/mim/normal_solver.hpp"
#include "ferro/contact/mim/tangential_solver.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "mim_kalker.hpp"

using namespace ferro::contact;
using namespace ferro::contact::mim;

namespace {

const Material kSteel = Material::from_young(210.0e9, 0.28);
constexpr double kRrel = 1.0 / (1.0 / 0.300 + 1.0 / 0.460);  // spheres 300 / 460 mm

// The thesis's sphere case: dx = dy = 0.5 mm, delta = 0.4 mm.
struct SphereCase {
  CombinedMaterial m = combine(kSteel, kSteel);
  Grid grid = Grid::centred(37, 37, 0.5e-3, 0.5e-3);
  InfluenceOperator op{grid, m};
  NormalGridSolution normal;
  double a = 0.0;
  SphereCase() {
    const Field gap =
        sample(grid, [](double x, double y) { return (x * x + y * y) / (2.0 * kRrel); });
    normal = solve_normal_approach(op, gap, 0.4e-3);
    a = std::cbrt(3.0 * normal.normal_force * kRrel / (4.0 * m.contact_modulus));
  }
};

using ferro::test::mim_creep_coefficients;

}  // namespace

// Circular contact: the initial slopes C11, C22, C23 against Kalker's table (annex A.2, nu =
// 0.28 interpolated), Richardson-extrapolated from 40 and 80 elements across the patch at second
// order (the steady-rolling derivative is the second-order upwind difference, see
// tangential_solver.cpp): C = (4 C(h/2) - C(h)) / 3. Tolerance 2 %. The other ellipse ratios
// are in slow/mim_kalker_slow_test.cpp.
TEST(MimRolling, kalker_linear_theory_circle) {
  constexpr double kTol = 0.02;
  const double r = 6.0e-3;
  const KalkerCoefficients coarse = mim_creep_coefficients(r, r, 40);
  const KalkerCoefficients fine = mim_creep_coefficients(r, r, 80);
  const KalkerCoefficients ref = kalker_coefficients_table(r, r, 0.28);
  const auto extrapolate = [](double c, double f) { return (4.0 * f - c) / 3.0; };
  const double c11 = extrapolate(coarse.c11, fine.c11), c22 = extrapolate(coarse.c22, fine.c22),
               c23 = extrapolate(coarse.c23, fine.c23);
  std::printf(
      "kalker circle (40/80 elements, Richardson): C11 %.4f vs %.4f, C22 %.4f vs %.4f, C23 "
      "%.4f vs %.4f (40: %.4f %.4f %.4f)\n",
      c11, ref.c11, c22, ref.c22, c23, ref.c23, coarse.c11, coarse.c22, coarse.c23);
  EXPECT_NEAR(c11 / ref.c11, 1.0, kTol);
  EXPECT_NEAR(c22 / ref.c22, 1.0, kTol);
  EXPECT_NEAR(c23 / ref.c23, 1.0, kTol);
}

// The thesis's three sphere cases (xi_x = 3 per mille, xi_y = 3 mrad, phi = 0.0006 /mm),
// mu = 0.2. No published numbers (the thesis compares pictures with CONTACT), so the oracles are:
// symmetry (pure xi_x gives F_y = M_z = 0, to 1e-6 mu F_n: solver tolerance 1e-5 on the slip
// velocity), Coulomb, the force below both the linear-theory force and mu F_n, the adhesion area
// towards the leading edge (+x) and the slip area towards the trailing edge, and for the pure
// creepages the Shen-Hedrick-Elkins cubic saturation of Kalker's linear force
// (F/mu F_n = 1 - (1 - xi/3)^3): an approximation of Kalker's exact theory, measured 3.7 % and
// 3.5 % from MIM at dx = 0.5 mm (2.8 % and 2.4 % at 0.25 mm); tolerance 5 %.
TEST(MimRolling, thesis_sphere_cases) {
  constexpr double kCubicLawTol = 0.05;
  SphereCase sc;
  ASSERT_TRUE(sc.normal.converged);
  const double mu = 0.2, fn = sc.normal.normal_force, g = sc.m.shear_modulus, a = sc.a;
  const KalkerCoefficients kc = kalker_coefficients_table(a, a, sc.m.poisson);
  const Grid& grid = sc.grid;
  for (const RollingInput in :
       {RollingInput{3.0e-3, 0.0, 0.0, mu}, RollingInput{0.0, 3.0e-3, 0.0, mu},
        RollingInput{0.0, 0.0, 0.6, mu}}) {
    const TangentialGridSolution t = solve_steady_rolling(sc.op, sc.normal.pressure, in);
    ASSERT_TRUE(t.converged);
    EXPECT_LE(t.coulomb_residual, 1.0e-5);
    const double lin_x = -g * a * a * kc.c11 * in.creepage_x;
    const double lin_y = -g * a * a * kc.c22 * in.creepage_y - g * a * a * a * kc.c23 * in.spin;
    const double lin = std::hypot(lin_x, lin_y);
    const double ft = std::hypot(t.force_x, t.force_y);
    EXPECT_LT(ft, lin);
    EXPECT_LT(ft, mu * fn);
    double x_stick = 0.0, x_slip = 0.0;  // centroids of the adhesion and slip areas
    for (int iy = 0; iy < grid.ny; ++iy)
      for (int ix = 0; ix < grid.nx; ++ix) {
        const ElementState st = t.state[grid.index(ix, iy)];
        if (st == ElementState::stick) x_stick += grid.x(ix) / t.stick_elements;
        if (st == ElementState::slip) x_slip += grid.x(ix) / t.slip_elements;
      }
    EXPECT_GT(x_stick, 0.1 * a);
    EXPECT_LT(x_slip, -0.1 * a);
    if (in.creepage_x != 0.0) {
      EXPECT_LT(t.force_x, 0.0);
      EXPECT_NEAR(t.force_y, 0.0, 1.0e-6 * mu * fn);
      EXPECT_NEAR(t.moment_z, 0.0, 1.0e-6 * mu * fn * a);
    } else if (in.creepage_y != 0.0) {
      EXPECT_LT(t.force_y, 0.0);
      EXPECT_GT(t.moment_z, 0.0);  // sign of G (ab)^1.5 C23 xi_y, eq. (40)
    } else {
      EXPECT_LT(t.force_y, 0.0);   // sign of -G (ab)^1.5 C23 phi, eq. (39)
      EXPECT_LT(t.moment_z, 0.0);  // sign of -G (ab)^2 C33 phi, eq. (40)
    }
    std::printf(
        "thesis case xi_x %g xi_y %g phi %g /m: Fx/muFn %.5f Fy/muFn %.5f Mz %.5g N m; "
        "stick %d slip %d; linear |F|/muFn %.4f\n",
        in.creepage_x, in.creepage_y, in.spin, t.force_x / (mu * fn), t.force_y / (mu * fn),
        t.moment_z, t.stick_elements, t.slip_elements, lin / (mu * fn));
    if (in.spin == 0.0) {
      const double xi = lin / (mu * fn);
      const double cubic = 1.0 - std::pow(1.0 - xi / 3.0, 3);
      EXPECT_NEAR(ft / (mu * fn) / cubic, 1.0, kCubicLawTol);
    }
  }
}

// The thesis's 25-point creep curve, xi_x in [-20, 20] per mille (figure 2.13): odd in xi_x,
// monotone, initial slope C11 (within 5 %: dx = 0.5 mm is not grid-converged, +2.7 % measured),
// saturation at mu F_n at +-20 per mille (full slip; within 0.1 %: the elastic part -du/dx of
// the slip still turns the local directions slightly, measured 0.02 %).
TEST(MimRolling, thesis_creep_curve_25_points) {
  SphereCase sc;
  const double mu = 0.2, fn = sc.normal.normal_force;
  std::vector<double> fx;
  for (int k = 0; k < 25; ++k) {
    const double xi = -20.0e-3 + k * (40.0e-3 / 24.0);
    const TangentialGridSolution t =
        solve_steady_rolling(sc.op, sc.normal.pressure, RollingInput{xi, 0.0, 0.0, mu});
    ASSERT_TRUE(t.converged) << xi;
    EXPECT_LE(std::abs(t.force_x), mu * fn * (1.0 + 1.0e-9));
    fx.push_back(t.force_x);
  }
  for (int k = 0; k < 25; ++k) {
    std::printf("creep curve xi_x %+.4f per mille: Fx/muFn %+.5f\n", (-20.0 + k * 40.0 / 24.0),
                fx[k] / (mu * fn));
  }
  for (int k = 0; k < 25; ++k) EXPECT_NEAR(fx[k], -fx[24 - k], 1.0e-6 * mu * fn);
  for (int k = 1; k < 25; ++k) EXPECT_LE(fx[k], fx[k - 1] + 1.0e-6 * mu * fn);
  EXPECT_NEAR(fx[0], mu * fn, 1.0e-3 * mu * fn);
  EXPECT_NEAR(fx[24], -mu * fn, 1.0e-3 * mu * fn);
  const double tiny = 1.0e-7;
  const TangentialGridSolution lin =
      solve_steady_rolling(sc.op, sc.normal.pressure, RollingInput{tiny, 0.0, 0.0, mu});
  const double c11 = -lin.force_x / (sc.m.shear_modulus * sc.a * sc.a * tiny);
  EXPECT_NEAR(c11 / kalker_coefficients_table(1.0, 1.0, 0.28).c11, 1.0, 0.05);
}

// Combined creepage and spin beyond saturation: |F| = mu F_n and, without spin, F opposite to
// the creepage vector (full sliding). Tolerances 0.1 % and 0.5 deg: in full slip the elastic
// part -du/dx of the slip velocity still turns the local directions slightly (measured 0.003 %
// and 0.12 deg).
TEST(MimRolling, saturation_combined) {
  SphereCase sc;
  const double mu = 0.2, fn = sc.normal.normal_force;
  const TangentialGridSolution t =
      solve_steady_rolling(sc.op, sc.normal.pressure, RollingInput{0.03, 0.04, 0.0, mu});
  ASSERT_TRUE(t.converged);
  EXPECT_EQ(t.stick_elements, 0);
  EXPECT_NEAR(std::hypot(t.force_x, t.force_y), mu * fn, 1.0e-3 * mu * fn);
  EXPECT_NEAR(std::atan2(-t.force_y, -t.force_x), std::atan2(0.04, 0.03), 0.5 * 3.14159265 / 180.0);
  const TangentialGridSolution ts =
      solve_steady_rolling(sc.op, sc.normal.pressure, RollingInput{0.02, 0.01, 3.0, mu});
  ASSERT_TRUE(ts.converged);
  EXPECT_LT(std::hypot(ts.force_x, ts.force_y), mu * fn);  // spin diverts part of the traction
  EXPECT_GT(std::hypot(ts.force_x, ts.force_y), 0.5 * mu * fn);
  EXPECT_LE(ts.coulomb_residual, 1.0e-5);
}

// Robustness over the envelope a tangential-model benchmark spans: ellipse ratios 0.2..5,
// creepage levels from micro-slip (0.1 mu F_n of linear force) to full slip (3x), pure
// longitudinal, lateral, spin and a combination. Every case must converge, obey Coulomb
// (|tau| <= mu p_n to 1e-9 mu max p_n) and give |F| <= mu F_n; reversing all creepages must
// reverse the forces (tau -> -tau symmetry of eqs. 116-120), to 1e-5 mu F_n (solver tolerance).
TEST(MimRolling, robustness_envelope) {
  const Material steel = Material::from_young(210.0e9, 0.28);
  const CombinedMaterial m = combine(steel, steel);
  const double fn = 80.0e3, mu = 0.3;
  int cases = 0;
  for (double ratio : {0.2, 0.5, 1.0, 2.0, 5.0}) {
    const double b = ratio <= 1.0 ? 5.0e-3 : 5.0e-3 / ratio;
    const double a = ratio <= 1.0 ? 5.0e-3 * ratio : 5.0e-3;
    const KalkerCoefficients kc = kalker_coefficients_table(a, b, 0.28);
    const double g = m.shear_modulus, c = a * b;
    const HertzGap hg = hertz_gap_for_ellipse(a, b, fn, m.contact_modulus);
    const Grid grid = grid_for_ellipse(a, b, 24);
    InfluenceOperator op(grid, m);
    const NormalGridSolution s =
        solve_normal_force(op, quadratic_gap(grid, hg.curvature_x, hg.curvature_y), fn);
    ASSERT_TRUE(s.converged);
    for (double level : {0.1, 0.5, 1.0, 3.0}) {
      const double xs = level * mu * fn / (g * c * kc.c11);
      const double ys = level * mu * fn / (g * c * kc.c22);
      const double ps = level * mu * fn / (g * std::pow(c, 1.5) * kc.c23);
      for (const RollingInput in :
           {RollingInput{xs, 0.0, 0.0, mu}, RollingInput{0.0, ys, 0.0, mu},
            RollingInput{0.0, 0.0, ps, mu}, RollingInput{0.6 * xs, -0.6 * ys, 0.5 * ps, mu}}) {
        const TangentialGridSolution t = solve_steady_rolling(op, s.pressure, in);
        ++cases;
        ASSERT_TRUE(t.converged) << "a/b " << ratio << " level " << level;
        EXPECT_LE(t.coulomb_residual, 1.0e-9);
        EXPECT_LE(std::hypot(t.force_x, t.force_y), mu * fn * (1.0 + 1.0e-9));
        if (level == 0.5) {
          const TangentialGridSolution r = solve_steady_rolling(
              op, s.pressure, RollingInput{-in.creepage_x, -in.creepage_y, -in.spin, mu});
          ASSERT_TRUE(r.converged);
          EXPECT_NEAR(r.force_x, -t.force_x, 1.0e-5 * mu * fn);
          EXPECT_NEAR(r.force_y, -t.force_y, 1.0e-5 * mu * fn);
        }
      }
    }
  }
  EXPECT_EQ(cases, 80);
}

// The preconditioner changes the path, not the solution: spin + creepage on the sphere case with
// and without the FFT preconditioner, and with the nested coarse-grid start, agree to the
// solver tolerance (1e-5 of the rigid slip -> forces within 1e-5 mu F_n).
TEST(MimRolling, solver_options_same_solution) {
  SphereCase sc;
  const double mu = 0.2, fn = sc.normal.normal_force;
  const RollingInput in{2.0e-3, -1.0e-3, 0.4, mu};
  TangentialSolverOptions fft;
  fft.fft_preconditioner_min_elements = 0;
  const TangentialGridSolution ref = solve_steady_rolling(sc.op, sc.normal.pressure, in, fft);
  TangentialSolverOptions plain;
  plain.fft_preconditioner_min_elements = std::numeric_limits<int>::max();
  TangentialSolverOptions nested;
  nested.nested = true;
  for (const TangentialSolverOptions& o : {plain, nested}) {
    const TangentialGridSolution t = solve_steady_rolling(sc.op, sc.normal.pressure, in, o);
    ASSERT_TRUE(ref.converged && t.converged);
    EXPECT_NEAR(t.force_x, ref.force_x, 1.0e-5 * mu * fn);
    EXPECT_NEAR(t.force_y, ref.force_y, 1.0e-5 * mu * fn);
    EXPECT_EQ(t.slip_elements, ref.slip_elements);
  }
}

// Non-Hertzian, two-lobe patch on the thesis's S1002/UIC60 grid (46 x 100, dx = 0.223 mm,
// F_n = 54.53 kN, mu = 0.36, xi_x = -0.161 per mille, phi = 5.227e-5 /mm), with a synthetic
// two-minimum lateral gap standing in for the profiles (the real profile gap belongs to the
// geometry work): the full normal + rolling chain must converge, obey Coulomb and
// |F| <= mu F_n, give two separate pressure lobes, and reverse its forces when every creepage
// is reversed (to 1e-5 mu F_n, the solver tolerance).
TEST(MimRolling, two_lobe_gap) {
  const CombinedMaterial m = combine(kSteel, kSteel);
  const Grid grid = Grid::centred(46, 100, 0.223e-3, 0.223e-3);
  InfluenceOperator op(grid, m);
  const Field gap = sample(grid, [](double x, double y) {
    const double ymm = y * 1.0e3;
    const double f_mm =
        std::min(0.002 * (ymm - 3.0) * (ymm - 3.0), 0.003 * (ymm + 6.0) * (ymm + 6.0) + 0.004);
    return x * x / (2.0 * 0.46) + f_mm * 1.0e-3;
  });
  NormalLoad load;
  load.normal_force = 54530.0;
  const double mu = 0.36, mufn = mu * 54530.0;
  const RollingInput in{-0.161e-3, 0.0, 0.05227, mu};
  const MimResult r = solve_rolling_contact(op, gap, load, in);
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.coulomb_residual, 1.0e-9);
  EXPECT_LE(std::hypot(r.force_x, r.force_y), mufn);
  // two lobes: along the centre column x = 0 the pressure has two separate runs
  int runs = 0;
  bool inside = false;
  const int ix = grid.nx / 2;
  for (int iy = 0; iy < grid.ny; ++iy) {
    const bool p = r.pressure[grid.index(ix, iy)] > 0.0;
    if (p && !inside) ++runs;
    inside = p;
  }
  EXPECT_EQ(runs, 2);
  const MimResult rev =
      solve_rolling_contact(op, gap, load, RollingInput{-in.creepage_x, 0.0, -in.spin, mu});
  ASSERT_TRUE(rev.converged);
  EXPECT_NEAR(rev.force_x, -r.force_x, 1.0e-5 * mufn);
  EXPECT_NEAR(rev.force_y, -r.force_y, 1.0e-5 * mufn);
  EXPECT_NEAR(rev.moment_z, -r.moment_z, 1.0e-5 * mufn * 1.0e-2);
}
