// Half-space limit of the finite-element influence coefficients: a large clamped block loaded on
// its top face reproduces the Boussinesq-Cerruti coefficients of annex B.3 near the load, and the
// K_ij of the dense FE operator against the half-space on the same grid are close to 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ferro/contact/mim/dense_operator.hpp"
#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/contact/mim/influence.hpp"
#include "ferro/contact/mim/influence_operator.hpp"
#include "ferro/fe_contact/creep_slopes.hpp"
#include "ferro/fe_contact/fe_block.hpp"

using namespace ferro;
using namespace ferro::contact::mim;

namespace {

const contact::Material kSteel = contact::Material::from_young(210.0e9, 0.28);

// Triquadratic hexahedra (Lagrange degree 2), one per grid element along the loaded column and
// its neighbours, with node lines 0.15 grid element either side of the loaded element's edges
// and at depths 0.15 and 0.375 grid element (the strain of a uniform load is singular along the
// load's edges), sizes growing by 2.5 outwards to a block 50 x the loaded area's half-size with
// a clamped bottom; traction integrated over the loaded element, displacement interpolated at
// the element centres (annex B.3 gives centre values of uniformly loaded rectangles).
// Measured against annex B.3: self within 0.2 %, nearest neighbours within 1.1 %, diagonal
// neighbour within 1.7 % (zz; the clamped bottom lowers zz with the distance), i.e. the 2 %
// asked of the half-space limit. Second neighbours sit in the first grown elements (2.5 grid
// elements long): measured within 4.6 %, bound 5 %.
constexpr double kNearTolerance = 0.02;
constexpr double kSecondNeighbourTolerance = 0.05;

TEST(FeBlock, boussinesq_cerruti_near_the_load) {
  fe_contact::FeBlockSpec s;
  s.grid = Grid::centred(3, 3, 1.0e-3, 1.0e-3);
  s.material = kSteel;
  s.mesh.degree = 2;
  s.mesh.subdivisions = 1;
  s.mesh.growth = 2.5;
  s.mesh.near_columns = 1;
  s.extent = 50.0;
  s.edge_refinement = 0.15;
  const fe_contact::FeInfluence fe = fe_contact::block_influence(s);
  const ColumnInfluence pair = fe_contact::pair_of_identical(fe.single_body);
  const contact::CombinedMaterial m = contact::combine(kSteel, kSteel);
  std::printf("FE block: %ld elements, %ld dofs, %.1f s CPU\n", fe.elements, fe.dofs,
              fe.cpu_seconds);
  const int is = 1;  // middle row
  for (int ox = 0; ox <= 2; ++ox)
    for (int oy = 0; oy <= 1; ++oy) {
      const InfluenceCoefficients hs =
          influence_coefficients(ox * 1.0e-3, oy * 1.0e-3, 1.0e-3, 1.0e-3, m);
      const std::size_t k = pair.index(ox, is + oy, is);
      const double tol = ox <= 1 ? kNearTolerance : kSecondNeighbourTolerance;
      std::printf("offset (%d, %d): zz %.4f xx %.4f yy %.4f of annex B.3\n", ox, oy,
                  pair.zz[k] / hs.zz, pair.xx[k] / hs.xx, pair.yy[k] / hs.yy);
      EXPECT_NEAR(pair.zz[k] / hs.zz, 1.0, tol) << ox << ", " << oy;
      EXPECT_NEAR(pair.xx[k] / hs.xx, 1.0, tol) << ox << ", " << oy;
      EXPECT_NEAR(pair.yy[k] / hs.yy, 1.0, tol) << ox << ", " << oy;
    }
}

// K_ij: a uniform far-field offset cancels in the rolling difference and the near-field errors
// of opposite sign largely cancel over the patch; bound: the 2 % asked of the half-space limit
// (measured K11 = 1.017, K22 = 1.008 with this trilinear mesh).
constexpr double kKTolerance = 0.02;

TEST(FeBlock, reduction_factors_near_one) {
  // Hertzian patch a = b = 4 mm on a 1 mm grid (10 x 10 elements).
  const contact::CombinedMaterial m = contact::combine(kSteel, kSteel);
  const double a = 4.0e-3, fn = 20.0e3;
  const Grid grid = grid_for_ellipse(a, a, 10, 0.2);
  const HertzGap g = hertz_gap_for_ellipse(a, a, fn, m.contact_modulus);
  const Field gap = quadratic_gap(grid, g.curvature_x, g.curvature_y);
  fe_contact::FeBlockSpec s;
  s.grid = grid;
  s.material = kSteel;
  // Trilinear hexahedra, two per grid element side over the whole loaded area, block 20 x the
  // loaded area's half-size.
  s.mesh.degree = 1;
  s.mesh.subdivisions = 2;
  s.mesh.growth = 1.4;
  s.mesh.near_columns = grid.nx;
  s.extent = 20.0;
  const fe_contact::FeInfluence fe = fe_contact::block_influence(s);
  DenseInfluenceOperator dense(grid, fe_contact::pair_of_identical(fe.single_body), m);
  InfluenceOperator half_space(grid, m);
  fe_contact::SlopeCase c;
  c.normal_force = fn;
  c.friction = 0.3;
  c.semi_axis_x = a;
  const fe_contact::SlopeResult r = fe_contact::reduction_factors(dense, half_space, gap, c);
  std::printf("FE block %ld elements %.1f s CPU: K11 %.4f K22 %.4f K23 %.4f K33 %.4f\n",
              fe.elements, fe.cpu_seconds, r.k.k11, r.k.k22, r.k.k23, r.k.k33);
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.k.k11, 1.0, kKTolerance);
  EXPECT_NEAR(r.k.k22, 1.0, kKTolerance);
}

}  // namespace
