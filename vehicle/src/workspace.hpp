#pragma once
// The scratch space of one evaluation of a VehicleModel: body kinematics and force
// accumulators, the contact points of a wheelset, the semi-Hertz patches, the per-wheel results.
// Its contents carry nothing from one evaluation to the next (every stage overwrites what it
// reads); it only keeps the memory, so the right-hand side does not allocate once it has grown.
// One workspace serves one caller at a time: every VehicleModel object owns one, and a model
// used from several threads needs one object per thread.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/contact/geometry/point_normal_contact.hpp"
#include "ferro/contact/normal/semi_hertz.hpp"
#include "ferro/track/kinematics.hpp"
#include "ferro/track/track.hpp"
#include "ferro/track/track_structure.hpp"

namespace ferro::vehicle::detail {

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

/// What one loaded contact point carries (signals; contact frame: x along the rail, y = n x x).
struct PointResult {
  double creep_force_x = 0.0, creep_force_y = 0.0;  ///< tangential force on the wheel [N]
  double spin_moment = 0.0;                         ///< about the normal [N m]
  /// T gamma = -(Fx creepage_x + Fy creepage_y) with F the creep force on the wheel: the
  /// frictional energy per metre rolled, >= 0 [N]
  double wear_number = 0.0;
  double contact_angle = 0.0;   ///< [rad]
  double rolling_radius = 0.0;  ///< [m]
  double wheel_y = 0.0, rail_y = 0.0;  ///< place on the wheel and rail profiles [m]
  double semi_axis_a = 0.0, semi_axis_b = 0.0;  ///< of its largest patch [m]
  double peak_pressure = 0.0;                   ///< [Pa]
};

/// Per-wheel results of the wheel-rail coupling (signals). Quantities undefined on a lifted
/// wheel (no loaded point) stay 0; `points` says whether it touches.
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
  /// Those points' other results (zero where there is no such point).
  std::array<PointResult, kPointSignals> point{};
  /// Sums over every loaded point of the wheel.
  double creep_force_x = 0.0, creep_force_y = 0.0, spin_moment = 0.0, wear_number = 0.0;
  /// The most loaded point's.
  PointResult largest;
  /// The wheelset's yaw relative to this wheel's rail's actual direction (angle of attack)
  /// [rad].
  double angle_of_attack = 0.0;
};

/// What one contact point's patches carry, summed while the wheel-rail stage goes through them.
struct PointTotals {
  PointResult result;
  double largest_patch_force = 0.0;
};

/// Scratch of the wheel-rail stage.
struct WheelRailScratch {
  std::vector<contact::WheelRailContact> points;
  contact::ContactScratch geometry;  ///< the geometry source's buffers
  contact::SemiHertzScratch semi_hertz;
};

struct Workspace {
  std::vector<BodyKinematics> kin;     ///< one per body, model order
  BodyKinematics track_frame;          ///< a suspension element's track-frame end
  WheelRailScratch wheel_rail;
  std::vector<WheelResult> wheels;     ///< signals: 2 per contact body
  /// Per contact body, the wheels' loads on its left and right rail and the rails' pad forces
  /// (flexible track).
  std::vector<std::array<track::RailLoad, 2>> rail_loads;
  std::vector<std::array<track::PadForce, 2>> pad_forces;
};

}  // namespace ferro::vehicle::detail
