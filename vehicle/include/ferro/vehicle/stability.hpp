#pragma once
// Linear stability: eigenvalues of the Jacobian of an OdeSystem at an equilibrium, the shape
// of each mode (which bodies and directions carry its kinetic energy) and its class (hunting,
// contact, track, ...), damping ratio of the least damped mode against speed, and the speed
// where a hunting mode crosses zero.
//
// Mode shapes: for a mode with eigenvector v (Jacobian J v = lambda v) the kinetic energy
// carried by state i is w_i |v_i|^2 / 2 for the velocity-type states (the rates of the
// positions and the first-order wheelset spin perturbation), w_i the state's generalised mass
// (mass or moment of inertia about the DOF's axis). The shares of the total over the groups of
// DofGroup are the mode's participation: they do not depend on how the eigenvector is scaled
// and compare translations and rotations in one unit (energy), which displacement amplitudes
// (m against rad) cannot.
//
// References: Wickens, "Fundamentals of Rail Vehicle Dynamics" (2003) ch. 5-6 (wheelset and
//   bogie hunting modes: lateral displacement and yaw of the wheelsets, with the bogie frame);
//   True (1999) (hunting as the Hopf bifurcation of the lateral modes); Knothe & Grassie,
//   "Modelling of railway track and vehicle/track interaction at high frequencies", Vehicle
//   System Dynamics 22 (1993) (the wheelset's vertical modes on the contact stiffness, P1/P2,
//   and the track's own modes above 50 Hz).
// Known deviations: the energy share uses the kinetic energy alone (the potential energy would
//   need the stiffness matrix, which the right-hand side does not expose).

#include <array>
#include <complex>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <span>
#include <vector>

#include "ferro/vehicle/ode_system.hpp"

namespace ferro::vehicle {

/// Groups of velocity-type states a mode's kinetic energy is shared over.
enum class DofGroup : int {
  wheelset_lateral_yaw = 0,        ///< wheelset y, yaw (the hunting motion of the wheelsets)
  wheelset_vertical_roll = 1,      ///< wheelset z, roll (against the contact-normal stiffness)
  wheelset_longitudinal_spin = 2,  ///< wheelset x, spin perturbation
  frame_lateral = 3,               ///< bogie frames: y, roll, yaw
  frame_vertical = 4,              ///< bogie frames: x, z, pitch
  carbody_lateral = 5,             ///< car body: y, roll, yaw
  carbody_vertical = 6,            ///< car body: x, z, pitch
  track = 7,                       ///< states of the track structure ("track." names)
  none = 8,                        ///< no kinetic energy (positions, damper deflections, ...)
};
inline constexpr int kDofGroups = 8;  ///< groups that carry energy (all but none)
[[nodiscard]] const char* to_string(DofGroup g);

/// Class of a mode by its shape (the largest participation decides, see classify_mode()).
enum class ModeClass : int {
  unclassified = 0,  ///< no shape information was given
  hunting,       ///< lateral modes the wheelsets' lateral/yaw motion takes part in (with the
                 ///< frames and the car body): the modes whose crossing is hunting
  contact,       ///< wheelsets moving on the contact stiffness: vertical/roll
  longitudinal,  ///< wheelset longitudinal motion and spin
  body,          ///< bogie frames and car body with the wheelsets (nearly) still: sway,
                 ///< bounce, pitch on the suspension
  track,         ///< the track structure's own modes
};
[[nodiscard]] const char* to_string(ModeClass c);

/// Per state of a system: its group and generalised mass (0 for states of group none).
struct ModeShapeInput {
  std::vector<DofGroup> group;  ///< one per state
  std::vector<double> weight;   ///< [kg] or [kg m^2], one per state
  [[nodiscard]] bool empty() const { return group.empty(); }
};

/// Groups from state names, the vehicle's naming (vehicle_model.hpp): "<body>.<dof>_dot" rates
/// and "<body>.spin" spin perturbations of bodies whose name starts with "wheelset", "bogie" or
/// "car_body"; "track." states belong to the track (their rates: names ending in "_dot"). Every
/// other state (positions, damper deflections) is of group none. `mass(body, dof)` gives the
/// generalised mass of a body's DOF ("x", "y", "z", "roll", "pitch", "yaw", "spin") or of a
/// track state (body "track.<...>", dof as named), NaN when unknown: such states take the
/// median of the known weights (a documented fallback for a structure that does not state its
/// masses).
[[nodiscard]] ModeShapeInput mode_shape_input(
    const std::vector<SignalInfo>& states,
    const std::function<double(const std::string& body, const std::string& dof)>& mass);

/// Participation above which a group is said to dominate a mode [-].
inline constexpr double kDominantShare = 0.5;
/// A lateral mode whose wheelsets' lateral/yaw motion carries at least this fraction of its
/// lateral energy (wheelsets, frames and car body) is hunting: the creep forces couple it to
/// the wheelsets' kinematics. Below, a body mode (the car body or the frames swaying on the
/// suspension with the wheelsets nearly still) [-]. Measured on the Cooperrider wagon
/// (docs/VALIDATION.md, "Mode classes"): car-body sway and yaw modes carry 0-0.4 % in the
/// wheelsets, the hunting modes 11-39 %.
inline constexpr double kHuntingWheelsetShare = 0.01;

struct Mode {
  std::complex<double> eigenvalue;  ///< [1/s]
  double damping_ratio = 0.0;       ///< zeta = -Re(lambda)/|lambda| [-]
  double frequency_hz = 0.0;        ///< |Im(lambda)| / 2 pi [Hz]
  /// Kinetic-energy share of each DofGroup (index by the enum), summing to 1; all 0 when no
  /// shape input was given.
  std::array<double, kDofGroups> participation{};
  ModeClass kind = ModeClass::unclassified;
  /// Mass-weighted velocity components sqrt(w_i) v_i of the kinetic states, unit norm (with
  /// shape input only): the inner product of two of them is the modal assurance criterion in
  /// the kinetic-energy metric, which follows a mode from one speed to the next.
  std::vector<std::complex<double>> energy_vector;
  /// The mode's largest groups, e.g. "wheelset lateral/yaw 0.52, frame lateral 0.45".
  [[nodiscard]] std::string shape() const;
};

/// |a^H b|^2 of two energy vectors (1: the same shape, 0: orthogonal in kinetic energy).
[[nodiscard]] double shape_correlation(const Mode& a, const Mode& b);

/// Class from the participation (shares of the DofGroups):
///   track          the track's share >= kDominantShare;
///   else the largest of: lateral = wheelset lateral/yaw + frame lateral + car-body lateral,
///   contact = wheelset vertical/roll, longitudinal = wheelset longitudinal/spin, vertical =
///   frame vertical + car-body vertical; where the lateral energy is the largest the mode is
///   hunting when the wheelsets carry at least kHuntingWheelsetShare of it, else body;
///   vertical is body.
[[nodiscard]] ModeClass classify_mode(const std::array<double, kDofGroups>& participation);

/// Modes of the system linearised at (t, x_eq) by central differences, sorted by increasing
/// damping ratio (least damped first). Eigenvalues with |lambda| < 1e-9 /s (neutral rigid-body
/// modes) are left out. With a shape input (one entry per state), each mode carries its
/// participation and class.
[[nodiscard]] std::vector<Mode> linear_modes(const OdeSystem& system, double t,
                                             std::span<const double> x_eq,
                                             const ModeShapeInput& shapes = {});

/// Modes with |damping ratio| below this are treated as neutral: undamped structural modes (a
/// wheelset bouncing on the Hertz contact stiffness without contact damping) whose computed
/// damping is numerical noise of either sign. They are never taken as the least damped mode
/// and never flag an instability; a mode becoming unstable must pass -kNeutralDamping.
inline constexpr double kNeutralDamping = 1e-3;

/// Builds the system at a given speed [m/s].
using SystemAtSpeed = std::function<std::unique_ptr<OdeSystem>(double speed)>;

struct SweepPoint {
  double speed = 0.0;  ///< [m/s]
  Mode least_damped;   ///< least damped non-neutral mode at that speed, of any class
  /// Least damped non-neutral mode of each class at that speed (index by ModeClass; a class
  /// without a mode has frequency and damping NaN). Only with shape input.
  std::array<Mode, 6> least_damped_of{};
  [[nodiscard]] const Mode& of(ModeClass c) const {
    return least_damped_of[static_cast<std::size_t>(c)];
  }
  /// The hunting mode: the hunting-class mode followed down from the sweep's highest speed
  /// (where it is the least damped one, the mode that crosses first) by the largest shape
  /// correlation with the speed above. Only with shape input.
  Mode hunting;
  /// Shape correlation of `hunting` with the hunting mode of the speed above (1 at the top);
  /// below kShapeTracked the branch was lost and `hunting` restarted as the least damped
  /// hunting-class mode.
  double hunting_correlation = NAN;
};

/// Shape correlation below which a mode is not taken for the same mode at the next speed [-].
inline constexpr double kShapeTracked = 0.5;

/// A system at one speed and the state it is linearised about (its equilibrium at that speed),
/// with the shape input of its states (empty: modes unclassified).
struct Linearisation {
  std::unique_ptr<OdeSystem> system;
  std::vector<double> x_eq;
  ModeShapeInput shapes;
};
/// Builds the system at a given speed [m/s] with its equilibrium at that speed.
using LinearisationAtSpeed = std::function<Linearisation(double speed)>;

/// Least damped non-neutral mode at each speed, of each class, and the hunting mode followed
/// over the speeds (see SweepPoint).
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
/// to a relative width `rel_tol`. When the family gives shape input, only hunting modes count
/// (the Hopf speed of the hunting motion; a contact or track mode crossing is no hunting).
/// Empty when no crossing is found.
[[nodiscard]] std::optional<double> critical_speed(const LinearisationAtSpeed& family, double v_min,
                                                   double v_max, int scan_points = 64,
                                                   double rel_tol = 1e-10);
/// The same about one state x_eq at every speed.
[[nodiscard]] std::optional<double> critical_speed(const SystemAtSpeed& factory, double v_min,
                                                   double v_max, std::span<const double> x_eq,
                                                   int scan_points = 64, double rel_tol = 1e-10);

}  // namespace ferro::vehicle
