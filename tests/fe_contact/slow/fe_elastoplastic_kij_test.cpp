// Elasto-plastic rail: the K_ij range (first pass to shaken down) and the load study of the
// thesis's Table 3.9 (R900A and 350HT at 7.5 / 11.25 / 15 t).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "ferro/fe_contact/elastoplastic.hpp"
#include "ferro/fe_contact/elastoplastic_kij.hpp"

using namespace ferro;
using namespace ferro::fe_contact;

namespace {

const contact::Material kSteel = contact::Material::from_young(210.0e9, 0.28);
constexpr double kG = 9.81;  // m/s^2, tonnes to newtons

// K of two MIM runs with the same compliance: equal to the tangential solver's tolerance (1e-5
// of the rigid slip) with a margin for the two different preconditioners.
constexpr double kSameCompliance = 1.0e-4;
// A yielded zone must lower the first-pass slopes by more than the solver noise.
constexpr double kVisibleReduction = 1.0e-3;
// Just above first yield the plastic core is a few cells 0.47 a below the surface: the surface
// compliance, and so K, moves by less than 1 %.
constexpr double kFirstYieldCore = 0.01;
// Cells of a/4 place first yield within 10 % of the closed-form load (see
// fe_elastoplastic_test.cpp): loads 10 % either side must be elastic / plastic.
constexpr double kYieldMargin = 0.10;

ElastoplasticKijSpec circular_case(double peak_pressure) {
  // Circular Hertz patch a = b = 5 mm carrying p0: F_n = 2 pi a^2 p0 / 3.
  ElastoplasticKijSpec s;
  const double a = 5.0e-3;
  s.contact.reference_force = 2.0 * M_PI * a * a * peak_pressure / 3.0;
  s.contact.reference_semi_axis_x = a;
  s.contact.reference_semi_axis_y = a;
  s.contact.normal_force = s.contact.reference_force;
  s.contact.body = kSteel;
  s.contact.friction = 0.2;
  s.yield_stress = 489.0e6;  // R900A
  s.elements_per_semi_axis = 4;
  s.load_steps = 2;
  return s;
}

// The elastic limit: below the closed-form first yield (p0 = sigma_y / 0.629 = 1.59 sigma_y) the
// rail is elastic, so both bounds are the elastic K of the same grid (the half-space: 1); just
// above it a small plastic core appears below the surface, unloading is elastic (shakedown) and K
// stays within 1 % of 1.
TEST(ElastoplasticKij, elastic_below_first_yield_reduced_above) {
  const double p0_yield = 489.0e6 / hertz_circular_axis_von_mises_peak(kSteel.poisson).ratio;
  const ElastoplasticKij below = elastoplastic_reduction_factors(
      circular_case((1.0 - kYieldMargin) * p0_yield));
  std::printf("0.9 p0_yield: flowing %d, K11 %.5f / %.5f, K22 %.5f / %.5f, %.1f s CPU\n",
              below.cycle.flowing_points, below.first_pass.k.k11, below.shaken_down.k.k11,
              below.first_pass.k.k22, below.shaken_down.k.k22, below.cpu_seconds);
  ASSERT_TRUE(below.first_pass.converged);
  ASSERT_TRUE(below.shaken_down.converged);
  EXPECT_EQ(below.cycle.flowing_points, 0);
  for (const contact::ReductionFactors& k : {below.first_pass.k, below.shaken_down.k}) {
    EXPECT_NEAR(k.k11, 1.0, kSameCompliance);
    EXPECT_NEAR(k.k22, 1.0, kSameCompliance);
    EXPECT_NEAR(k.k23, 1.0, kSameCompliance);
    EXPECT_NEAR(k.k33, 1.0, kSameCompliance);
  }

  const ElastoplasticKij above = elastoplastic_reduction_factors(
      circular_case((1.0 + kYieldMargin) * p0_yield));
  std::printf(
      "1.1 p0_yield: flowing %d (reverse %d), residual %.3f um, K11 %.4f / %.4f, K22 %.4f / "
      "%.4f, %.1f s CPU\n",
      above.cycle.flowing_points, above.cycle.reverse_flowing_points,
      above.cycle.displacement_residual * 1e6, above.first_pass.k.k11, above.shaken_down.k.k11,
      above.first_pass.k.k22, above.shaken_down.k.k22, above.cpu_seconds);
  ASSERT_TRUE(above.first_pass.converged);
  EXPECT_GT(above.cycle.flowing_points, 0);
  for (const contact::ReductionFactors& k : {above.first_pass.k, above.shaken_down.k}) {
    EXPECT_NEAR(k.k11, 1.0, kFirstYieldCore);
    EXPECT_NEAR(k.k22, 1.0, kFirstYieldCore);
  }
  // Unloading from just above first yield is elastic: the cycle has shaken down.
  EXPECT_EQ(above.cycle.reverse_flowing_points, 0);
}

// Thesis Table 3.9 (R900A; the thesis gives no 350HT row): p_max, u_z under load, residual u_z.
// Two cheap rows here; the whole table (6 rows) is fe_contact/examples/
// thesis_elastoplastic_study.yaml run by `ferrodyn fe-kij`.
struct Table39Row {
  const char* name;
  double yield_stress;  // Pa
  double tonnes;
  double thesis_p_max;     // MPa, NaN: not given
  double thesis_residual;  // um, NaN: not given
};

class Table39 : public ::testing::TestWithParam<Table39Row> {};

// Residual displacement against the thesis: our pressure is the elastic Hertz one (1044 MPa), the
// thesis's elasto-plastic contact lowers it to 992 MPa, so our overload p0 / p0_yield - 1 is 0.34
// against 0.28; our own table grows the residual as that overload to the power 2.45 (5.2 um at
// 0.34, 15.8 um at 0.54), i.e. the pressure alone raises it by up to 1.7 x. Our steel is perfectly
// plastic (more flow than the thesis's hardening steel) and our load stationary (a rolling pass
// ratchets more: the other way). Bound: a factor of 2.
constexpr double kTable39Factor = 2.0;

TEST_P(Table39, row) {
  const Table39Row& r = GetParam();
  ElastoplasticKijSpec s;
  s.contact.reference_force = 7.5e3 * kG;  // Toumi (2016) Tables 3.1, 3.7
  s.contact.reference_semi_axis_x = 6.66e-3;
  s.contact.reference_semi_axis_y = 5.05e-3;
  s.contact.normal_force = r.tonnes * 1e3 * kG;
  s.contact.body = kSteel;
  s.contact.friction = 0.2;
  s.yield_stress = r.yield_stress;
  s.elements_per_semi_axis = 4;
  // 4 steps up, 1 down: against 6 and 6 (the table's setting) the residual moves by 0.25 %, the
  // first-pass K by < 1e-5, at 80 % of the CPU (docs/VALIDATION.md); one unloading step is exact
  // while the unloading is elastic (checked below).
  s.load_steps = 4;
  s.unload_steps = 1;
  const ElastoplasticKij k = elastoplastic_reduction_factors(s);
  const ElastoplasticResult& c = k.cycle;
  const double p0_yield = r.yield_stress / hertz_circular_axis_von_mises_peak(kSteel.poisson).ratio;
  std::printf(
      "TABLE39 | %s | %.2f t | p0 %.0f MPa (thesis %.0f) | p0/p0_yield %.2f | u_z %.1f um | "
      "residual %.2f um (thesis %.1f) | eps_p %.2e at %.2f mm | flowing %d reverse %d | "
      "K11 %.3f-%.3f | K22 %.3f-%.3f | K23 %.3f-%.3f | K33 %.3f-%.3f | %ld dofs | "
      "%d Newton | %.0f s CPU (cycle %.0f s)\n",
      r.name, r.tonnes, c.peak_pressure * 1e-6, r.thesis_p_max, c.peak_pressure / p0_yield,
      c.displacement_loaded * 1e6, c.displacement_residual * 1e6, r.thesis_residual,
      c.max_plastic_strain, c.depth_max_plastic_strain * 1e3, c.flowing_points,
      c.reverse_flowing_points, k.first_pass.k.k11, k.shaken_down.k.k11, k.first_pass.k.k22,
      k.shaken_down.k.k22, k.first_pass.k.k23, k.shaken_down.k.k23, k.first_pass.k.k33,
      k.shaken_down.k.k33, c.dofs, c.newton_iterations, k.cpu_seconds, c.cpu_seconds);
  ASSERT_TRUE(k.first_pass.converged);
  ASSERT_TRUE(k.shaken_down.converged);
  if (c.peak_pressure < (1.0 - kYieldMargin) * p0_yield) {
    // Elastic (350HT at 7.5 t, p0 = 0.88 p0_yield): no flow, K = 1 at both ends.
    EXPECT_EQ(c.flowing_points, 0);
    EXPECT_NEAR(k.first_pass.k.k11, 1.0, kSameCompliance);
    EXPECT_NEAR(k.shaken_down.k.k11, 1.0, kSameCompliance);
  } else if (c.peak_pressure > (1.0 + kYieldMargin) * p0_yield) {
    EXPECT_GT(c.flowing_points, 0);
    EXPECT_EQ(c.reverse_flowing_points, 0);
    EXPECT_LT(k.first_pass.k.k11, 1.0 - kVisibleReduction);
    EXPECT_LT(k.first_pass.k.k22, 1.0 - kVisibleReduction);
  }
  if (std::isfinite(r.thesis_residual)) {
    EXPECT_GT(c.displacement_residual, r.thesis_residual * 1e-6 / kTable39Factor);
    EXPECT_LT(c.displacement_residual, r.thesis_residual * 1e-6 * kTable39Factor);
  }
}

INSTANTIATE_TEST_SUITE_P(
    ElastoplasticKij, Table39,
    ::testing::Values(Table39Row{"R900A_7_5t", 489.0e6, 7.5, 992.0, 5.0},
                      Table39Row{"HT350_7_5t", 750.7e6, 7.5, NAN, NAN}),
    [](const ::testing::TestParamInfo<Table39Row>& row_info) { return std::string(row_info.param.name); });

}  // namespace
