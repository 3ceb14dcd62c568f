// The one vehicle <-> contact frame boundary: a lateral shift, a roll and a yaw given in the
// vehicle frame (y left, z up) place the wheelset where the contact layer (y right, z down,
// axle centre at (0, lateral, -r0 + vertical), attitude Rz(yaw) Rx(roll)) puts it, and the
// S1002 / UIC60 contact search sees a leftward shift on the left wheel's flange.
#include "ferro/vehicle/frames.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>

#include "ferro/contact/geometry/profile.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::vehicle {
namespace {

constexpr double kR0 = 0.46;
constexpr double kE = 0.75;
// Exact change of axes: only round-off separates the two routes.
constexpr double kPositionTol = 1e-14;

// Left axle end (vehicle y = +e) placed with the vehicle-frame pose, vehicle frame.
Eigen::Vector3d left_end_vehicle(const RailRelativePose& p) {
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(p.yaw, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(p.roll, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  return Eigen::Vector3d(0.0, p.lateral, kR0 + p.height) + R * Eigen::Vector3d(0.0, kE, 0.0);
}

// The same end placed the contact layer's way from the converted pose, mapped back.
Eigen::Vector3d left_end_via_contact(const RailRelativePose& p) {
  const contact::WheelsetPose c = to_contact_pose(p);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(c.yaw, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(c.roll, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const Eigen::Vector3d q =
      Eigen::Vector3d(0.0, c.lateral, -kR0 + c.vertical) + R * Eigen::Vector3d(0.0, -kE, 0.0);
  return from_contact_frame(q.x(), q.y(), q.z());
}

TEST(Frames, lateral_shift_roll_and_yaw_place_the_axle_alike) {
  const RailRelativePose poses[] = {
      {0.006, 0.0, 0.0, 0.0}, {0.0, 0.0, 0.004, 0.0}, {0.0, 0.0, 0.0, 0.003},
      {-0.004, -1e-4, -0.002, 0.005}};
  for (const auto& p : poses) {
    const Eigen::Vector3d a = left_end_vehicle(p), b = left_end_via_contact(p);
    EXPECT_NEAR((a - b).norm(), 0.0, kPositionTol)
        << "pose " << p.lateral << " " << p.height << " " << p.roll << " " << p.yaw;
  }
  // Physical reading of each: shift left moves the end to +y, positive roll raises the left
  // end, positive yaw (nose left) moves the left end backwards.
  EXPECT_GT(left_end_via_contact({0.006, 0, 0, 0}).y(), kE);
  EXPECT_GT(left_end_via_contact({0, 0, 0.004, 0}).z(), kR0);
  EXPECT_LT(left_end_via_contact({0, 0, 0, 0.003}).x(), 0.0);
}

TEST(Frames, normals_and_points_map_back) {
  // Flange contact on the left wheel: the rail pushes the wheel up and to the right (-y).
  const Eigen::Vector3d n = rail_normal(contact::Side::left, 1.2);
  EXPECT_LT(n.y(), 0.0);
  EXPECT_GT(n.z(), 0.0);
  EXPECT_NEAR(n.norm(), 1.0, 1e-15);
  const Eigen::Vector3d nr = rail_normal(contact::Side::right, 1.2);
  EXPECT_GT(nr.y(), 0.0);
  // A contact-frame point on the right rail (y > 0, 1 mm below top of rail) is at y < 0, z < 0.
  const Eigen::Vector3d p = from_contact_frame(0.01, 0.75, 0.001);
  EXPECT_DOUBLE_EQ(p.x(), 0.01);
  EXPECT_DOUBLE_EQ(p.y(), -0.75);
  EXPECT_DOUBLE_EQ(p.z(), -0.001);
}

TEST(Frames, leftward_shift_brings_the_left_flange_onto_the_rail) {
  contact::WheelRailPairParams params;
  params.track_gauge = 1.435;
  params.flange_back_distance = 1.360;
  params.flange_back_y = -0.070;
  params.nominal_radius = kR0;
  const std::string data = FERRO_DATA_DIR;
  const contact::WheelRailPair pair(
      contact::read_simpack_profile(data + "/profiles/MBench_S1002_v3.prw"),
      contact::read_simpack_profile(data + "/profiles/MBench_UIC60_v3.prr"), params);
  // 7 mm to the left in the vehicle frame closes the left flangeway (about 7 mm for S1002 /
  // UIC60 at 1435 / 1360): the left wheel's touching point is on the flange, the right one on
  // the tread.
  const contact::WheelsetPose pose =
      contact::touching_pose(pair, to_contact_pose({0.0075, 0.0, 0.0, 0.0}));
  const auto left = contact::candidate_points(pair, pose, contact::Side::left);
  const auto right = contact::candidate_points(pair, pose, contact::Side::right);
  EXPECT_GT(contact::deepest_candidate(left).contact_angle, 0.5236);
  EXPECT_LT(contact::deepest_candidate(right).contact_angle, 0.1);
}

}  // namespace
}  // namespace ferro::vehicle
