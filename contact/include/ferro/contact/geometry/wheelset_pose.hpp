#pragma once
// The wheelset's pose relative to the rails and the one place its rotation and axle centre are
// computed. Contact-layer track frame: x forward, y lateral to the RIGHT, z DOWN. The wheelset
// frame has the same axes at the axle centre, rotated by roll about x then yaw about z:
// R = Rz(yaw) Rx(roll). The axle centre sits at y = lateral, z = -r0 + vertical (r0 the nominal
// rolling radius), so at zero pose the taping-line circles touch the rail-top level.
//
// References: Shabana, Zaazaa & Sugiyama, "Railroad Vehicle Dynamics" (2008) ch. 4 (wheelset
// coordinates); Shackleton & Iwnicki, VSD 46 (2008) (Manchester benchmark conventions).
// Known deviations: none (data and rigid-body kinematics only).

#include <Eigen/Core>
#include <cmath>

namespace ferro::contact {

/// Wheelset position relative to the track (see the frame description above).
struct WheelsetPose {
  double lateral = 0.0;   ///< axle-centre lateral shift, + to the right [m]
  double vertical = 0.0;  ///< axle-centre drop below the nominal height, + down [m]
  double roll = 0.0;      ///< about track x [rad]; + lowers the right wheel
  double yaw = 0.0;       ///< about track z (down) [rad]; + turns the front to the right
};

enum class Side { left = 0, right = 1 };

/// +1 for the right wheel, -1 for the left one (profiles are read for the right side).
[[nodiscard]] inline double side_sign(Side side) {
  return side == Side::right ? 1.0 : -1.0;
}

/// Rotation R = Rz(yaw) Rx(roll) and axle centre of a wheelset at `pose`, track frame.
struct WheelsetFrame {
  double cos_yaw = 1.0, sin_yaw = 0.0;
  double cos_roll = 1.0, sin_roll = 0.0;
  double centre_y = 0.0;  ///< axle centre, lateral [m]
  double centre_z = 0.0;  ///< axle centre, -r0 + vertical [m]

  WheelsetFrame() = default;
  /// `nominal_radius` [m]: r0, the axle centre's height above the rail-top level at zero pose.
  WheelsetFrame(const WheelsetPose& pose, double nominal_radius)
      : cos_yaw(std::cos(pose.yaw)),
        sin_yaw(std::sin(pose.yaw)),
        cos_roll(std::cos(pose.roll)),
        sin_roll(std::sin(pose.roll)),
        centre_y(pose.lateral),
        centre_z(-nominal_radius + pose.vertical) {}

  [[nodiscard]] Eigen::Vector3d centre() const { return {0.0, centre_y, centre_z}; }
  /// R, whose columns are the wheelset's axes in the track frame.
  [[nodiscard]] Eigen::Matrix3d rotation() const {
    Eigen::Matrix3d r;
    r << cos_yaw, -sin_yaw * cos_roll, sin_yaw * sin_roll,  //
        sin_yaw, cos_yaw * cos_roll, -cos_yaw * sin_roll,   //
        0.0, sin_roll, cos_roll;
    return r;
  }
  /// The axle direction R e_y (towards the right wheel).
  [[nodiscard]] Eigen::Vector3d axle() const {
    return {-sin_yaw * cos_roll, cos_yaw * cos_roll, sin_roll};
  }
  /// R^T (x, y, z): a track-frame vector in wheelset axes.
  void to_wheelset(double x, double y, double z, double& lx, double& ly, double& lz) const {
    const double x1 = cos_yaw * x + sin_yaw * y, y1 = -sin_yaw * x + cos_yaw * y, z1 = z;
    lx = x1;
    ly = cos_roll * y1 + sin_roll * z1;
    lz = -sin_roll * y1 + cos_roll * z1;
  }
  /// A track-frame point in wheelset coordinates (relative to the axle centre).
  [[nodiscard]] Eigen::Vector3d point_to_wheelset(const Eigen::Vector3d& p) const {
    Eigen::Vector3d local;
    to_wheelset(p.x(), p.y() - centre_y, p.z() - centre_z, local.x(), local.y(), local.z());
    return local;
  }
};

}  // namespace ferro::contact
