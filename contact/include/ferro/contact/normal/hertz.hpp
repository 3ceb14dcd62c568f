#pragma once
// Hertz's solution of the normal contact between two quadric surfaces, solved exactly with the
// complete elliptic integrals (no m, n, r table).
//
// References: Hertz (1882); Johnson, "Contact Mechanics" (1985) eqs. (3.64)-(3.72); Toumi (2016)
// eqs. (5)-(13) and annex A.1 (m, n, r, used only as a cross-check in the tests).
// Known deviations: none within the half-space and quasi-identity assumptions; the ellipse
// eccentricity is solved by a safeguarded Newton iteration to ~1e-14 in the curvature ratio.

#include <limits>

namespace ferro::contact {

/// Hertzian ellipse. x is the rolling (longitudinal) direction, y the lateral one.
struct HertzSolution {
  double semi_axis_x = std::numeric_limits<double>::quiet_NaN();    ///< a [m]
  double semi_axis_y = std::numeric_limits<double>::quiet_NaN();    ///< b [m]
  double approach = std::numeric_limits<double>::quiet_NaN();       ///< delta [m]
  double peak_pressure = std::numeric_limits<double>::quiet_NaN();  ///< p_max = 3F/(2 pi a b) [Pa]
  double normal_force = std::numeric_limits<double>::quiet_NaN();   ///< F_n [N]

  /// Pressure p(x, y) = p_max sqrt(1 - x^2/a^2 - y^2/b^2) inside the ellipse, 0 outside [Pa].
  [[nodiscard]] double pressure(double x, double y) const;
};

/// Dimensionless Hertz coefficients of Toumi eqs. (8)-(10): a_major = m c, b_minor = n c,
/// delta = r c^2 (A + B), with c = (3 F / (4 E* (A + B)))^(1/3).
struct HertzCoefficients {
  double m = 0.0;
  double n = 0.0;
  double r = 0.0;
};

/// Relative curvatures A (x), B (y) [1/m] as the Hertz solution uses them. This is the one
/// treatment of curvatures outside Hertz's assumptions, applied by every Hertz function here:
/// - conformal or negative curvature (B <= 0, e.g. a hollow wheel on a flat-topped rail, or the
///   throat of a flange root): the smaller curvature is raised to kHertzMinCurvatureRatio times the
///   larger one, so the patch stays a (very elongated) ellipse instead of failing; the result is
///   the Hertz solution of that nearly cylindrical contact, a stiffness bound, not a conformal
///   solution (use semi-Hertz or MIM where conformity matters);
/// - kinks of sampled profiles (unbounded curvature): each curvature is capped at
///   kHertzMaxCurvature (10 um radius), a very stiff point contact.
/// The larger of A, B must be finite and > 0 (otherwise std::invalid_argument naming `where`).
struct HertzCurvatures {
  double x = 0.0;  ///< A used [1/m]
  double y = 0.0;  ///< B used [1/m]
};
inline constexpr double kHertzMinCurvatureRatio = 1e-3;  ///< smaller >= 1e-3 larger [-]
inline constexpr double kHertzMaxCurvature = 1e5;        ///< [1/m]
[[nodiscard]] HertzCurvatures hertz_curvatures(double curvature_x, double curvature_y,
                                               const char* where = "hertz");

/// Hertz solution for the gap z = A x^2 + B y^2 (A = curvature_x, B = curvature_y [1/m], treated
/// by hertz_curvatures()), normal force F_n >= 0 [N] and contact modulus E* [Pa] (see combine()
/// in material.hpp). Exact: solves the eccentricity by Newton on the elliptic integrals.
[[nodiscard]] HertzSolution hertz_solve(double curvature_x, double curvature_y, double normal_force,
                                        double contact_modulus);

/// The same Hertz solution given the normal approach delta [m] instead of the load (delta <= 0:
/// no contact, F_n = 0, semi-axes 0). The eccentricity comes from a relation tabulated once per
/// process over ln(curvature ratio) in [0, ln 1e6] (cubic interpolation of the exact values,
/// relative error < 1e-8; exact Newton beyond); no allocation, < 0.1 us.
[[nodiscard]] HertzSolution hertz_solve_from_approach(double curvature_x, double curvature_y,
                                                      double approach, double contact_modulus);

/// m, n, r for the angle theta of eq. (13), cos(theta) = |A - B| / (A + B), theta in (0, pi/2].
[[nodiscard]] HertzCoefficients hertz_coefficients(double theta);

/// Largest curvature ratio (larger/smaller) the elliptic solution accepts [-]; beyond it the
/// axis ratio falls below kMinAxisRatio and the elliptic modulus sqrt(1 - k^2) rounds to 1.
inline constexpr double kMaxCurvatureRatio = 1e10;
/// Smallest minor/major axis ratio accepted [-] (rho(kMinAxisRatio) > kMaxCurvatureRatio).
inline constexpr double kMinAxisRatio = 1e-7;

/// Minor/major semi-axis ratio k = b_minor/a_major (in (0, 1]) of the Hertz ellipse for the
/// curvature ratio rho = larger/smaller curvature >= 1.
[[nodiscard]] double hertz_axis_ratio(double curvature_ratio);

/// Inverse: the curvature ratio rho = larger/smaller curvature >= 1 giving the axis ratio
/// k = minor/major in (0, 1].
[[nodiscard]] double hertz_curvature_ratio(double axis_ratio);

}  // namespace ferro::contact
