#pragma once
// Linear stability: eigenvalues of the Jacobian of an OdeSystem at an equilibrium, damping
// ratio of the least damped mode against speed, and the speed where it crosses zero.

#include <complex>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "ferro/vehicle/ode_system.hpp"

namespace ferro::vehicle {

struct Mode {
  std::complex<double> eigenvalue;  ///< [1/s]
  double damping_ratio = 0.0;       ///< zeta = -Re(lambda)/|lambda| [-]
  double frequency_hz = 0.0;        ///< |Im(lambda)| / 2 pi [Hz]
};

/// Modes of the system linearised at (t, x_eq) by central differences, sorted by increasing
/// damping ratio (least damped first). Eigenvalues with |lambda| < 1e-9 /s (neutral rigid-body
/// modes) are left out.
[[nodiscard]] std::vector<Mode> linear_modes(const OdeSystem& system, double t,
                                             std::span<const double> x_eq);

/// Modes with |damping ratio| below this are treated as neutral: undamped structural modes (a
/// wheelset bouncing on the Hertz contact stiffness without contact damping) whose computed
/// damping is numerical noise of either sign. They are never taken as the least damped mode
/// and never flag an instability; a mode becoming unstable must pass -kNeutralDamping.
inline constexpr double kNeutralDamping = 1e-3;

/// Builds the system at a given speed [m/s].
using SystemAtSpeed = std::function<std::unique_ptr<OdeSystem>(double speed)>;

struct SweepPoint {
  double speed = 0.0;  ///< [m/s]
  Mode least_damped;   ///< least damped non-neutral mode at that speed
};

/// A system at one speed and the state it is linearised about (its equilibrium at that speed).
struct Linearisation {
  std::unique_ptr<OdeSystem> system;
  std::vector<double> x_eq;
};
/// Builds the system at a given speed [m/s] with its equilibrium at that speed.
using LinearisationAtSpeed = std::function<Linearisation(double speed)>;

/// Least damped non-neutral mode at each speed.
[[nodiscard]] std::vector<SweepPoint> damping_sweep(const LinearisationAtSpeed& family,
                                                    const std::vector<double>& speeds);
/// The same about one state x_eq at every speed.
[[nodiscard]] std::vector<SweepPoint> damping_sweep(const SystemAtSpeed& factory,
                                                    const std::vector<double>& speeds,
                                                    std::span<const double> x_eq);

/// Lowest speed in [v_min, v_max] where a mode's damping ratio crosses zero (stable below):
/// scan on `scan_points` speeds for the first speed with a mode below -kNeutralDamping, then
/// bisection on the sign of the largest real part among the modes that are not neutral at
/// every speed (|damping ratio| < kNeutralDamping with the same eigenvalue at the unstable scan
/// speed and at v_min), from the scan speed before (or further back while that is not damped),
/// to a relative width `rel_tol`. Empty when no crossing is found.
[[nodiscard]] std::optional<double> critical_speed(const LinearisationAtSpeed& family, double v_min,
                                                   double v_max, int scan_points = 64,
                                                   double rel_tol = 1e-10);
/// The same about one state x_eq at every speed.
[[nodiscard]] std::optional<double> critical_speed(const SystemAtSpeed& factory, double v_min,
                                                   double v_max, std::span<const double> x_eq,
                                                   int scan_points = 64, double rel_tol = 1e-10);

}  // namespace ferro::vehicle
