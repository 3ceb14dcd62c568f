#pragma once
// Creepages: the rigid slip of the wheel relative to the rail at a contact point over the rolling
// speed, in the contact frame; the one definition every caller (the vehicle's wheel-rail
// coupling, the wheelset-contact solver) uses.
//
// Frame: t1 is the rolling direction (the track's x) projected on the tangent plane, n the rail's
// outward normal (from the rail into the wheel), t2 = n x t1; any right-handed caller frame in
// which the track's x is the first axis.
//
// References: Toumi (2016) eqs. (24)-(27) (creepages as the rigid slip of body 1 (wheel)
// relative to body 2 (rail) over the rolling speed; spin from the relative angular velocity along
// the normal); Kalker, "Three-dimensional elastic bodies in rolling contact" (1990) ch. 1.
// Known deviations: none (kinematics only); the rolling speed is the caller's choice (the
// vehicle regularises it at low speed).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace ferro::contact {

struct Creepage {
  double longitudinal = 0.0;  ///< xi_x [-]
  double lateral = 0.0;       ///< xi_y [-]
  double spin = 0.0;          ///< phi [1/m]
};

/// Contact frame at a point (see the file comment), in the caller's frame.
struct ContactFrame {
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX();  ///< rolling direction in the tangent plane
  Eigen::Vector3d t2 = Eigen::Vector3d::UnitY();  ///< n x t1
  Eigen::Vector3d n = Eigen::Vector3d::UnitZ();   ///< normal, rail -> wheel (unit)

  /// The frame of unit normal `normal`: t1 = (e_x - n_x n) / |e_x - n_x n|, t2 = n x t1.
  [[nodiscard]] static ContactFrame from_normal(const Eigen::Vector3d& normal) {
    ContactFrame f;
    f.n = normal;
    f.t1 = Eigen::Vector3d::UnitX() - normal.x() * normal;
    f.t1.normalize();
    f.t2 = normal.cross(f.t1);
    return f;
  }
};

/// Arm from the axle centre to the wheel's material point at a contact: the axial part of
/// `point_from_centre` (the contact point minus the axle centre) along the unit `axle` is kept,
/// the radial part is set to the length `rolling_radius` [m], so that the rolling radius the
/// geometry gives enters the creepages exactly. `down` is the radial direction used when the point
/// lies on the axle line (straight down in the caller's frame).
[[nodiscard]] inline Eigen::Vector3d wheel_point_arm(const Eigen::Vector3d& point_from_centre,
                                                     const Eigen::Vector3d& axle,
                                                     double rolling_radius,
                                                     const Eigen::Vector3d& down) {
  const Eigen::Vector3d axial = point_from_centre.dot(axle) * axle;
  Eigen::Vector3d radial = point_from_centre - axial;
  const double radial_length = radial.norm();
  radial = radial_length > 0.0 ? Eigen::Vector3d(radial / radial_length) : down;
  return axial + rolling_radius * radial;
}

/// Creepages at a contact (Toumi eqs. 24-27), V = `rolling_speed` [m/s] (> 0):
///   xi_x = (v_w - v_r) . t1 / V,  xi_y = (v_w - v_r) . t2 / V,  phi = (w_w - w_r) . n / V,
/// v_w [m/s] the velocity of the wheel's material point at the contact (axle-centre velocity +
/// w_w x wheel_point_arm()), v_r [m/s] that of the rail's material point there (zero for a rail at
/// rest), w_w, w_r [rad/s] the angular velocities of the wheelset and of the rail.
[[nodiscard]] inline Creepage creepage(const Eigen::Vector3d& wheel_point_velocity,
                                       const Eigen::Vector3d& wheel_angular_velocity,
                                       const Eigen::Vector3d& rail_point_velocity,
                                       const Eigen::Vector3d& rail_angular_velocity,
                                       const ContactFrame& frame, double rolling_speed) {
  const Eigen::Vector3d slip = wheel_point_velocity - rail_point_velocity;
  const Eigen::Vector3d relative_rotation = wheel_angular_velocity - rail_angular_velocity;
  Creepage c;
  c.longitudinal = slip.dot(frame.t1) / rolling_speed;
  c.lateral = slip.dot(frame.t2) / rolling_speed;
  c.spin = relative_rotation.dot(frame.n) / rolling_speed;
  return c;
}

}  // namespace ferro::contact
