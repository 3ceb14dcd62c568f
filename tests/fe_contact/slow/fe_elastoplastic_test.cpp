// Elasto-plastic rail head under the Hertz pressure (J2, GetFEM small-strain brick): first yield
// where the closed-form Hertz stresses reach the yield stress (R900A), and the elastic centre
// displacement of the Hertz pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "ferro/fe_contact/elastoplastic.hpp"

using namespace ferro;
using namespace ferro::fe_contact;

namespace {

const contact::Material kSteel = contact::Material::from_young(210.0e9, 0.28);

RailSteel steel(double yield_stress) {
  RailSteel s;
  s.elastic = kSteel;
  s.yield_stress = yield_stress;
  s.hardening_modulus = 0.0;  // perfectly plastic: the thesis's hardening curves are figures
  return s;
}

// Trilinear cells of a/4 sample the stress at Gauss points a/8 apart around the yield point
// (0.47 a deep, where the von Mises stress is flat to 1 % over +-0.1 a): first yield is placed
// within 10 % of the closed form, so loads 10 % either side must be elastic / plastic.
constexpr double kYieldMargin = 0.10;
// The clamped bottom 12 a deep removes about (3 - 2 nu) / (18 pi (1 - nu)) = 6 % of the
// half-space's centre displacement (Johnson 1985 section 3.2); the free sides give some back.
constexpr double kDisplacementTolerance = 0.08;

TEST(ElastoplasticRail, first_yield_at_the_hertz_closed_form) {
  const AxisVonMisesPeak peak = hertz_circular_axis_von_mises_peak(kSteel.poisson);
  // Johnson (1985) section 6.2: 0.62 p0 at 0.48 a for nu = 0.3.
  EXPECT_NEAR(peak.ratio, 0.62, 0.015);
  EXPECT_NEAR(peak.depth_over_a, 0.48, 0.02);
  const RailSteel r900a = steel(489.0e6);
  const double p0_yield = r900a.yield_stress / peak.ratio;
  HertzLoadCase load;
  load.semi_axis_x = 5.0e-3;
  load.semi_axis_y = 5.0e-3;
  load.elements_per_semi_axis = 4;

  load.peak_pressure = (1.0 - kYieldMargin) * p0_yield;
  load.load_steps = 1;
  const ElastoplasticResult below = hertz_load_cycle(r900a, load);
  // Hertz centre displacement of one body: (1 - nu^2) pi p0 a / (2 E).
  const double hertz_uz = (1.0 - kSteel.poisson * kSteel.poisson) * M_PI * load.peak_pressure *
                          load.semi_axis_x / (2.0 * kSteel.young());
  std::printf(
      "p0 = %.0f MPa (%.2f p0_yield): u_z %.2f um (Hertz %.2f), eps_p %.2e, %ld dofs, "
      "%.1f s CPU\n",
      below.peak_pressure * 1e-6, 1.0 - kYieldMargin, below.displacement_loaded * 1e6,
      hertz_uz * 1e6, below.max_plastic_strain, below.dofs, below.cpu_seconds);
  EXPECT_EQ(below.max_plastic_strain, 0.0);
  EXPECT_NEAR(below.displacement_loaded / hertz_uz, 1.0, kDisplacementTolerance);
  EXPECT_LT(std::abs(below.displacement_residual), 1e-6 * below.displacement_loaded);

  load.peak_pressure = (1.0 + kYieldMargin) * p0_yield;
  load.load_steps = 2;
  const ElastoplasticResult above = hertz_load_cycle(r900a, load);
  std::printf(
      "p0 = %.0f MPa (%.2f p0_yield): eps_p %.2e at %.2f mm (closed form %.2f mm), "
      "residual u_z %.3f um, %d Newton iterations, %.1f s CPU\n",
      above.peak_pressure * 1e-6, 1.0 + kYieldMargin, above.max_plastic_strain,
      above.depth_max_plastic_strain * 1e3, peak.depth_over_a * load.semi_axis_x * 1e3,
      above.displacement_residual * 1e6, above.newton_iterations, above.cpu_seconds);
  EXPECT_GT(above.max_plastic_strain, 0.0);
  EXPECT_GT(above.displacement_residual, 0.0);
  // Plastic flow starts below the surface, around the closed-form depth (within two cells).
  EXPECT_NEAR(above.depth_max_plastic_strain, peak.depth_over_a * load.semi_axis_x,
              2.0 * load.semi_axis_x / load.elements_per_semi_axis);
}

// Thesis Table 3.9 rows: fe_elastoplastic_kij_test.cpp (with the K_ij range).

}  // namespace
