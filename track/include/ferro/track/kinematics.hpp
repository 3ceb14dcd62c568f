#pragma once
// Kinematics of the track frame carried along the design track by a vehicle at speed V and
// acceleration dV/dt: angular velocity and acceleration, acceleration of the frame origin and
// the specific force (acceleration minus gravity) in track axes, hence the uncompensated
// lateral acceleration in the cant plane and the cant deficiency.
//
// References: Toumi (2016) eq. (148) balance cant D = 2 e V^2 / (R g); EN 13803:2017 §6
// (cant deficiency I = b V^2 / (R g) - D, i.e. 11.8 V^2/R - D in mm and km/h for b = 1500 mm).
// Known deviations: eq. (148) is the small-angle form. The frame's lateral specific force is
// exact, a_y = V^2 k cos(phi) - g sin(phi), so with the cant of eq. (148) (sin phi = V^2 k / g)
// it leaves -V^2 k (1 - cos phi), about 0.4 % of V^2 k at phi = 0.09 rad; the exact balance is
// tan(phi) = V^2 k / g (balance_cant_exact()).

#include <Eigen/Core>

#include "ferro/track/alignment.hpp"

namespace ferro::track {

inline constexpr double kStandardGravity = 9.80665;  ///< [m/s^2]

/// Motion of the track frame at one instant, everything in track axes unless said otherwise.
struct FrameKinematics {
  double speed = 0.0;                                              ///< V [m/s]
  double acceleration = 0.0;                                       ///< dV/dt [m/s^2]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();      ///< [rad/s]
  Eigen::Vector3d angular_acceleration = Eigen::Vector3d::Zero();  ///< [rad/s^2]
  /// Acceleration of the frame origin (centreline point) [m/s^2].
  Eigen::Vector3d origin_acceleration = Eigen::Vector3d::Zero();
  /// Specific force = origin acceleration - gravity [m/s^2]; y is the uncompensated lateral
  /// acceleration, z the acceleration normal to the cant plane.
  Eigen::Vector3d specific_force = Eigen::Vector3d::Zero();
  double yaw_rate = 0.0;   ///< V * curvature, about ground z [rad/s]
  double roll_rate = 0.0;  ///< -V * d(cant_angle)/ds, about the track x axis [rad/s]
  /// Uncompensated lateral acceleration in the cant plane, V^2 k cos(phi) - g sin(phi) [m/s^2];
  /// positive towards +y (the centre of a left-hand curve): what the wheel-rail forces must
  /// supply, felt by passengers as an outward push.
  double uncompensated_lateral_acceleration = 0.0;
  /// Cant deficiency (EN 13803, linearised): b V^2 k / g - cant [m], signed like the curvature.
  double cant_deficiency = 0.0;
};

/// Kinematics of `frame` travelled at `speed` (> 0 forwards) with `acceleration` = dV/dt.
[[nodiscard]] FrameKinematics frame_kinematics(const TrackFrame& frame, double speed,
                                               double acceleration = 0.0,
                                               double gravity = kStandardGravity);

/// Eq. (148): balance cant D = 2e V^2 / (R g) = rail_spacing V^2 curvature / g [m] (signed).
[[nodiscard]] double balance_cant(double curvature, double speed, double rail_spacing,
                                  double gravity = kStandardGravity);
/// Exact balance cant for the banked frame: rail_spacing * sin(atan(V^2 curvature / g)) [m].
[[nodiscard]] double balance_cant_exact(double curvature, double speed, double rail_spacing,
                                        double gravity = kStandardGravity);
/// Speed at which the uncompensated lateral acceleration vanishes for this frame,
/// sqrt(g tan(phi) / curvature) [m/s]; NaN if curvature is zero or of the other sign.
[[nodiscard]] double balance_speed(const TrackFrame& frame, double gravity = kStandardGravity);

}  // namespace ferro::track
