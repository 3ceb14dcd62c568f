#pragma once
// Hertzian (quadratic) undeformed gap reproducing a given contact ellipse, for MIM runs driven
// by Hertz semi-axes (tangential-model adapters, Kalker-coefficient checks).
//
// References: Toumi (2016) eqs. (5)-(13); Johnson, "Contact Mechanics" (1985) eqs. (3.63)-(3.64):
// for semi-axes a >= b, e^2 = 1 - b^2/a^2, p0 = 3 F / (2 pi a b),
//   A = p0 b / (E* a^2) (K(e) - E(e)) / e^2,   B = p0 b / (E* a^2) ((a/b)^2 E(e) - K(e)) / e^2,
//   delta = p0 b K(e) / E*,
// with the gap z = A x^2 + B y^2 (x along a) and K, E the complete elliptic integrals.
// Known deviations: none (exact elliptic integrals, by the arithmetic-geometric mean, elliptic.hpp).

#include "ferro/contact/mim/grid.hpp"

namespace ferro::contact::mim {

/// Curvature coefficients of the gap z = A x^2 + B y^2 and the Hertz approach.
struct HertzGap {
  double curvature_x = 0.0;   ///< A [1/m]
  double curvature_y = 0.0;   ///< B [1/m]
  double approach = 0.0;      ///< delta [m]
  double max_pressure = 0.0;  ///< p0 [Pa]
};

/// Gap reproducing the ellipse with semi-axes a (along x) and b (along y) [m] under normal
/// force F_n [N] for the contact modulus E* [Pa]. Throws std::invalid_argument on non-positive
/// input.
[[nodiscard]] HertzGap hertz_gap_for_ellipse(double semi_axis_x, double semi_axis_y,
                                             double normal_force, double contact_modulus);

/// Grid of square elements (dx = dy) centred on the origin, covering the ellipse a x b with a
/// relative margin (0.05 = 5 % beyond each semi-axis), with `elements_minor` elements across
/// the shorter axis 2 min(a, b) (1 + margin).
[[nodiscard]] Grid grid_for_ellipse(double semi_axis_x, double semi_axis_y, int elements_minor,
                                    double margin = 0.05);

/// Grid sized to the patch: `elements` x `elements` elements over the ellipse a x b with a
/// relative margin (dx = 2a (1 + margin) / elements, dy = 2b (1 + margin) / elements, so the
/// elements are rectangular with dx / dy = a / b). The default margin 0 puts the outer element
/// edges on the ends of the axes: the elements then tile the ellipse's bounding box, and the
/// discrete contact area follows the ellipse evenly at every element count (with a 5 % margin
/// the edge falls at a different fraction of an element at each count, and the 25 x 25 creep
/// forces are twice as far from the converged ones; docs/VALIDATION.md).
[[nodiscard]] Grid grid_over_ellipse(double semi_axis_x, double semi_axis_y, int elements,
                                     double margin = 0.0);

/// Samples z = A x^2 + B y^2 on the grid.
[[nodiscard]] Field quadratic_gap(const Grid& grid, double curvature_x, double curvature_y);

}  // namespace ferro::contact::mim
