#pragma once
// The one boundary between the vehicle/track frame (x forward, y LEFT, z UP) and the contact
// layer's frame (x forward, y RIGHT, z DOWN, SIMPACK / Manchester convention). The two frames
// differ by a half turn about x: y -> -y, z -> -z. A rotation vector keeps its x component and
// changes the sign of its y and z components, so roll keeps its sign (positive roll raises the
// left wheel = lowers the right wheel in both) and yaw changes sign (nose left in the vehicle
// frame = front to the left, negative in the contact frame).
//
// References: docs/DESIGN.md "Frames"; contact/geometry/wheel_rail_geometry.hpp (contact frame).
// Known deviations: none (exact change of axes).

#include <Eigen/Core>
#include <cmath>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::vehicle {

/// Wheelset pose relative to the two rails in the vehicle frame.
struct RailRelativePose {
  double lateral = 0.0;  ///< axle-centre shift, + left [m]
  double height = 0.0;   ///< axle-centre height above its nominal height r0 over the rails [m]
  double roll = 0.0;     ///< about x [rad], + raises the left wheel
  double yaw = 0.0;      ///< about z up [rad], + turns the front to the left
};

/// The same pose in the contact layer's terms.
[[nodiscard]] inline contact::WheelsetPose to_contact_pose(const RailRelativePose& p) {
  contact::WheelsetPose c;
  c.lateral = -p.lateral;
  c.vertical = -p.height;
  c.roll = p.roll;
  c.yaw = -p.yaw;
  return c;
}

/// A point or free vector given in the contact frame, in the vehicle frame.
[[nodiscard]] inline Eigen::Vector3d from_contact_frame(double x, double y, double z) {
  return {x, -y, -z};
}

/// Unit normal of the rail surface (pointing from the rail into the wheel) at a contact point
/// of `side` with contact angle `angle` (+ leaning towards the track centre), vehicle frame.
[[nodiscard]] inline Eigen::Vector3d rail_normal(contact::Side side, double angle) {
  const double towards_centre = side == contact::Side::left ? -1.0 : 1.0;
  return {0.0, towards_centre * std::sin(angle), std::cos(angle)};
}

}  // namespace ferro::vehicle
