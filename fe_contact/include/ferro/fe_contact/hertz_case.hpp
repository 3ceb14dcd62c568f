#pragma once
// The Hertzian contact of a K_ij study (thesis chapter 3: wheel on rail under the wheel load),
// its MIM grid and gap, and the interfacial (third-body) layer on the rail.
//
// References: Toumi (2016) Table 3.1 (E = 210 GPa, nu = 0.28, mu = 0.2, 7.5 t), Table 3.7
// (Hertz a = 6.66 mm, b = 5.05 mm), section 3.4 (third-body layer, h = 125 um, G = 820 MPa,
// perfectly plastic layer sigma_c); Johnson, "Contact Mechanics" (1985) eq. (4.24)
// (semi-axes scale as F_n^(1/3) at fixed curvatures); Vollebregt, CONTACT user guide
// (interfacial layer: local tangential compliance h / G3).
// Known deviations: the layer is a local (Winkler-type) tangential compliance; it does not
// spread load laterally and adds no normal compliance, valid for h much smaller than the patch.

#include <limits>
#include <string>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/grid.hpp"
#include "ferro/fe_contact/creep_slopes.hpp"

namespace ferro::fe_contact {

/// Hertzian contact given at a reference load; other loads scale the semi-axes by
/// (F_n / F_ref)^(1/3) (same curvatures).
struct HertzCase {
  double reference_force = kNaN;        ///< F_ref [N]
  double reference_semi_axis_x = kNaN;  ///< a at F_ref (rolling direction) [m]
  double reference_semi_axis_y = kNaN;  ///< b at F_ref [m]
  double normal_force = kNaN;           ///< F_n of this case [N]
  contact::Material body;               ///< wheel and rail (same steel)
  double friction = kNaN;               ///< mu [-]
  int elements_minor = 24;  ///< elements across the shorter axis of the grid [-]
  double margin = 0.15;     ///< grid margin beyond each semi-axis, relative [-]
  void validate(const std::string& where = "HertzCase") const;
  [[nodiscard]] double semi_axis_x() const;
  [[nodiscard]] double semi_axis_y() const;
  /// Grid and undeformed gap of the Hertz ellipse of this case.
  [[nodiscard]] contact::mim::Grid grid() const;
  [[nodiscard]] contact::mim::Field gap(const contact::mim::Grid& grid) const;
};

/// Interfacial layer on the rail: thickness h, shear modulus G3, optional shear strength tau_c
/// (perfectly plastic). h = 0 is no layer.
struct InterfaceLayer {
  double thickness = 0.0;                                       ///< h [m]
  double shear_modulus = kNaN;                                  ///< G3 [Pa]
  double yield_shear = std::numeric_limits<double>::infinity();  ///< tau_c [Pa]
  void validate(const std::string& where = "InterfaceLayer") const;
  /// h / G3 [m/Pa] (0 without layer).
  [[nodiscard]] double compliance() const;
};

/// Closed-form estimate of K11 for a layer in series with the half-space: full adhesion in the
/// layer alone gives F_x = -(8/3) a^2 b xi_x G3 / h (traction growing linearly from the leading
/// edge), the half-space gives F_x = -G a b C11 xi_x; in series,
/// K11 = 1 / (1 + 3 G C11 h / (8 a G3)).
[[nodiscard]] double layer_k11_estimate(double shear_modulus, double c11, double semi_axis_x,
                                        double thickness, double layer_shear_modulus);

/// K_ij of the layer against the half-space on the same grid (MIM, FFT operators).
[[nodiscard]] SlopeResult layer_reduction_factors(const HertzCase& c, const InterfaceLayer& layer,
                                                  const SlopeOptions& options = {});

}  // namespace ferro::fe_contact
