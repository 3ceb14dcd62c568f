// Interfacial (third-body) layer: K11 against the closed-form series estimate, the layer-free
// limit, and the perfectly plastic layer (tau_c lowers the saturation, not the initial slope).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "ferro/contact/mim/influence_operator.hpp"
#include "ferro/contact/mim/normal_solver.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/fe_contact/hertz_case.hpp"
#include "thesis_hertz_case.hpp"

using namespace ferro;
using namespace ferro::fe_contact;

namespace {

// Thesis chapter 3 case (tests/support/thesis_hertz_case.hpp), default margin.
HertzCase thesis_case(int elements_minor = 24) {
  return ferro::test::thesis_hertz_case(elements_minor, HertzCase{}.margin);
}

// The series estimate treats the layer as carrying the Kalker-linear traction distribution of a
// rigid body and the half-space the Kalker one of a layer-free body; the exact discrete solution
// of both in series lies within a few per cent of it (the acceptance band).
constexpr double kEstimateTolerance = 0.05;
// tau_c below mu p only near the patch centre at the probe creepage does not touch the
// full-adhesion solution: the initial slope changes only by round-off and solver tolerance.
constexpr double kSlopeTolerance = 1.0e-3;

TEST(InterfaceLayer, no_layer_gives_one) {
  const SlopeResult r = layer_reduction_factors(thesis_case(12), InterfaceLayer{});
  ASSERT_TRUE(r.converged);
  EXPECT_NEAR(r.k.k11, 1.0, 1.0e-12);
  EXPECT_NEAR(r.k.k22, 1.0, 1.0e-12);
  EXPECT_NEAR(r.k.k33, 1.0, 1.0e-12);
}

TEST(InterfaceLayer, k11_follows_series_estimate) {
  const HertzCase c = thesis_case();
  const double g = c.body.shear_modulus;
  // C11 of the discrete half-space on the same grid: S11 / (G a b).
  const double a = c.semi_axis_x(), b = c.semi_axis_y();
  for (const double h_over_g3 : {2.0e-14, 1.0e-13, 1.5e-13}) {  // m/Pa: h = 125 um, G3 >= 820 MPa
    InterfaceLayer layer;
    layer.thickness = 125.0e-6;
    layer.shear_modulus = layer.thickness / h_over_g3;
    const SlopeResult r = layer_reduction_factors(c, layer);
    ASSERT_TRUE(r.converged);
    const double c11 = r.half_space.s11 / (g * a * b);
    const double estimate = layer_k11_estimate(g, c11, a, layer.thickness, layer.shear_modulus);
    std::printf("h/G3 = %.2e m/Pa: C11(grid) %.3f, K11 %.4f, estimate %.4f (%+.1f %%)\n",
                h_over_g3, c11, r.k.k11, estimate, 100.0 * (r.k.k11 / estimate - 1.0));
    EXPECT_NEAR(r.k.k11, estimate, kEstimateTolerance * estimate)
        << "h/G3 = " << h_over_g3 << " C11(grid) = " << c11;
    EXPECT_LT(r.k.k22, 1.0);
  }
}

TEST(InterfaceLayer, yield_shear_lowers_saturation_not_initial_slope) {
  const HertzCase c = thesis_case(16);
  const contact::mim::Grid grid = c.grid();
  const contact::mim::Field gap = c.gap(grid);
  const contact::CombinedMaterial m = contact::combine(c.body, c.body);
  InterfaceLayer layer;
  layer.thickness = 125.0e-6;
  layer.shear_modulus = 820.0e6;
  contact::mim::InfluenceOperator op(grid, m, layer.compliance());
  SlopeCase elastic;
  elastic.normal_force = c.normal_force;
  elastic.friction = c.friction;
  elastic.semi_axis_x = c.semi_axis_x();
  SlopeCase plastic = elastic;
  plastic.yield_shear = 100.0e6;  // Toumi Fig. 3.48: sigma_c = 100 MPa
  const CreepStiffness se = creep_stiffness(op, gap, elastic);
  const CreepStiffness sp = creep_stiffness(op, gap, plastic);
  EXPECT_NEAR(sp.s11, se.s11, kSlopeTolerance * se.s11);
  // Saturation at large creepage: full slip, F_x = -sum min(mu p, tau_c) dA exactly.
  const contact::mim::NormalGridSolution n =
      contact::mim::solve_normal_force(op, gap, c.normal_force);
  double bound_sum = 0.0;
  for (double p : n.pressure) bound_sum += std::min(c.friction * p, plastic.yield_shear);
  bound_sum *= grid.element_area();
  const std::vector<double> xi{0.05};
  const CreepCurve ce = creep_curve(op, gap, elastic, 'x', xi);
  const CreepCurve cp = creep_curve(op, gap, plastic, 'x', xi);
  EXPECT_NEAR(-ce.force[0], c.friction * c.normal_force, 1.0e-6 * c.normal_force);
  EXPECT_NEAR(-cp.force[0], bound_sum, 1.0e-6 * c.normal_force);
  EXPECT_LT(-cp.force[0], 0.9 * c.friction * c.normal_force);
}

}  // namespace
