#pragma once
// A single wheelset held by primary springs to a frame moving at constant speed V on straight
// track: lateral displacement y and yaw psi, conical wheels of effective conicity gamma, linear
// Kalker creep forces.
//
// References: Toumi (2016) eqs. (150)-(151) and SPEC_DIGEST §5 (the standard form with 2f on
// the off-diagonal terms); Wickens, "Fundamentals of Rail Vehicle Dynamics" (2003) ch. 2;
// Kalker's C11, C22 from Toumi annex A.2.
// Known deviations: spin creep, gravitational stiffness and the wheelset's roll are neglected,
// as in eq. (150); creep forces are linear (no saturation), so above the critical speed the
// motion grows without bound instead of reaching a flange-limited limit cycle.

#include <array>
#include <limits>
#include <string>

#include "ferro/contact/kij/reduction_factors.hpp"
#include "ferro/contact/material.hpp"
#include "ferro/vehicle/ode_system.hpp"

namespace ferro::vehicle {

struct SuspendedWheelsetParams {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double mass = kNaN;                  ///< m [kg]
  double yaw_inertia = kNaN;           ///< I_zz [kg m^2]
  double half_gauge = kNaN;            ///< e, lateral semi-distance of the contact points [m]
  double rolling_radius = kNaN;        ///< R, nominal rolling radius [m]
  double conicity = kNaN;              ///< gamma, effective conicity [-]
  double primary_stiffness_x = kNaN;   ///< k_x, longitudinal, per axlebox [N/m]
  double primary_stiffness_y = kNaN;   ///< k_y, lateral, per axlebox [N/m]
  double primary_damping_x = 0.0;      ///< c_x, longitudinal, per axlebox [N s/m]
  double primary_damping_y = 0.0;      ///< c_y, lateral, per axlebox [N s/m]
  double primary_semi_spacing = kNaN;  ///< d, lateral semi-spacing of the axleboxes [m]; NaN = e

  /// Throws std::invalid_argument naming `where`.field.
  void validate(const std::string& where = "model") const;
  /// Lateral semi-spacing actually used (d, or e when unset) [m].
  [[nodiscard]] double spring_semi_spacing() const;
};

/// Linear creep: contact ellipse semi-axes and materials give f_ij = G a b C_ij K_ij per wheel.
struct LinearCreepParams {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double semi_axis_a = kNaN;  ///< a, along the rolling direction [m]
  double semi_axis_b = kNaN;  ///< b, lateral [m]
  contact::Material wheel = contact::Material::steel();
  contact::Material rail = contact::Material::steel();
  /// K_ij; linear theory without spin uses K11 on C11 and K22 on C22 [-].
  contact::ReductionFactors reduction;
  /// Coefficient source: "kalker_table" (annex A.2) or "equal" (C11 = C22 = the table's C11,
  /// the assumption of the closed-form critical speed).
  std::string coefficients = "kalker_table";

  void validate(const std::string& where = "contact") const;
};

/// Per-wheel creep coefficients [N]: f11 = G a b C11 K11, f22 = G a b C22 K22.
struct CreepCoefficients {
  double f11 = 0.0;
  double f22 = 0.0;
};
[[nodiscard]] CreepCoefficients creep_coefficients(const LinearCreepParams& creep);

class SuspendedWheelset final : public OdeSystem {
 public:
  /// State order: y [m], psi [rad], y' [m/s], psi' [rad/s].
  SuspendedWheelset(SuspendedWheelsetParams params, CreepCoefficients creep, double speed);

  [[nodiscard]] std::size_t size() const override { return 4; }
  int rhs(double t, std::span<const double> x, std::span<double> xdot) const override;
  [[nodiscard]] std::vector<SignalInfo> state_info() const override;
  [[nodiscard]] std::vector<SignalInfo> signal_info() const override;
  void signals(double t, std::span<const double> x, std::span<double> out) const override;

  [[nodiscard]] double speed() const { return speed_; }
  [[nodiscard]] const SuspendedWheelsetParams& params() const { return p_; }
  [[nodiscard]] const CreepCoefficients& creep() const { return creep_; }

 private:
  SuspendedWheelsetParams p_;
  CreepCoefficients creep_;
  double speed_;
};

/// Closed-form critical speed of eq. (151) in the standard form (SPEC_DIGEST §5):
/// Vc^2 = 8 f^2 e R (Kx + Ky) / (m (16 f^2 gamma - e R (Ky - Kx)^2)), with Ky = 2 k_y,
/// Kx = 2 k_x d^2 / e^2 (so that e^2 Kx is the yaw stiffness), f = f11 = f22.
/// Valid only for f11 = f22, I_zz = m e^2 and no primary damping; returns +inf when the
/// denominator is not positive (always stable). Throws std::invalid_argument otherwise.
[[nodiscard]] double analytic_critical_speed(const SuspendedWheelsetParams& params,
                                             const CreepCoefficients& creep);

}  // namespace ferro::vehicle
