#pragma once
// The whole-vehicle multibody model: rigid bodies (car body, bogie frames, wheelsets) with up to
// six degrees of freedom each relative to a track frame that travels along the alignment,
// suspension elements between attachment points, and the wheel-rail coupling at every contact
// point a ContactGeometrySource returns, with a registered tangential (creep-force) model.
// One model serves the whole vehicle, one bogie or one wheelset (ModelSelection).
//
// Frames (docs/DESIGN.md "Frames"): x forward, y LEFT, z UP. Every body i has its own track
// frame F_i at arc length s_i = s_ref(t) + X_i (X_i its rest x position, s_ref the reference
// point's arc length); its displacements x, y, z are those of its centre of mass from the rest
// position (0, Y_i, Z_i) in F_i, its angles roll, pitch, yaw are rotations about F_i's x, y, z
// axes (attitude R = Rz(yaw) Ry(pitch) Rx(roll)). The contact layer's frame (y right, z down)
// is met at exactly one place, frames.hpp.
//
// State layout. Bodies are ordered by decreasing rest x (front first), so that bodies coupled
// by suspension are neighbours in the state (banded Jacobian). Each dynamic body contributes
// one contiguous block:
//   [active positions in the order x, y, z, roll, pitch, yaw][their rates][spin perturbation]
// followed by the internal deflection of every series damper whose upper body it is. Names:
// "wheelset_1.y" [m], "wheelset_1.y_dot" [m/s], "wheelset_1.spin" [rad/s] (perturbation beta of
// the spin speed V/r0 + beta), "<element>.damper_deflection" [m]. A wheelset has no pitch state
// (its rotation about the axle is the spin). Frozen DOF and bodies outside the selection have no
// state and stay at rest in their own track frame.
//
// Equations of motion (each body, in the axes of its track frame F_i, frame kinematics from
// track::frame_kinematics at s_i with the speed V(t) and dV/dt):
//   m (u'' + a_O + alpha x r + w x (w x r) + 2 w x u') = F + m g            (r = rest + u)
//   I (alpha + theta'' + w x theta') + w_h x (I w_h + I_y s e_y) + I_y s' e_y = M
// with w, alpha the frame's angular velocity and acceleration, a_O its origin acceleration,
// w_h = w + theta' the rate of the body axes without spin, s the wheelset spin speed (0 for
// other bodies), giving the gyroscopic couplings +I_y s yaw' in roll and -I_y s roll' in yaw.
//
// Suspension forces: the attachment points are placed in the ground frame from each body's own
// track frame (exact frame positions and rotations, exact attitude rotation), their relative
// position is expressed in the track frame of body_a, and the deflection is its change from the
// straight-track rest geometry. In a curve the car body and bogie frames therefore see the
// versine and the relative yaw of their frames as suspension deflection, as they physically do.
//
// Wheel-rail coupling (per wheelset, per contact point):
//   - the pose relative to the rails (track irregularities at s_i included: lateral alignment
//     y_irr, vertical level z_irr, cross-level c giving a rail roll -c / rail_spacing, and the
//     alignment slope giving a rail yaw) is converted once (frames.hpp) to contact::WheelsetPose;
//   - normal force from the penetration by Hertz (semi-axes from the same solution), optionally
//     times (1 + alpha d(penetration)/dt) (Hunt-Crossley, clamped at >= 0); a point with zero
//     penetration or force is skipped (no tangential model call);
//   - creepages from the exact velocity of the wheel material point and the absolute angular
//     velocity of the wheelset (frame rotation, body rates, spin), relative to the rail at
//     rest in the ground, divided by max(|V|, regularisation_speed);
//   - tangential forces from contact::make_tangential_model(name, options) with K_ij constants,
//     in the contact frame (x along the rail, z the rail->wheel normal, y = z x x);
//   - forces and moments are applied to the wheelset in the axes of its track frame.
//
// Signals (signal_info() lists them with units): per wheelset i (1-based, front first) and side
// (left = +y):
//   wheelset_i.<side>.Y [N]           lateral force of the rail on the wheel in track axes,
//                                     POSITIVE TOWARDS THE TRACK CENTRE (-y on the left wheel,
//                                     +y on the right): the Y of Nadal's Y/Q for flange contact
//   wheelset_i.<side>.Q [N]           vertical force of the rail on the wheel, + up (wheel load)
//   wheelset_i.<side>.normal_force [N]  sum of the normal forces of the wheel's points
//   wheelset_i.<side>.creepage_x [-], .creepage_y [-], .spin [1/m]: creepages of the point with
//                                     the largest normal force, contact frame (x along the
//                                     rail, y = n x x with n the rail->wheel normal)
//   wheelset_i.<side>.contact_y [m]   lateral position of that point relative to the rail's
//                                     nominal reference point (+- rail_spacing/2), + towards the
//                                     field side (outwards)
//   wheelset_i.<side>.contact_angle [rad]  of that point, + when the normal leans towards the
//                                     track centre (flange contact ~ +1.2 rad)
//   wheelset_i.<side>.points [-]      number of contact points carrying load
//   wheelset_i.<side>.point_k.normal_force [N]  of the first three loaded points (source order)
//   wheelset_i.<side>.in_contact [-]  1 with a loaded point, 0 lifted
//   wheelset_i.<side>.creep_force_x, .creep_force_y [N], .spin_moment [N m], .wear_number [N]:
//                                     tangential forces on the wheel in each point's contact
//                                     frame, moment about its normal, T gamma = Tx cx + Ty cy
//                                     (T the creep force on the rail, c the creepages: the
//                                     frictional energy per metre rolled without the spin
//                                     term, slightly negative where spin dominates), summed
//   wheelset_i.<side>.rolling_radius, .contact_wheel_y, .contact_rail_y [m], .semi_axis_a,
//                                     .semi_axis_b [m], .peak_pressure [Pa]: of the most loaded
//                                     point (places in profile coordinates)
//   wheelset_i.<side>.point_k.{creep_force_x, creep_force_y, spin_moment, wear_number,
//                                     contact_angle, rolling_radius, wheel_y, rail_y,
//                                     peak_pressure}: the same per loaded point (with
//                                     OutputSignalsSpec::contact_point_details)
//   wheelset_i.rolling_radius_difference [m]  left minus right, most loaded points
//   wheelset_i.angle_of_attack [rad]  the wheelset's yaw relative to its rails' actual direction
//                                     (irregularities and rail deflection included)
//   Undefined quantities of a lifted wheel (no loaded point) read 0 (forces, places, angles,
//   radii; the rolling-radius difference of a wheelset with a lifted wheel): in_contact tells;
//   sources without profiles (conical, imported) give 0 profile coordinates.
//   car_body.ay [m/s^2]               lateral acceleration an accelerometer fixed to the car
//                                     body's centre of mass reads (non-gravitational force / m
//                                     in the body's axes; absent when there is no car body)
//   position [m], speed [m/s]         of the reference point (arc length, V)
// With inputs.outputs (OutputSignalsSpec), for each sensor <name>:
//   <name>.ax, .ay, .az [m/s^2]       what an accelerometer fixed to the body at the point
//                                     reads, in body axes: the specific force (acceleration
//                                     minus gravity; az reads +g at rest on level track)
//   <name>.dx, .dy, .dz [m]           displacement of the point from its rest position, axes of
//                                     the body's track frame
// and, with an anti-alias frequency, each wheel's Y and Q and each sensor's accelerations
// through the low-pass (states "<signal>.filter_<k>" and "<signal>.filter_<k>_rate"):
//   wheelset_i.<side>.Y_filtered, .Q_filtered [N], <name>.ax_filtered, ... [m/s^2]
//
// References: Toumi (2016) eqs. (24)-(27) (creepages), (38)-(40) and (150)-(156) (creep forces,
// K_ij, single wheelset); Wickens, "Fundamentals of Rail Vehicle Dynamics" (2003) ch. 2
// (wheelset and bogie equations, gyroscopic terms); Shabana, Zaazaa & Sugiyama, "Railroad
// Vehicle Dynamics" (2008) ch. 6 (track-frame / body coordinates); Iwnicki (1998) Manchester
// benchmarks (element set).
// Known deviations: the relative angular velocity of a body is taken as the rate of its angles
// (small angles: products of angles and angular rates are dropped) and its inertia tensor is
// taken in track axes (diagonal roll/pitch/yaw, not rotated by the body's small angles); the
// attitude itself is the exact rotation. Gauge irregularity is ignored by the contact geometry
// (WheelsetPose has no gauge input; a gauge deviation shifts neither rail). The irregularities
// displace and roll the rails within the design frame (track.hpp) and do not move the body
// frames. Normal contact is undamped unless wheel_rail.hunt_crossley_alpha > 0 (Hunt-Crossley
// damping, wheel_rail.cpp); tangential forces use the Hertz patch of the penetration with that
// normal force. K_ij come from the constants or, with wheel_rail.reduction_table, from the table
// looked up per contact patch.

#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/contact/material.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/track/track.hpp"
#include "ferro/track/track_structure.hpp"
#include "ferro/vehicle/ode_system.hpp"
#include "ferro/vehicle/output_signals.hpp"
#include "ferro/vehicle/vehicle_config.hpp"

namespace ferro::vehicle {

/// v(t) = max(0, initial + acceleration * t) [m/s].
struct SpeedProfile {
  double initial = 0.0;       ///< [m/s]
  double acceleration = 0.0;  ///< [m/s^2]
  [[nodiscard]] double speed(double t) const;
  /// dV/dt at t (0 once the speed has reached zero) [m/s^2].
  [[nodiscard]] double rate(double t) const;
  /// Distance travelled from t = 0 to t [m].
  [[nodiscard]] double distance(double t) const;
};

struct VehicleModelInputs {
  VehicleConfig config;
  /// What the wheels run on: rigid rails, or a co-running discrete track under every wheelset.
  track::TrackStructureSpec track_structure;
  ModelSelection selection;
  std::shared_ptr<const track::Track> track;                       ///< null: straight, perfect
  std::shared_ptr<const contact::ContactGeometrySource> geometry;  ///< required
  SpeedProfile speed;
  double start_position = 0.0;  ///< arc length of the vehicle reference point (x = 0) at t = 0 [m]
  OutputSignalsSpec outputs;    ///< sensors and anti-alias filters (none by default)
};

namespace detail {
struct ModelData;
struct Workspace;
}  // namespace detail

/// The model as an OdeSystem: its read-only data (built and validated once, shareable) and the
/// workspace its evaluations use. One object serves one caller at a time (its workspace is
/// reused by every evaluation); a model evaluated from several threads needs one object per
/// thread.
class VehicleModel final : public OdeSystem {
 public:
  /// Validates everything (std::invalid_argument naming the field, e.g.
  /// "bodies[2].mass: must be > 0 kg") and builds the tangential model and workspace.
  explicit VehicleModel(VehicleModelInputs inputs);
  ~VehicleModel() override;
  VehicleModel(const VehicleModel&) = delete;
  VehicleModel& operator=(const VehicleModel&) = delete;

  [[nodiscard]] std::size_t size() const override;
  /// Only a pose outside the contact geometry's range or the designed track
  /// (std::out_of_range) and a non-finite derivative of a trial state are recoverable; any
  /// other failure is fatal.
  int rhs(double t, std::span<const double> x, std::span<double> xdot) const override;
  [[nodiscard]] std::vector<SignalInfo> state_info() const override;
  [[nodiscard]] std::vector<SignalInfo> signal_info() const override;
  void signals(double t, std::span<const double> x, std::span<double> out) const override;
  /// Half-bandwidths from the coupling structure (suspension elements, contact) and the state
  /// order.
  [[nodiscard]] std::pair<int, int> jacobian_bandwidth() const override;
  /// The anti-alias filters' states (OutputSignalsSpec).
  [[nodiscard]] std::vector<std::size_t> output_states() const override;
  /// 1 for every state but the rates of the co-running track's bodies, which take the natural
  /// frequency of the body on its pads or ballast (sqrt(k / m)) [1/s].
  [[nodiscard]] std::vector<double> tolerance_scales() const override;
  /// A body's states (its block, with its series dampers) act on its own block and those of
  /// the bodies its elements join; a wheelset's co-running track acts on the wheelset's block
  /// alone.
  [[nodiscard]] std::vector<std::vector<int>> jacobian_pattern() const override;

  /// Every body at its rest position, velocities and internal states zero.
  [[nodiscard]] std::vector<double> rest_state() const;
  [[nodiscard]] std::size_t wheelset_count() const;  ///< wheelsets with contact in the model
  /// State index of a body's position DOF (-1 when frozen, absent, or a wheelset's pitch).
  [[nodiscard]] int state_index(const std::string& body, Dof dof) const;
  /// State index of the rate of that DOF (-1 likewise).
  [[nodiscard]] int rate_index(const std::string& body, Dof dof) const;
  [[nodiscard]] const VehicleModelInputs& inputs() const;

  /// The read-only model data and the workspace of this object (vehicle/src/ only).
  [[nodiscard]] const detail::ModelData& data() const { return *data_; }
  [[nodiscard]] detail::Workspace& workspace() const { return *workspace_; }

 private:
  std::shared_ptr<const detail::ModelData> data_;
  std::unique_ptr<detail::Workspace> workspace_;
};

/// Static (steady, at the speed and track position of time t) equilibrium of the model: damped
/// Newton on the accelerations, spin accelerations and series-damper rates with every velocity
/// zero, from the rest state with the wheelsets lowered onto the rails. Numerical Jacobian,
/// minimum-norm steps (weakly determined directions stay near rest); the car body's x is held at
/// rest (it defines the neutral longitudinal position of the whole vehicle). When that Newton
/// does not converge (sharp curves at speed: flange contact, bump stops), continuation in speed:
/// the equilibrium at V = 0 (no creep forces), then the speed raised in adaptive steps, first to
/// wheel_rail.regularisation_speed (the creep forces grow from zero) and then to V(t), each
/// Newton warm-started from the previous step with the same criteria. Throws
/// std::runtime_error when neither converges (the message gives the speed the continuation
/// reached). `start` (size() entries, optional) replaces the rest state as the initial guess of
/// the first Newton (e.g. beyond a bump stop's free play).
[[nodiscard]] std::vector<double> static_equilibrium(const VehicleModel& model, double t = 0.0,
                                                     std::span<const double> start = {});

/// The geometry source a WheelRailSpec asks for (files resolved relative to base_dir).
[[nodiscard]] std::shared_ptr<const contact::ContactGeometrySource> make_geometry_source(
    const WheelRailSpec& spec, const std::string& base_dir);

}  // namespace ferro::vehicle
