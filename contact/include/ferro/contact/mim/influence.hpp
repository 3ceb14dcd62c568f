#pragma once
// Half-space influence coefficients of piecewise-constant rectangular surface loads.
//
// References: Toumi (2016) eqs. (70)-(76) and annex B.3 eqs. (B.13)-(B.20); Boussinesq-Cerruti
// point-load solutions annex B.1; Johnson, "Contact Mechanics" (1985) section 3.
// Known deviations: quasi-identical bodies only (K = 0, eq. 60): the normal-tangential coupling
// terms of eqs. (67)-(69) are dropped. The integration limits of eq. (76) are printed as
// x_j +- dx; the element is [x_j - dx/2, x_j + dx/2] (its width is dx), which is what is used.

#include "ferro/contact/material.hpp"

namespace ferro::contact::mim {

/// Relative surface displacements (body 1 minus body 2) at a point offset by (x, y) from the
/// centre of a dx x dy element carrying a unit uniform traction (1 Pa), in m/Pa.
/// u_z = zz p_n; u_x = xx tau_x + xy tau_y; u_y = xy tau_x + yy tau_y.
struct InfluenceCoefficients {
  double zz = 0.0;
  double xx = 0.0;
  double xy = 0.0;
  double yy = 0.0;
};

/// Closed forms (B.13)-(B.20) with the combined shear modulus G and Poisson ratio nu of the pair
/// (use combine() of material.hpp). Valid for any offset, including the element itself.
[[nodiscard]] InfluenceCoefficients influence_coefficients(double x, double y, double dx, double dy,
                                                           const CombinedMaterial& material);

}  // namespace ferro::contact::mim
