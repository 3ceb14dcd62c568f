#pragma once
// Test support: Kalker's creep coefficients measured with the MIM solver, shared by the fast
// and the slow MIM rolling tests.
#include <gtest/gtest.h>

#include <cmath>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/contact/mim/normal_solver.hpp"
#include "ferro/contact/mim/tangential_solver.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"

namespace ferro::test {


// Creep coefficients from full-adhesion (mu very large) runs on a Hertz ellipse a x b with
// `elements` across the shorter axis.
inline contact::KalkerCoefficients mim_creep_coefficients(double a, double b, int elements) {
  using namespace ferro::contact;
  using namespace ferro::contact::mim;
  const Material steel = Material::from_young(210.0e9, 0.28);
  const CombinedMaterial m = combine(steel, steel);
  const double fn = 1.0e5;
  const HertzGap hg = hertz_gap_for_ellipse(a, b, fn, m.contact_modulus);
  const Grid grid = grid_for_ellipse(a, b, elements, 0.04);
  InfluenceOperator op(grid, m);
  const NormalGridSolution s =
      solve_normal_force(op, quadratic_gap(grid, hg.curvature_x, hg.curvature_y), fn);
  EXPECT_TRUE(s.converged);
  const double g = m.shear_modulus, c = a * b, tiny = 1.0e-6, mu = 1.0e6;
  KalkerCoefficients k;
  auto rolling = [&](const RollingInput& in) {
    const TangentialGridSolution t = solve_steady_rolling(op, s.pressure, in);
    EXPECT_TRUE(t.converged);
    return t;
  };
  k.c11 = -rolling(RollingInput{tiny, 0.0, 0.0, mu}).force_x / (g * c * tiny);
  k.c22 = -rolling(RollingInput{0.0, tiny, 0.0, mu}).force_y / (g * c * tiny);
  const double spin = tiny / std::sqrt(c);
  k.c23 = -rolling(RollingInput{0.0, 0.0, spin, mu}).force_y / (g * std::pow(c, 1.5) * spin);
  return k;
}

}  // namespace ferro::test
