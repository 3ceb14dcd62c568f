#pragma once
// Kalker's linear-theory creep coefficients C11, C22, C23, C33 for an elliptic contact.
//
// References: Kalker, "On the rolling contact of two elastic bodies in the presence of dry
// friction", PhD thesis, Delft (1967), table reproduced in Toumi (2016) annex A.2.
// Known deviations: between table nodes the coefficients are interpolated linearly in the
// ellipse parameter (a/b for a <= b, 2 - b/a for a > b) and quadratically (Lagrange) in nu
// through the nu = 0, 1/4, 1/2 columns, so every printed node is reproduced exactly. Outside
// the table (a/b < 0.1 or b/a < 0.1) the value is clamped to the end row.

namespace ferro::contact {

/// Kalker's coefficients (dimensionless). Sign convention of Toumi eqs. (38)-(40):
/// Fx = -G a b C11 xi_x, Fy = -G a b C22 xi_y - G (ab)^1.5 C23 phi,
/// Mz = G (ab)^1.5 C23 xi_y - G (ab)^2 C33 phi.
struct KalkerCoefficients {
  double c11 = 0.0;
  double c22 = 0.0;
  double c23 = 0.0;
  double c33 = 0.0;
};

/// Coefficients from the annex A.2 table for semi-axes a (rolling direction x) and b (lateral y),
/// any length unit, and Poisson's ratio nu in [0, 0.5]. Throws std::invalid_argument otherwise.
[[nodiscard]] KalkerCoefficients kalker_coefficients_table(double a, double b, double poisson);

}  // namespace ferro::contact
