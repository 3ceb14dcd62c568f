// MIM sliding (shift) problem against Cattaneo-Mindlin, Toumi (2016) section 2.2.3.4.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "ferro/contact/mim/normal_solver.hpp"
#include "ferro/contact/mim/tangential_solver.hpp"

using namespace ferro::contact;
using namespace ferro::contact::mim;

// Spheres R1 = 300 mm, R2 = 460 mm, steel, dx = dy = 0.5 mm, delta = 0.4 mm, mu = 0.2, rigid
// shift delta_x from 0 to 0.09 mm. Reference: eq. (110),
//   F_t = mu F_n - mu F_n (1 - 16 a G delta_t / (6 (2 - nu) mu F_n))^(3/2),
// and the stick radius c = a (1 - F_t / mu F_n)^(1/3) (Johnson 1985, eq. 7.43).
// Tolerances: F_t within 2 % (first-order discretisation); stick radius within one element (dx), measured as the
// radius of the circle with the area of the stick elements.
TEST(MimSliding, cattaneo_mindlin) {
  constexpr double kForceTol = 0.02;
  const Material steel = Material::from_young(210.0e9, 0.28);
  const CombinedMaterial m = combine(steel, steel);
  const double r_rel = 1.0 / (1.0 / 0.300 + 1.0 / 0.460);
  const double dx = 0.5e-3;
  const Grid grid = Grid::centred(37, 37, dx, dx);
  InfluenceOperator op(grid, m);
  const Field gap =
      sample(grid, [&](double x, double y) { return (x * x + y * y) / (2.0 * r_rel); });
  const NormalGridSolution normal = solve_normal_approach(op, gap, 0.4e-3);
  ASSERT_TRUE(normal.converged);
  const double fn = normal.normal_force;
  const double a = std::cbrt(3.0 * fn * r_rel / (4.0 * m.contact_modulus));
  const double mu = 0.2;

  TangentialWorkspace workspace;  // one Krylov basis for every shift
  for (double shift : {0.01e-3, 0.03e-3, 0.05e-3, 0.07e-3, 0.09e-3}) {
    const TangentialGridSolution t =
        solve_sliding(op, normal.pressure, SlidingInput{shift, 0.0, mu}, {}, workspace);
    ASSERT_TRUE(t.converged) << shift;
    EXPECT_LE(t.coulomb_residual, 1.0e-9);
    const double base =
        1.0 - 16.0 * a * m.shear_modulus * shift / (6.0 * (2.0 - m.poisson) * mu * fn);
    ASSERT_GT(base, 0.0);
    const double ft = mu * fn * (1.0 - std::pow(base, 1.5));
    EXPECT_NEAR(t.force_x / ft, 1.0, kForceTol) << "delta_x = " << shift;
    EXPECT_NEAR(t.force_y, 0.0, 1.0e-5 * mu * fn);  // symmetry, to the solver tolerance 1e-5
    const double c = a * std::sqrt(base);
    const double c_num = std::sqrt(t.stick_elements * dx * dx / std::numbers::pi);
    EXPECT_NEAR(c_num, c, dx) << "delta_x = " << shift;
    std::printf(
        "cattaneo_mindlin delta_x %.3f mm: F_t %.6g N vs eq. 110 %.6g N (%+.4f %%); stick "
        "radius %.4f mm vs %.4f mm\n",
        shift * 1e3, t.force_x, ft, 100.0 * (t.force_x / ft - 1.0), c_num * 1e3, c * 1e3);
  }
}

// An oblique shift must give the same |F_t| law (isotropy of the half-space) and a force
// parallel to the shift. Tolerances: 2 % on |F_t| (as above), 0.5 deg on the direction (the
// nu x-y coupling of eq. 62 only bends it by a small amount in the slip ring).
TEST(MimSliding, cattaneo_mindlin_oblique) {
  const Material steel = Material::from_young(210.0e9, 0.28);
  const CombinedMaterial m = combine(steel, steel);
  const double r_rel = 1.0 / (1.0 / 0.300 + 1.0 / 0.460);
  const Grid grid = Grid::centred(37, 37, 0.5e-3, 0.5e-3);
  InfluenceOperator op(grid, m);
  const Field gap =
      sample(grid, [&](double x, double y) { return (x * x + y * y) / (2.0 * r_rel); });
  const NormalGridSolution normal = solve_normal_approach(op, gap, 0.4e-3);
  const double fn = normal.normal_force;
  const double a = std::cbrt(3.0 * fn * r_rel / (4.0 * m.contact_modulus));
  const double mu = 0.2;
  TangentialWorkspace workspace;
  const TangentialGridSolution t =
      solve_sliding(op, normal.pressure, SlidingInput{0.03e-3, 0.04e-3, mu}, {}, workspace);
  ASSERT_TRUE(t.converged);
  const double base =
      1.0 - 16.0 * a * m.shear_modulus * 0.05e-3 / (6.0 * (2.0 - m.poisson) * mu * fn);
  const double ft = mu * fn * (1.0 - std::pow(base, 1.5));
  EXPECT_NEAR(std::hypot(t.force_x, t.force_y) / ft, 1.0, 0.02);
  const double angle = std::atan2(t.force_y, t.force_x) - std::atan2(0.04, 0.03);
  EXPECT_LT(std::abs(angle) * 180.0 / std::numbers::pi, 0.5);
}
