// Track-frame kinematics at a given speed.
//
// References: Toumi (2016) eq. (148); EN 13803:2017 §6 (cant deficiency).
// Known deviations: see kinematics.hpp (eq. 148 is the small-angle balance).

#include "ferro/track/kinematics.hpp"

#include <cmath>
#include <limits>

namespace ferro::track {

FrameKinematics frame_kinematics(const TrackFrame& frame, double speed, double acceleration,
                                 double gravity) {
  FrameKinematics k;
  k.speed = speed;
  k.acceleration = acceleration;
  const double sp = std::sin(frame.cant_angle), cp = std::cos(frame.cant_angle);
  const Eigen::Vector3d w = frame.angular_rate_per_length(sp, cp);
  const Eigen::Vector3d dw = frame.d_angular_rate_per_length(sp, cp);
  k.angular_velocity = speed * w;
  // d/dt (V w(s)) = dV/dt w + V^2 dw/ds.
  k.angular_acceleration = acceleration * w + speed * speed * dw;
  // Origin acceleration in ground axes: dV/dt t + V^2 k n_horizontal; in track axes the
  // horizontal normal is (0, cos phi, sin phi).
  const double centripetal = speed * speed * frame.curvature;
  k.origin_acceleration = {acceleration, centripetal * cp, centripetal * sp};
  // Gravity (0, 0, -g) in track axes is -g (0, -sin phi, cos phi).
  k.specific_force = k.origin_acceleration + gravity * Eigen::Vector3d(0.0, -sp, cp);
  k.yaw_rate = speed * frame.curvature;
  k.roll_rate = -speed * frame.d_cant_angle;
  k.uncompensated_lateral_acceleration = k.specific_force.y();
  k.cant_deficiency = frame.rail_spacing * centripetal / gravity - frame.cant;
  return k;
}

double balance_cant(double curvature, double speed, double rail_spacing, double gravity) {
  return rail_spacing * speed * speed * curvature / gravity;
}

double balance_cant_exact(double curvature, double speed, double rail_spacing, double gravity) {
  return rail_spacing * std::sin(std::atan(speed * speed * curvature / gravity));
}

double balance_speed(const TrackFrame& frame, double gravity) {
  const double ratio = std::tan(frame.cant_angle) / frame.curvature;
  if (!(frame.curvature != 0.0) || !(ratio >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return std::sqrt(gravity * ratio);
}

}  // namespace ferro::track
