#pragma once
// The contact patch passed from a normal model to a tangential (creep-force) model.
//
// References: Toumi (2016) eqs. (11)-(12) (Hertz ellipse) and (22)-(23) (semi-Hertz strips).
// Known deviations: none (data only).

#include <limits>
#include <vector>

#include "ferro/contact/normal/hertz.hpp"

namespace ferro::contact {

/// One strip of a non-elliptic patch, parallel to the rolling direction x.
struct PatchStrip {
  double y = 0.0;              ///< lateral position of the strip centre [m]
  double width = 0.0;          ///< lateral width dy [m]
  double x_center = 0.0;       ///< longitudinal centre of the strip [m]
  double half_length = 0.0;    ///< a_i [m]
  double peak_pressure = 0.0;  ///< p0_i: pressure p = p0_i sqrt(1 - (x - xc)^2 / a_i^2) [Pa]
};

/// A contact patch. Elliptic patches need only the semi-axes, load and curvatures; non-elliptic
/// ones (semi-Hertz) also carry their strips. Every tangential model reads a and b (an
/// equivalent ellipse for non-elliptic patches, used for Kalker's coefficients and FASTSIM's
/// flexibilities).
struct ContactPatch {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double semi_axis_x = kNaN;       ///< a [m] (rolling direction)
  double semi_axis_y = kNaN;       ///< b [m] (lateral)
  double normal_force = kNaN;      ///< F_n [N]
  double peak_pressure = kNaN;     ///< p_max [Pa]
  double approach = kNaN;          ///< delta [m] (NaN if the model does not give it)
  double curvature_x = kNaN;       ///< A [1/m] (NaN if unknown; needed by VOCO's C_ij fits)
  double curvature_y = kNaN;       ///< B [1/m] (equivalent value for semi-Hertz patches)
  double y_center = 0.0;           ///< lateral position of the patch centre in the gap frame [m]
  std::vector<PatchStrip> strips;  ///< empty for an elliptic (Hertz) patch
  /// Kalker's coefficients C11, C22, C23 [-] when the contact source gives them with the point
  /// (a one-point table imported from another tool carries the ones its author computed); NaN:
  /// from a/b and the Poisson ratio (Kalker's table or the chosen fits). C33 always from a/b.
  double c11 = kNaN, c22 = kNaN, c23 = kNaN;

  [[nodiscard]] bool elliptic() const { return strips.empty(); }
  /// Throws std::invalid_argument naming the field when a, b, F_n are not positive/finite.
  void validate(const char* where = "patch") const;
};

/// Elliptic patch from Hertz semi-axes and load (p_max = 3F/(2 pi a b)); curvatures unknown
/// unless given.
[[nodiscard]] ContactPatch elliptic_patch(double semi_axis_x, double semi_axis_y,
                                          double normal_force,
                                          double curvature_x = ContactPatch::kNaN,
                                          double curvature_y = ContactPatch::kNaN);

/// Elliptic patch of a Hertz solution (semi-axes, load, p_max, approach) for the curvatures
/// A, B [1/m] it was solved for.
[[nodiscard]] ContactPatch hertz_patch(const HertzSolution& hertz, double curvature_x,
                                       double curvature_y);

}  // namespace ferro::contact
