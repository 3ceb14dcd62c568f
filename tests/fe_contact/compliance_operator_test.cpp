// The dense (numerical influence coefficient) compliance operator against the FFT half-space
// operator: filled with the annex B.3 coefficients it must give the same products and the same
// steady-rolling creep forces up to round-off.
#include <gtest/gtest.h>

#include "operator_products.hpp"

#include <cmath>
#include <random>

#include "ferro/contact/mim/dense_operator.hpp"
#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/contact/mim/influence_operator.hpp"
#include "ferro/contact/mim/mim.hpp"

using namespace ferro::contact;
using namespace ferro::contact::mim;

namespace {

const Material kSteel = Material::from_young(210.0e9, 0.28);

// Products: direct sums against zero-padded FFT convolution of the same coefficients. FFT
// round-off grows like log(n) eps times the largest kernel entry.
constexpr double kProductTolerance = 1.0e-11;
// Creep forces: the two solvers follow the same iteration with products differing by round-off;
// the converged forces then agree to round-off amplified by the Newton/GMRES steps.
constexpr double kForceTolerance = 1.0e-9;


TEST(DenseInfluenceOperator, products_equal_fft_half_space) {
  const Grid grid = Grid::centred(13, 9, 0.4e-3, 0.3e-3);
  const CombinedMaterial m = combine(kSteel, kSteel);
  InfluenceOperator fft(grid, m);
  DenseInfluenceOperator dense(grid, ColumnInfluence::half_space(grid, m), m);
  ferro::test::expect_products_equal(fft, dense, 7, kProductTolerance, 1.0e-14);
}

TEST(DenseInfluenceOperator, rolling_creep_forces_equal_fft_half_space) {
  // Hertzian patch a = 6.66 mm, b = 5.05 mm under 73.6 kN (Toumi 2016 Table 3.7), 24 elements
  // across b; combined creepages and spin with partial slip.
  const CombinedMaterial m = combine(kSteel, kSteel);
  const double a = 6.66e-3, b = 5.05e-3, fn = 73575.0;
  const Grid grid = grid_for_ellipse(a, b, 20);
  const HertzGap g = hertz_gap_for_ellipse(a, b, fn, m.contact_modulus);
  const Field gap = quadratic_gap(grid, g.curvature_x, g.curvature_y);
  InfluenceOperator fft(grid, m);
  DenseInfluenceOperator dense(grid, ColumnInfluence::half_space(grid, m), m);
  NormalLoad load;
  load.normal_force = fn;
  MimOptions opt;
  opt.tangential.tolerance = 1.0e-9;
  for (const RollingInput& in : {RollingInput{1.0e-3, 0.0, 0.0, 0.2},
                                 RollingInput{-4.0e-4, 8.0e-4, 0.5, 0.2},
                                 RollingInput{0.0, 0.0, 2.0, 0.3}}) {
    const MimResult rf = solve_rolling_contact(fft, gap, load, in, opt);
    const MimResult rd = solve_rolling_contact(dense, gap, load, in, opt);
    ASSERT_TRUE(rf.converged);
    ASSERT_TRUE(rd.converged);
    const double scale = in.friction * fn;
    EXPECT_NEAR(rd.force_x, rf.force_x, kForceTolerance * scale);
    EXPECT_NEAR(rd.force_y, rf.force_y, kForceTolerance * scale);
    EXPECT_NEAR(rd.moment_z, rf.moment_z, kForceTolerance * scale * a);
    EXPECT_NEAR(rd.approach, rf.approach, kForceTolerance * rf.approach);
  }
}

TEST(DenseInfluenceOperator, rejects_inconsistent_coefficients) {
  const Grid grid = Grid::centred(6, 5, 1.0e-3, 1.0e-3);
  const CombinedMaterial m = combine(kSteel, kSteel);
  ColumnInfluence c = ColumnInfluence::half_space(grid, m);
  c.xy.pop_back();
  EXPECT_THROW(DenseInfluenceOperator(grid, c, m), std::invalid_argument);
  ColumnInfluence d = ColumnInfluence::half_space(Grid::centred(6, 4, 1.0e-3, 1.0e-3), m);
  EXPECT_THROW(DenseInfluenceOperator(grid, d, m), std::invalid_argument);
}

}  // namespace
