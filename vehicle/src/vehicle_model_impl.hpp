#pragma once
// Internal data of VehicleModel: the read-only model built in the constructor (bodies, element
// list, state layout, tangential model) and the per-call kinematics scratch. See
// vehicle_model.hpp for the equations and conventions.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/contact/reduction_factors.hpp"
#include "ferro/contact/semi_hertz.hpp"
#include "ferro/track/kinematics.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::vehicle {

/// One body of the configuration with its place in the state.
struct BodyData {
  std::string name;
  BodyKind kind = BodyKind::car_body;
  double mass = 0.0;
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  ///< roll, pitch, yaw [kg m^2]
  Eigen::Vector3d rest = Eigen::Vector3d::Zero();     ///< rest position; x is the frame offset
  double r0 = 0.0;                                    ///< wheelsets: nominal rolling radius [m]
  bool dynamic = false;      ///< has at least one state
  bool has_contact = false;  ///< wheelset in the selection: wheel-rail forces are computed
  std::array<int, 6> q{-1, -1, -1, -1, -1, -1};  ///< position state per DOF
  std::array<int, 6> v{-1, -1, -1, -1, -1, -1};  ///< rate state per DOF
  int spin = -1;                                 ///< spin perturbation state
  int block_begin = 0, block_end = 0;            ///< state range incl. series-damper states
};

struct ElementData {
  SuspensionElementSpec spec;
  int a = -1, b = -1;  ///< indices into Impl::bodies (-1: track frame)
  int state = -1;      ///< series damper internal deflection
  /// Relative position point_b - point_a on straight track at rest, track axes [m].
  Eigen::Vector3d rest_vector = Eigen::Vector3d::Zero();
};

/// Kinematics and force accumulators of one body during one evaluation (track axes of the
/// body's own frame).
struct BodyKinematics {
  track::TrackFrame frame;
  track::FrameKinematics motion;
  track::IrregularitySample irregularity;
  Eigen::Vector3d u = Eigen::Vector3d::Zero(), angles = Eigen::Vector3d::Zero();
  Eigen::Vector3d u_dot = Eigen::Vector3d::Zero(), rates = Eigen::Vector3d::Zero();
  Eigen::Matrix3d attitude = Eigen::Matrix3d::Identity();
  double spin = 0.0;  ///< wheelsets: V/r0 + beta [rad/s]
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
};

/// Per-wheel results of the wheel-rail coupling (signals).
struct WheelResult {
  double lateral_towards_centre = 0.0, vertical = 0.0, normal_force = 0.0;
  double creepage_x = 0.0, creepage_y = 0.0, spin = 0.0;
  double contact_y = 0.0, contact_angle = 0.0;
  double largest_normal_force = 0.0;
  int points = 0;
  /// Normal force of the first kPointSignals loaded points in the geometry source's order, 0
  /// where there is no such point [N].
  static constexpr int kPointSignals = 3;
  std::array<double, kPointSignals> point_normal_force{};
};

struct VehicleModel::Impl {
  VehicleModelInputs in;
  std::vector<BodyData> bodies;  ///< in state order (decreasing rest x)
  std::vector<ElementData> elements;
  std::vector<int> contact_bodies;  ///< bodies with wheel-rail contact, front first
  int car_body = -1;
  std::size_t n_states = 0;
  std::vector<SignalInfo> states, signal_list;
  std::unique_ptr<contact::TangentialModel> tangential;
  contact::Material material;
  double contact_modulus = 0.0;
  contact::ReductionFactors reduction;
  /// K_ij from a table (wheel_rail.reduction_table), looked up per contact patch; empty:
  /// the constants `reduction`.
  std::optional<contact::KijPatchLookup> reduction_table;
  double nominal_rail_spacing = 1.5;
  /// wheel_rail.normal = semi_hertz: the geometry source's profiles, whose gap around each
  /// contact point the semi-Hertz model reads; nullptr: Hertz from the point's curvatures.
  const contact::WheelRailPair* semi_hertz_pair = nullptr;
  contact::SemiHertzOptions semi_hertz_options;

  /// Evaluates the model at (t, x): xdot (may be empty) and, when `wheels` is given, the
  /// per-wheel results (2 per contact body) and the car-body lateral acceleration.
  /// `speed_override` (finite) replaces the speed profile's V(t) (the static equilibrium's
  /// continuation in speed); the track position and dV/dt stay those of t.
  void evaluate(double t, std::span<const double> x, std::span<double> xdot,
                WheelResult* wheels, double* car_body_ay,
                double speed_override = std::numeric_limits<double>::quiet_NaN()) const;

  /// Frame, frame motion and irregularities at arc length s.
  void frame_at(double s, double speed, double rate, BodyKinematics& k, bool irregular) const;
};

/// Suspension element forces and moments added to the bodies' accumulators; series-damper
/// internal rates written into xdot (when not empty).
void apply_element(const VehicleModel::Impl& model, const ElementData& element,
                   std::vector<BodyKinematics>& kin, const BodyKinematics& track_frame_a,
                   std::span<const double> x, std::span<double> xdot);

/// Wheel-rail forces on one wheelset (added to its accumulators) and the per-wheel results.
void apply_wheel_rail(const VehicleModel::Impl& model, const BodyData& body,
                      BodyKinematics& k, WheelResult* left_right);

/// Position and velocity (ground frame) of a point p given in body axes, and its arm from the
/// body's centre in the axes of the body's track frame (the rotated p; (0, p_y, p_z) for the
/// track frame itself, body == nullptr).
void point_state(const BodyData* body, const BodyKinematics& k, const Eigen::Vector3d& p,
                 Eigen::Vector3d& position, Eigen::Vector3d& velocity, Eigen::Vector3d& arm);

}  // namespace ferro::vehicle
