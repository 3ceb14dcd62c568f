// Multi-point contact table (S1002 / UIC60 1:40, Manchester pair) against the online search
// at poses off the grid nodes; two-point contact (tread + flange on one wheel) found by both;
// HDF5 round trip; range errors.

#include <gtest/gtest.h>

#include "a22_pair.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "ferro/contact/geometry/contact_sources.hpp"

namespace fc = ferro::contact;

namespace {

const std::string kData = FERRO_DATA_DIR;

// Table vs search, two tiers. Typical points: along a branch the gap is interpolated to third
// order with its exact gradient and the geometry linearly over 0.1 mm x 1 mrad cells: 95 % of the
// deepest points per wheel agree within 1 um in penetration and 0.5 mm in position (measured
// 0.74 um / 0.48 mm). Every point: where the contact point races along the flange root (up to
// ~7 mm per cell) a branch is cut rather than averaged across a jump, so a point may sit up to
// 2 kBranchMatch + a cell's motion from the search's: 10 um, 3 mm, 0.25 rad (measured 7.1 um,
// 2.4 mm, 0.21 rad). A table point is never further than that from a real one (no fake point).
// Where a submerged barrier joins candidates into one run, the members share the run's depth
// through the barrier (share_joined_runs), which the table interpolates with its own gradient:
// the typical tier is 1.5 um (measured 1.26 um). A branch born inside a cell is absent from the
// table until the cell's half-weight point; a wheel whose member count differs for that reason
// is counted, not compared point by point: at most kMembershipShare of the wheels (measured
// 1 of 400).
constexpr double kTypicalPenetrationTol = 1.5e-6;  // [m], 95th percentile
constexpr double kMembershipShare = 0.01;
constexpr double kTypicalPositionTol = 0.5e-3;     // [m], 95th percentile
constexpr double kPenetrationTol = 10.0e-6;        // [m], every point
constexpr double kPositionTol = 3.0e-3;            // [m], every point
constexpr double kAngleTol = 0.25;                 // [rad], every point

using ferro::test::a22_pair;

const fc::MultiPointContactTable& a22_table() {
  static const fc::MultiPointContactTable t = [] {
    fc::MultiPointTableParams tp;
    tp.lateral_min = -4e-3;
    tp.lateral_max = 10e-3;
    tp.lateral_step = 0.1e-3;
    tp.roll_min = -0.006;
    tp.roll_max = 0.006;
    tp.roll_step = 1e-3;
    return fc::MultiPointContactTable::build(*a22_pair(), tp);
  }();
  return t;
}

int count_on(const std::vector<fc::WheelRailContact>& v, fc::Side side) {
  return static_cast<int>(std::count_if(v.begin(), v.end(),
                                        [&](const fc::WheelRailContact& c) { return c.side == side; }));
}

// Every point of `a` deeper than kPenetrationTol has a partner in `b` (same wheel, nearest in
// wheel_y) within the every-point tolerances; wheels whose member count differs are skipped and
// counted in `membership_differs`.
void expect_matched(const std::vector<fc::WheelRailContact>& a,
                    const std::vector<fc::WheelRailContact>& b, const std::string& what,
                    int* membership_differs = nullptr) {
  for (const fc::Side side : {fc::Side::left, fc::Side::right}) {
    if (membership_differs && count_on(a, side) != count_on(b, side)) ++*membership_differs;
  }
  for (const fc::WheelRailContact& p : a) {
    if (membership_differs && count_on(a, p.side) != count_on(b, p.side)) continue;
    if (p.penetration < kPenetrationTol) continue;
    const fc::WheelRailContact* best = nullptr;
    for (const fc::WheelRailContact& q : b) {
      if (q.side != p.side) continue;
      if (!best || std::abs(q.wheel_y - p.wheel_y) < std::abs(best->wheel_y - p.wheel_y)) {
        best = &q;
      }
    }
    ASSERT_NE(best, nullptr) << what << ": no point on that wheel";
    EXPECT_NEAR(best->penetration, p.penetration, kPenetrationTol) << what;
    EXPECT_NEAR(best->y, p.y, kPositionTol) << what;
    EXPECT_NEAR(best->wheel_y, p.wheel_y, kPositionTol) << what;
    EXPECT_NEAR(best->contact_angle, p.contact_angle, kAngleTol) << what;
  }
}

// The deepest point of wheel `side` (nullptr when none).
const fc::WheelRailContact* deepest(const std::vector<fc::WheelRailContact>& v, fc::Side side) {
  const fc::WheelRailContact* d = nullptr;
  for (const auto& c : v) {
    if (c.side == side && (!d || c.penetration > d->penetration)) d = &c;
  }
  return d;
}

double percentile95(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(0.95 * static_cast<double>(v.size() - 1))];
}

}  // namespace

TEST(multi_point_contact_table, agrees_with_the_online_search_off_the_grid) {
  const auto pair = a22_pair();
  const fc::SearchContactSource search(pair);
  const fc::MultiPointContactTable& table = a22_table();
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> lat(-3.9e-3, 9.9e-3), roll(-0.0055, 0.0055),
      depth(20e-6, 120e-6);
  std::vector<fc::WheelRailContact> a, b;
  std::vector<double> pen_err, pos_err;
  int points = 0, wheels = 0, membership_differs = 0;
  for (int n = 0; n < 200; ++n) {
    fc::WheelsetPose pose{lat(rng), 0.0, roll(rng), 0.0};
    pose = fc::touching_pose(*pair, pose);
    pose.vertical += depth(rng);
    search.contacts(pose, a);
    table.contacts(pose, b);
    const std::string what = "y " + std::to_string(pose.lateral) + " roll " +
                             std::to_string(pose.roll);
    expect_matched(a, b, "search->table " + what, &membership_differs);
    int counted_once = 0;  // the same wheels as above
    expect_matched(b, a, "table->search " + what, &counted_once);
    wheels += 2;
    points += static_cast<int>(a.size());
    for (const fc::Side side : {fc::Side::left, fc::Side::right}) {
      const fc::WheelRailContact* p = deepest(a, side);
      const fc::WheelRailContact* q = deepest(b, side);
      if (!p || !q) continue;
      pen_err.push_back(std::abs(p->penetration - q->penetration));
      pos_err.push_back(std::abs(p->y - q->y));
    }
  }
  EXPECT_GT(points, 200);
  EXPECT_LE(membership_differs, kMembershipShare * wheels);
  EXPECT_LT(percentile95(pen_err), kTypicalPenetrationTol);
  EXPECT_LT(percentile95(pos_err), kTypicalPositionTol);
}

TEST(multi_point_contact_table, two_point_contact_found_by_table_and_search) {
  // Manchester case 11 (y = 5 mm, roll -0.3554 mrad, yaw 12 mrad) loaded to 20 kN has two
  // separate interpenetration runs on the right wheel (tread and flange root). A table with a yaw
  // axis around it must report both, each at its own place (no single averaged point between).
  const auto pair = a22_pair();
  const fc::SearchContactSource search(pair);
  fc::MultiPointTableParams tp;
  tp.lateral_min = 4.5e-3;
  tp.lateral_max = 5.5e-3;
  tp.roll_min = -0.002;
  tp.roll_max = 0.001;
  tp.yaw_min = 0.010;
  tp.yaw_max = 0.014;
  tp.yaw_step = 0.002;
  const fc::MultiPointContactTable table = fc::MultiPointContactTable::build(*pair, tp);
  const double estar = 2.0 * 82.0e9 * 1.28 / (2.0 * (1.0 - 0.28 * 0.28));
  for (const double dy : {0.0, 0.037e-3, -0.061e-3}) {  // on and off the grid nodes
    const fc::LoadedWheelset lw = fc::solve_vertical_load(
        *pair, fc::WheelsetPose{5.0e-3 + dy, 0.0, -0.00035540, 0.0120}, 20000.0, estar);
    std::vector<fc::WheelRailContact> a, b;
    search.contacts(lw.pose, a);
    table.contacts(lw.pose, b);
    int right_search = 0, right_table = 0;
    for (const auto& p : a) right_search += p.side == fc::Side::right ? 1 : 0;
    for (const auto& p : b) right_table += p.side == fc::Side::right ? 1 : 0;
    EXPECT_EQ(right_search, 2) << "dy " << dy;
    EXPECT_EQ(right_table, 2) << "dy " << dy;
    expect_matched(a, b, "two-point search->table");
    expect_matched(b, a, "two-point table->search");
  }
}

TEST(multi_point_contact_table, hdf5_round_trip_and_range_errors) {
  const fc::MultiPointContactTable& table = a22_table();
  const std::string path = std::string(FERRO_BINARY_DIR) + "/multi_point_table_test.h5";
  table.save_hdf5(path);
  const fc::MultiPointContactTable back = fc::MultiPointContactTable::load_hdf5(path);
  EXPECT_EQ(back.node_count(), table.node_count());
  EXPECT_EQ(back.candidate_count(), table.candidate_count());
  std::vector<fc::WheelRailContact> a, b;
  for (double y = -3.5e-3; y < 9.5e-3; y += 0.37e-3) {
    const fc::WheelsetPose pose{y, 0.3e-3, 0.001, 0.0};
    table.contacts(pose, a);
    back.contacts(pose, b);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].penetration, b[i].penetration);
      EXPECT_EQ(a[i].y, b[i].y);
    }
  }
  std::remove(path.c_str());
  EXPECT_THROW(table.contacts(fc::WheelsetPose{12e-3, 0.0, 0.0, 0.0}, a), std::out_of_range);
  EXPECT_THROW(table.contacts(fc::WheelsetPose{0.0, 0.0, 0.01, 0.0}, a), std::out_of_range);
  EXPECT_THROW((void)fc::MultiPointContactTable::load_hdf5(kData + "/profiles/MBench_S1002_v3.prw"),
               std::invalid_argument);
}
