// Imported one-point contact table (Cooperrider wagon, data/cooperrider_wagon/): rows reproduced
// at the knots, the natural spline against an independent solve, the normal law at the quasi-static state and under a pure
// vertical drop, left/right mirror symmetry, range and input errors.

#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "ferro/contact/geometry/imported_contact_table.hpp"
#include "ferro/contact/geometry/point_normal_contact.hpp"

namespace fc = ferro::contact;

namespace {

const std::string kTable = std::string(FERRO_DATA_DIR) +
                           "/cooperrider_wagon/contact_table_s1002_uic60_1in40.csv";
constexpr double kEstar = 1.0;  // not used by reference-state points

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = std::string(FERRO_BINARY_DIR) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(imported_contact_table, reproduces_the_rows_at_the_knots) {
  // At a knot the natural cubic spline equals the row value exactly (a = 1, b = 0 in the
  // segment formula); the right wheel at pose.lateral = y reads the row at y (file frame -y).
  const fc::ImportedContactTable t(kTable);
  const std::vector<double>& y = t.lateral();
  ASSERT_EQ(y.size(), 3402u);
  for (std::size_t i = 0; i < y.size(); i += 97) {
    for (int c = 1; c < 12; ++c) {
      EXPECT_EQ(t.column(c, y[i]), t.column_values(c)[i]) << "row " << i << " column " << c;
    }
    if (std::abs(y[i]) > t.lateral_limit()) continue;
    const fc::WheelRailContact r = t.wheel_point(fc::WheelsetPose{y[i], 0.0, 0.0, 0.0},
                                                 fc::Side::right);
    EXPECT_EQ(r.ref_normal_force, t.column_values(1)[i]);
    EXPECT_EQ(r.contact_angle, t.column_values(2)[i]);
    EXPECT_EQ(r.rolling_radius, t.column_values(6)[i]);
    EXPECT_EQ(r.c23, t.column_values(9)[i]);
    EXPECT_EQ(r.penetration, t.column_values(11)[i]);
  }
}

TEST(imported_contact_table, natural_spline_against_an_independent_solve) {
  // Independent natural cubic spline: the moment equations (h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i)
  // M_i + h_i M_{i+1} = 6 (slope_i - slope_{i-1}), M_0 = M_n = 0) solved by Eigen's sparse LU,
  // evaluated at every segment midpoint. Tolerance: 1e-9 of the column's range (rounding of two
  // O(n) solves of a diagonally dominant system).
  const fc::ImportedContactTable t(kTable);
  const std::vector<double>& y = t.lateral();
  const int n = static_cast<int>(y.size());
  for (const int c : {1, 2, 6, 11}) {
    const std::vector<double>& v = t.column_values(c);
    Eigen::SparseMatrix<double> m(n, n);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    std::vector<Eigen::Triplet<double>> trip;
    trip.emplace_back(0, 0, 1.0);
    trip.emplace_back(n - 1, n - 1, 1.0);
    for (int i = 1; i + 1 < n; ++i) {
      const double h0 = y[i] - y[i - 1], h1 = y[i + 1] - y[i];
      trip.emplace_back(i, i - 1, h0);
      trip.emplace_back(i, i, 2.0 * (h0 + h1));
      trip.emplace_back(i, i + 1, h1);
      rhs[i] = 6.0 * ((v[i + 1] - v[i]) / h1 - (v[i] - v[i - 1]) / h0);
    }
    m.setFromTriplets(trip.begin(), trip.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(m);
    const Eigen::VectorXd mom = lu.solve(rhs);
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    const double tol = 1e-9 * (*hi - *lo);
    for (int i = 0; i + 1 < n; ++i) {
      const double h = y[i + 1] - y[i], ym = 0.5 * (y[i] + y[i + 1]);
      const double ref = 0.5 * (v[i] + v[i + 1]) - h * h / 16.0 * (mom[i] + mom[i + 1]);
      ASSERT_NEAR(t.column(c, ym), ref, tol) << "column " << c << " segment " << i;
    }
  }
}

TEST(imported_contact_table, normal_law_at_the_quasi_static_state_and_under_a_drop) {
  // y = 0, no drop, no roll: dq = 0 so N = N0(0) = 66661.24 N (README) on both wheels.
  // A pure drop v (down) adds v cos(delta) along each normal: N = N0 (1 + v cos(delta)/q0)^1.5.
  const fc::ImportedContactTable t(kTable);
  std::vector<fc::WheelRailContact> out;
  t.contacts(fc::WheelsetPose{0.0, 0.0, 0.0, 0.0}, out);
  ASSERT_EQ(out.size(), 2u);
  for (const auto& c : out) {
    const fc::ContactPatch p = fc::hertz_patch_from_penetration(c, kEstar);
    EXPECT_NEAR(p.normal_force, 66661.24, 0.01);
    EXPECT_NEAR(p.semi_axis_x, c.ref_semi_axis_a, 1e-12);
  }
  const double v = 20e-6;
  t.contacts(fc::WheelsetPose{3e-3, v, 0.0, 0.0}, out);
  ASSERT_EQ(out.size(), 2u);
  for (const auto& c : out) {
    const double delta = c.contact_angle;  // no roll: the table angle
    const double n = c.ref_normal_force * std::pow(1.0 + v * std::cos(delta) / c.ref_penetration,
                                                   1.5);
    const fc::ContactPatch p = fc::hertz_patch_from_penetration(c, kEstar);
    EXPECT_NEAR(p.normal_force / n, 1.0, 1e-12);
    EXPECT_NEAR(p.semi_axis_y / (c.ref_semi_axis_b * std::cbrt(n / c.ref_normal_force)), 1.0,
                1e-12);
  }
  // Lift: raising the wheelset by more than q0 / cos(delta) leaves no point.
  t.contacts(fc::WheelsetPose{0.0, -1e-3, 0.0, 0.0}, out);
  EXPECT_TRUE(out.empty());
}

TEST(imported_contact_table, mirror_symmetry_left_right) {
  // (y, roll) and (-y, -roll) mirror the wheels: same penetration, angle, radius, C_ij; the
  // points mirror in track y. Exact up to rounding (the same spline values are read).
  const fc::ImportedContactTable t(kTable);
  for (const double y : {-12e-3, -3.3e-3, 0.0, 4.1e-3, 8.8e-3, 16.9e-3}) {
    const fc::WheelsetPose a{y, 15e-6, 0.004, 0.0}, b{-y, 15e-6, -0.004, 0.0};
    const fc::WheelRailContact l = t.wheel_point(a, fc::Side::left);
    const fc::WheelRailContact r = t.wheel_point(b, fc::Side::right);
    EXPECT_NEAR(l.penetration, r.penetration, 1e-15) << y;
    EXPECT_NEAR(l.contact_angle, r.contact_angle, 1e-15) << y;
    EXPECT_EQ(l.rolling_radius, r.rolling_radius) << y;
    EXPECT_EQ(l.c22, r.c22) << y;
    EXPECT_NEAR(l.y, -r.y, 1e-15) << y;
  }
  // Flange side: a shift to the right (+y, contact layer) brings the right wheel's flange in.
  const fc::WheelRailContact flange = t.wheel_point({9.0e-3, 0.0, 0.0, 0.0}, fc::Side::right);
  EXPECT_GT(flange.contact_angle, 1.0);
  const fc::WheelRailContact other = t.wheel_point({9.0e-3, 0.0, 0.0, 0.0}, fc::Side::left);
  EXPECT_LT(other.contact_angle, 0.1);
}

TEST(imported_contact_table, range_limit_and_located_input_errors) {
  const fc::ImportedContactTable t(kTable);
  EXPECT_DOUBLE_EQ(t.lateral_limit(), 0.017);
  std::vector<fc::WheelRailContact> out;
  EXPECT_NO_THROW(t.contacts({-0.017, 0.0, 0.0, 0.0}, out));
  EXPECT_THROW(t.contacts({0.0171, 0.0, 0.0, 0.0}, out), std::out_of_range);
  const std::string header =
      "lateral_displacement_m,normal_force_N,contact_angle_rad,semi_axis_a_longitudinal_m,"
      "semi_axis_b_lateral_m,wheel_contact_lateral_position_m,rolling_radius_m,kalker_c11,"
      "kalker_c22,kalker_c23,rail_contact_vertical_position_m,penetration_m,"
      "rail_contact_lateral_position_m\n";
  const std::string row = ",6e4,0.01,6e-3,4e-3,0.75,0.425,5,4.8,2.5,-1e-4,1e-4,0\n";
  const std::string bad = write_file(
      "imported_bad.csv", header + "-2e-3" + row + "-1e-3" + row +
                              "0,6e4,0.01,6e-3,4x-3,0.75,0.425,5,4.8,2.5,-1e-4,1e-4,0\n");
  try {
    fc::ImportedContactTable x(bad);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "imported_bad.csv:4, column 'semi_axis_b_lateral_m': not a number"),
              std::string::npos)
        << e.what();
  }
  const std::string order = write_file("imported_order.csv",
                                       header + "-1e-3" + row + "-2e-3" + row);
  EXPECT_THROW(fc::ImportedContactTable{order}, std::invalid_argument);
  std::remove(bad.c_str());
  std::remove(order.c_str());
}
