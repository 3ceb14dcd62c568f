#pragma once
// Kalker's linear-theory creep coefficients C11, C22, C23, C33 for an elliptic contact.
//
// References: Kalker, "On the rolling contact of two elastic bodies in the presence of dry
// friction", PhD thesis, Delft (1967), table reproduced in Toumi (2016) annex A.2.
// VOCO's fits in the curvature ratio X = A/B: Toumi (2016) eq. (154), after Ayasse & Chollet,
// Handbook of railway vehicle dynamics (2006).
// Known deviations: between table nodes the coefficients are interpolated linearly in the
// ellipse parameter (a/b for a <= b, 2 - b/a for a > b) and quadratically (Lagrange) in nu
// through the nu = 0, 1/4, 1/2 columns, so every printed node is reproduced exactly.
// Below a/b = 0.1 the table's g -> 0 row (Kalker's asymptotes, annex A.2 first row) is used:
// C11 -> pi^2/(4(1-nu)), C22 -> pi^2/4 and g C33 -> pi^2/(16(1-nu)) are interpolated linearly in
// g = a/b between that limit and the a/b = 0.1 node; C23 follows the asymptotic law C23 ~ sqrt(g)
// scaled to the 0.1 node (the thesis prints the limit pi sqrt(g)/3 only for nu = 0, which that
// node matches within 1 %). Beyond b/a < 0.1 (ellipse elongated along x) no asymptote with a
// verified source was available here: the value is clamped to the b/a = 0.1 row.
// The eq. (154) fits give C11, C22, C23 for nu = 1/4 only; C33 is then taken from the table.

#include <string>

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

/// VOCO's fits, Toumi eq. (154), in the curvature ratio X = A/B > 0:
/// C11 = 3.3 + 0.89/(0.085 + X), C22 = 2.46 + 1.34/(0.109 + X), C23 = 0.18 + 1.29/(0.002 + X)^0.63.
/// c33 is NaN (the fits do not give it). Throws std::invalid_argument for X <= 0 or non-finite.
[[nodiscard]] KalkerCoefficients kalker_coefficients_voco_fit(double curvature_ratio);

/// Where C_ij come from in the tangential models ("kalker_table", "voco_fit").
enum class CoefficientSource { kKalkerTable, kVocoFit };

/// Parses "kalker_table" / "voco_fit"; throws std::invalid_argument naming the allowed values.
[[nodiscard]] CoefficientSource coefficient_source_from_name(const std::string& name);
[[nodiscard]] const char* coefficient_source_name(CoefficientSource source);

/// C_ij for a patch: the table in a/b and nu, or VOCO's fits in X = A/B (C33 from the table).
/// For voco_fit the curvature ratio must be finite and > 0 (std::invalid_argument otherwise).
[[nodiscard]] KalkerCoefficients kalker_coefficients(CoefficientSource source, double a, double b,
                                                     double poisson, double curvature_ratio);

}  // namespace ferro::contact
