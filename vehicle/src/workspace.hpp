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

/// Scratch of the wheel-rail stage.
struct WheelRailScratch {
  std::vector<contact::WheelRailContact> points;
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
