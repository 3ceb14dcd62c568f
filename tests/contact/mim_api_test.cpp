// One-call MIM API (Hertz input as a tangential-model adapter gives it) and HDF5 output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/contact/mim/mim.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/io/hdf5.hpp"

using namespace ferro::contact;
using namespace ferro::contact::mim;

// Hertz input a = 5 mm, b = 3 mm, F_n = 50 kN: the normal solve must reproduce the Hertz
// approach of the gap (Johnson eq. 3.64) within 1 % and the area pi a b within 3 % (staircase
// boundary at 30 elements across b), and a micro-creepage must give Kalker's C11 within 5 %
// (single grid, not extrapolated: first-order discretisation error, +2 % measured).
TEST(MimApi, hertz_input_matches_hertz_and_kalker) {
  HertzRollingInput in;
  in.semi_axis_x = 5.0e-3;
  in.semi_axis_y = 3.0e-3;
  in.normal_force = 50.0e3;
  in.rolling = RollingInput{1.0e-6, 0.0, 0.0, 0.3};
  in.body1 = in.body2 = Material::from_young(210.0e9, 0.28);
  in.elements_minor = 30;
  const MimResult r = solve_hertz_rolling(in);
  ASSERT_TRUE(r.converged);
  const CombinedMaterial m = combine(in.body1, in.body2);
  const HertzGap hg = hertz_gap_for_ellipse(5.0e-3, 3.0e-3, 50.0e3, m.contact_modulus);
  EXPECT_NEAR(r.normal_force, 50.0e3, 1.0e-6 * 50.0e3);
  EXPECT_NEAR(r.approach / hg.approach, 1.0, 0.01);
  int contact = 0;
  for (double p : r.pressure) contact += p > 0.0 ? 1 : 0;
  EXPECT_NEAR(contact * r.grid.element_area() / (std::numbers::pi * 15.0e-6), 1.0, 0.03);
  const double c11 = -r.force_x / (m.shear_modulus * 15.0e-6 * 1.0e-6);
  EXPECT_NEAR(c11 / kalker_coefficients_table(5.0e-3, 3.0e-3, 0.28).c11, 1.0, 0.05);
}

TEST(MimApi, input_validation_names_the_field) {
  NormalLoad both;
  both.normal_force = 1.0;
  both.approach = 1.0e-5;
  EXPECT_THROW(both.validate(), std::invalid_argument);
  HertzRollingInput in;  // NaN semi-axes
  try {
    in.validate();
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("semi_axis_x"), std::string::npos);
  }
  EXPECT_THROW((RollingInput{0.0, 0.0, 0.0, -1.0}.validate()), std::invalid_argument);
}

// Round trip through the HDF5 file: datasets and attributes read back bit-exact.
TEST(MimApi, hdf5_round_trip) {
  HertzRollingInput in;
  in.semi_axis_x = 4.0e-3;
  in.semi_axis_y = 4.0e-3;
  in.normal_force = 30.0e3;
  in.rolling = RollingInput{2.0e-3, 0.0, 0.0, 0.3};
  in.body1 = in.body2 = Material::from_young(210.0e9, 0.28);
  in.elements_minor = 16;
  const MimResult r = solve_hertz_rolling(in);
  const std::string path = std::string(FERRO_BINARY_DIR) + "/mim_api_test.h5";
  write_hdf5(r, path);
  std::vector<double> tx;
  double fx = 0.0;
  {
    const ferro::io::H5File file = ferro::io::H5File::open_read(path);
    tx = file.read_array("/traction_x_Pa");
    fx = file.number_attribute("/", "force_x_N");
  }
  ASSERT_EQ(tx.size(), r.grid.size());
  std::remove(path.c_str());
  EXPECT_EQ(fx, r.force_x);
  for (std::size_t i = 0; i < tx.size(); ++i) EXPECT_EQ(tx[i], r.traction_x[i]);
  // A folder that cannot exist (its parent is a file): the error names the file and the cause.
  const std::string bad = std::string(FERRO_SOURCE_DIR) + "/README.md/x.h5";
  EXPECT_THROW(write_hdf5(r, bad), std::runtime_error);
}

// The cached, unit-scaled solver must give the same physics as a direct SI solve on the same grid
// (homogeneity of the half-space kernels; to 1e-6 relative: solver tolerances), and reuse its
// operator for a patch with the same element counts.
TEST(MimApi, hertz_solver_scaling_and_cache) {
  HertzRollingInput in;
  in.semi_axis_x = 6.0e-3;
  in.semi_axis_y = 4.0e-3;
  in.normal_force = 60.0e3;
  in.rolling = RollingInput{1.5e-3, -1.0e-3, 0.8, 0.3};
  in.body1 = Material::from_young(210.0e9, 0.28);
  in.body2 = Material::from_young(190.0e9, 0.30);
  in.elements_minor = 24;

  const CombinedMaterial m = combine(in.body1, in.body2);
  const HertzGap hg =
      hertz_gap_for_ellipse(in.semi_axis_x, in.semi_axis_y, in.normal_force, m.contact_modulus);
  const Grid grid = grid_for_ellipse(in.semi_axis_x, in.semi_axis_y, in.elements_minor);
  InfluenceOperator op(grid, m);
  NormalLoad load;
  load.normal_force = in.normal_force;
  const MimResult direct = solve_rolling_contact(
      op, quadratic_gap(grid, hg.curvature_x, hg.curvature_y), load, in.rolling);

  HertzMimSolver solver;
  const MimResult scaled = solver.solve(in);
  ASSERT_TRUE(direct.converged && scaled.converged);
  const double f = 0.3 * in.normal_force;
  EXPECT_NEAR(scaled.normal_force, direct.normal_force, 1.0e-9 * in.normal_force);
  EXPECT_NEAR(scaled.force_x, direct.force_x, 1.0e-6 * f);
  EXPECT_NEAR(scaled.force_y, direct.force_y, 1.0e-6 * f);
  EXPECT_NEAR(scaled.moment_z, direct.moment_z, 1.0e-6 * f * in.semi_axis_x);
  EXPECT_NEAR(scaled.approach, direct.approach, 1.0e-6 * direct.approach);

  HertzRollingInput bigger = in;  // same shape, 1.5 x larger: same element counts
  bigger.semi_axis_x *= 1.5;
  bigger.semi_axis_y *= 1.5;
  (void)solver.solve(bigger);
  EXPECT_EQ(solver.operators_built(), 1);
}
