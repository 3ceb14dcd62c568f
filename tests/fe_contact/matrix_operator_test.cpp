// The full-matrix compliance operator (no translation invariance) against the FFT half-space
// operator: filled with the annex B.3 coefficients it must give the same products and creep
// forces up to round-off; a local tangential compliance added on its diagonal must give the
// interfacial-layer operator's K_ij (the layer is validated against its closed form).
#include <gtest/gtest.h>

#include "operator_products.hpp"

#include <cmath>
#include <random>

#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/contact/mim/influence_operator.hpp"
#include "ferro/contact/mim/mim.hpp"
#include "ferro/fe_contact/creep_slopes.hpp"
#include "ferro/fe_contact/matrix_operator.hpp"

using namespace ferro;
using namespace ferro::contact;
using namespace ferro::contact::mim;
using ferro::fe_contact::MatrixComplianceOperator;
using ferro::fe_contact::SurfaceCompliance;

namespace {

const Material kSteel = Material::from_young(210.0e9, 0.28);
// Products: direct sums against zero-padded FFT convolution; FFT round-off ~ log(n) eps of the
// largest kernel entry.
constexpr double kProductTolerance = 1.0e-11;
// K_ij: both runs converge to the tangential solver's tolerance (1e-5 of the rigid slip) with
// different preconditioners, so the slopes agree to about that.
constexpr double kKTolerance = 1.0e-4;


TEST(MatrixComplianceOperator, products_equal_fft_half_space) {
  const Grid grid = Grid::centred(12, 8, 0.4e-3, 0.3e-3);
  const CombinedMaterial m = combine(kSteel, kSteel);
  InfluenceOperator fft(grid, m);
  MatrixComplianceOperator full(SurfaceCompliance::half_space(grid, m), m);
  ferro::test::expect_products_equal(fft, full, 11, kProductTolerance, 1.0e-12);
}

TEST(MatrixComplianceOperator, layer_on_the_diagonal_gives_the_layer_operator_k) {
  // Thesis case (Toumi 2016 Tables 3.1, 3.7): 7.5 t, a = 6.66 mm, b = 5.05 mm, mu = 0.2; a layer
  // h / G3 = 5e-14 m/Pa (h = 41 um, G3 = 820 MPa) on a 14 x 10 grid.
  const CombinedMaterial m = combine(kSteel, kSteel);
  const double a = 6.66e-3, b = 5.05e-3, fn = 73575.0, layer = 5.0e-14;
  const Grid grid = Grid::centred(14, 10, 1.2625e-3, 1.2625e-3);
  const HertzGap g = hertz_gap_for_ellipse(a, b, fn, m.contact_modulus);
  const Field gap = quadratic_gap(grid, g.curvature_x, g.curvature_y);
  InfluenceOperator half_space(grid, m);
  InfluenceOperator layered(grid, m, layer);
  SurfaceCompliance c = SurfaceCompliance::half_space(grid, m);
  SurfaceCompliance diag = SurfaceCompliance::zeros(grid);
  for (int iy = 0; iy < grid.ny; ++iy)
    for (int ix = 0; ix < grid.nx; ++ix) {
      const std::size_t k = diag.index(ix, iy, grid.index(ix, iy));
      diag.xx[k] = layer;
      diag.yy[k] = layer;
    }
  c.add_tangential(diag);
  MatrixComplianceOperator full(std::move(c), m);
  fe_contact::SlopeCase sc;
  sc.normal_force = fn;
  sc.friction = 0.2;
  sc.semi_axis_x = a;
  const fe_contact::SlopeResult ref = fe_contact::reduction_factors(layered, half_space, gap, sc);
  const fe_contact::SlopeResult ours = fe_contact::reduction_factors(full, half_space, gap, sc);
  ASSERT_TRUE(ref.converged);
  ASSERT_TRUE(ours.converged);
  EXPECT_LT(ref.k.k11, 0.9);  // the layer matters on this grid
  EXPECT_NEAR(ours.k.k11, ref.k.k11, kKTolerance);
  EXPECT_NEAR(ours.k.k22, ref.k.k22, kKTolerance);
  EXPECT_NEAR(ours.k.k23, ref.k.k23, kKTolerance);
  EXPECT_NEAR(ours.k.k33, ref.k.k33, kKTolerance);
}

TEST(MatrixComplianceOperator, rejects_inconsistent_coefficients) {
  const Grid grid = Grid::centred(6, 4, 1.0e-3, 1.0e-3);
  const CombinedMaterial m = combine(kSteel, kSteel);
  SurfaceCompliance c = SurfaceCompliance::half_space(grid, m);
  c.yx.pop_back();
  EXPECT_THROW(MatrixComplianceOperator(c, m), std::invalid_argument);
  SurfaceCompliance d = SurfaceCompliance::half_space(grid, m);
  d.xx[3] = std::nan("");
  EXPECT_THROW(MatrixComplianceOperator(d, m), std::invalid_argument);
}

}  // namespace
