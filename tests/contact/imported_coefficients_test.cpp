// An imported one-point table's own Kalker coefficients reach the creep forces (the Cooperrider
// wagon's table, data/cooperrider_wagon/: its C_ij were computed by its author, and in the
// flange region they differ by up to 15 % from Kalker's table at the patch's a/b), and a
// saturated law can leave out the moment about the contact normal, as that source model does.
// Oracle: Kalker's linear theory written out, F_x = -G a b C11 xi_x,
// F_y = -G a b (C22 xi_y + sqrt(a b) C23 xi_s), with the table's a, b and C_ij at the point.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ferro/contact/geometry/imported_contact_table.hpp"
#include "ferro/contact/geometry/point_normal_contact.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"

namespace fc = ferro::contact;

namespace {

const std::string kTable = std::string(FERRO_DATA_DIR) +
                           "/cooperrider_wagon/contact_table_s1002_uic60_1in40.csv";

fc::TangentialProblem problem_at(const fc::ContactPatch& patch) {
  fc::TangentialProblem p;
  p.patch = &patch;
  p.creepage = {1e-4, -2e-4, 0.05};  // small: the linear range of the law
  p.friction = 0.15;
  p.body1 = p.body2 = fc::Material{1.4383561643835616e11, 0.27};  // the wagon's G, nu
  p.rolling_speed = 50.0;
  return p;
}

}  // namespace

TEST(imported_coefficients, the_tables_c_ij_reach_kalkers_linear_forces) {
  const fc::ImportedContactTable t(kTable);
  // A flange-region pose (y = 9.37 mm towards the left wheel's flange: the row where Kalker's
  // table at the patch's a/b is furthest from the file) and the centred one.
  for (const double y_file : {9.37e-3, 0.0}) {
    const fc::WheelRailContact c =
        t.wheel_point(fc::WheelsetPose{-y_file, 0.0, 0.0, 0.0}, fc::Side::left);
    const fc::ContactPatch patch = fc::hertz_patch_from_penetration(c, 1.0);
    EXPECT_EQ(patch.c11, c.c11);
    EXPECT_EQ(patch.c22, c.c22);
    EXPECT_EQ(patch.c23, c.c23);
    const auto model = fc::make_tangential_model("kalker_linear");
    const auto prob = problem_at(patch);
    const fc::TangentialSolution s = model->solve(prob);
    const double g = prob.body1.shear_modulus, a = patch.semi_axis_x, b = patch.semi_axis_y;
    const double fx = -g * a * b * c.c11 * prob.creepage.longitudinal;
    const double fy = -g * a * b *
                      (c.c22 * prob.creepage.lateral + std::sqrt(a * b) * c.c23 * prob.creepage.spin);
    // The same products in another order: round-off.
    EXPECT_NEAR(s.force_x / fx, 1.0, 1e-12) << y_file;
    EXPECT_NEAR(s.force_y / fy, 1.0, 1e-12) << y_file;
  }
}

TEST(imported_coefficients, shen_hedrick_elkins_without_the_spin_moment) {
  const fc::ImportedContactTable t(kTable);
  const fc::WheelRailContact c = t.wheel_point(fc::WheelsetPose{0.0, 0.0, 0.0, 0.0}, fc::Side::left);
  const fc::ContactPatch patch = fc::hertz_patch_from_penetration(c, 1.0);
  const auto prob = problem_at(patch);
  const auto with = fc::make_tangential_model("shen_hedrick_elkins")->solve(prob);
  const auto without =
      fc::make_tangential_model("shen_hedrick_elkins", {{"spin_moment", "false"}})->solve(prob);
  EXPECT_NE(with.moment_z, 0.0);
  EXPECT_EQ(without.moment_z, 0.0);
  EXPECT_EQ(without.force_x, with.force_x);
  EXPECT_EQ(without.force_y, with.force_y);
  EXPECT_THROW((void)fc::make_tangential_model("shen_hedrick_elkins", {{"spin_moment", "no"}}),
               std::invalid_argument);
}
