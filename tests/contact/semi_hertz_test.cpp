// Semi-Hertz (Ayasse-Chollet) against Hertz on a quadratic gap, and on two-lobe gaps.
#include "ferro/contact/normal/semi_hertz.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "ferro/contact/normal/hertz.hpp"
#include "ferro/contact/normal/normal_model.hpp"

namespace fc = ferro::contact;

namespace {

fc::NormalProblem base_problem() {
  fc::NormalProblem p;
  const fc::Material steel = fc::Material::from_young(210e9, 0.28);
  p.body1 = steel;
  p.body2 = steel;
  p.curvature_x = std::cos(std::atan(0.1)) / (2.0 * 0.460);
  p.normal_force = 7.5e3 * 9.81;
  return p;
}

void sample_gap(fc::NormalProblem& p, double y_lo, double y_hi, int n, auto&& gap) {
  p.gap_y.clear();
  p.gap_z.clear();
  for (int i = 0; i <= n; ++i) {
    const double y = y_lo + (y_hi - y_lo) * i / n;
    p.gap_y.push_back(y);
    p.gap_z.push_back(gap(y));
  }
}

}  // namespace

// Toumi eqs. (17)-(23): on z = B y^2 the compensated strips rebuild the Hertz ellipse.
// Tolerance 3 % (issue requirement); the strip discretisation error is ~1e-4 with 200 strips.
TEST(semi_hertz, quadratic_gap_reproduces_hertz) {
  constexpr double kTol = 0.03;
  for (double b_curv : {1.0 / 0.6, 0.3, 8.0}) {  // B/A from 0.3 to 8.6
    fc::NormalProblem p = base_problem();
    sample_gap(p, -0.03, 0.03, 600, [&](double y) { return b_curv * y * y + 1e-4; });
    p.curvature_y = b_curv;
    const fc::NormalSolution hertz = fc::make_normal_model("hertz")->solve(p);
    const fc::NormalSolution semi = fc::make_normal_model("semi_hertz")->solve(p);
    ASSERT_EQ(semi.patches.size(), 1u);
    const fc::ContactPatch& h = hertz.patches[0];
    const fc::ContactPatch& s = semi.patches[0];
    EXPECT_NEAR(s.semi_axis_x / h.semi_axis_x, 1.0, kTol) << "B=" << b_curv;
    EXPECT_NEAR(s.semi_axis_y / h.semi_axis_y, 1.0, kTol) << "B=" << b_curv;
    EXPECT_NEAR(s.peak_pressure / h.peak_pressure, 1.0, kTol) << "B=" << b_curv;
    EXPECT_NEAR(s.normal_force / p.normal_force, 1.0, 1e-9);
    EXPECT_NEAR(semi.approach / hertz.approach, 1.0, kTol) << "B=" << b_curv;
    // Strip half-lengths follow the ellipse a sqrt(1 - y^2/b^2).
    for (const fc::PatchStrip& st : s.strips) {
      const double r = 1.0 - std::pow(st.y / h.semi_axis_y, 2);
      EXPECT_NEAR(st.half_length, h.semi_axis_x * std::sqrt(std::max(r, 0.0)),
                  kTol * h.semi_axis_x);
    }
  }
}

// Two identical wells far apart: two patches, each the Hertz solution at half the load
// (the reference ellipse's p0/a and aspect ratio do not depend on the load).
TEST(semi_hertz, two_identical_lobes_are_half_load_hertz) {
  constexpr double kTol = 0.03;
  fc::NormalProblem p = base_problem();
  const double b_curv = 1.0 / 0.6, y1 = -0.012, y2 = 0.012;
  sample_gap(p, -0.03, 0.03, 1200, [&](double y) {
    return std::min(b_curv * (y - y1) * (y - y1), b_curv * (y - y2) * (y - y2));
  });
  const fc::NormalSolution semi =
      fc::make_normal_model("semi_hertz", {{"strips", "400"}})->solve(p);
  ASSERT_EQ(semi.patches.size(), 2u);
  const fc::Material steel = fc::Material::from_young(210e9, 0.28);
  const fc::HertzSolution half = fc::hertz_solve(p.curvature_x, b_curv, 0.5 * p.normal_force,
                                                 fc::combine(steel, steel).contact_modulus);
  double total = 0.0;
  for (const fc::ContactPatch& s : semi.patches) {
    total += s.normal_force;
    EXPECT_NEAR(s.normal_force / (0.5 * p.normal_force), 1.0, kTol);
    EXPECT_NEAR(s.semi_axis_x / half.semi_axis_x, 1.0, kTol);
    EXPECT_NEAR(s.semi_axis_y / half.semi_axis_y, 1.0, kTol);
    EXPECT_NEAR(s.peak_pressure / half.peak_pressure, 1.0, kTol);
  }
  EXPECT_NEAR(semi.patches[0].y_center, y1, 0.05 * half.semi_axis_y);
  EXPECT_NEAR(semi.patches[1].y_center, y2, 0.05 * half.semi_axis_y);
  EXPECT_NEAR(total / p.normal_force, 1.0, 1e-9);
}

// Two curvature regions: a tread well (B = 1/0.6 1/m) and a tighter, slightly higher well
// (B = 1/0.08 1/m, 5 um above) as on a worn gauge corner: two patches, the deeper one carries
// more load, and the load is conserved.
TEST(semi_hertz, two_curvature_regions_two_patches) {
  fc::NormalProblem p = base_problem();
  const double b1 = 1.0 / 0.6, b2 = 1.0 / 0.08, y1 = -0.006, y2 = 0.010, dz = 5e-6;
  sample_gap(p, -0.03, 0.03, 1200, [&](double y) {
    return std::min(b1 * (y - y1) * (y - y1), b2 * (y - y2) * (y - y2) + dz);
  });
  const fc::NormalSolution semi =
      fc::make_normal_model("semi_hertz", {{"strips", "400"}})->solve(p);
  ASSERT_EQ(semi.patches.size(), 2u);
  EXPECT_GT(semi.patches[0].normal_force, semi.patches[1].normal_force);
  EXPECT_GT(semi.patches[1].normal_force, 0.0);
  EXPECT_NEAR((semi.patches[0].normal_force + semi.patches[1].normal_force) / p.normal_force, 1.0,
              1e-9);
}

TEST(semi_hertz, bad_input_names_the_field) {
  fc::NormalProblem p = base_problem();
  p.gap_y = {0.0, 1.0};
  p.gap_z = {0.0, 1.0};
  EXPECT_THROW((void)fc::make_normal_model("semi_hertz")->solve(p), std::invalid_argument);
  sample_gap(p, -0.01, 0.01, 20, [](double y) { return -y * y; });  // no positive curvature
  EXPECT_THROW((void)fc::make_normal_model("semi_hertz")->solve(p), std::invalid_argument);
}

// A quadratic gap sampled every 0.1 mm with 0.05 um of seeded noise (a measured-profile level):
// the least-squares reference curvature keeps a, b, p_max within 3 % of Hertz, the 3-point
// second difference does not (it amplifies the noise by 1/dy^2).
TEST(semi_hertz, noisy_gap_least_squares_curvature) {
  constexpr double kTol = 0.03;
  fc::NormalProblem p = base_problem();
  const double b_curv = 1.0 / 0.6;
  std::mt19937 rng(20161);  // seeded
  std::uniform_real_distribution<double> noise(-5e-8, 5e-8);
  sample_gap(p, -0.03, 0.03, 600, [&](double y) { return b_curv * y * y + noise(rng); });
  p.curvature_y = b_curv;
  const fc::ContactPatch h = fc::make_normal_model("hertz")->solve(p).patches.at(0);
  const fc::NormalSolution fit = fc::make_normal_model("semi_hertz")->solve(p);
  ASSERT_EQ(fit.patches.size(), 1u);
  EXPECT_NEAR(fit.patches[0].semi_axis_x / h.semi_axis_x, 1.0, kTol);
  EXPECT_NEAR(fit.patches[0].semi_axis_y / h.semi_axis_y, 1.0, kTol);
  EXPECT_NEAR(fit.patches[0].peak_pressure / h.peak_pressure, 1.0, kTol);
  const fc::NormalSolution three =
      fc::make_normal_model("semi_hertz", {{"curvature", "three_point"}})->solve(p);
  const double err_fit = std::abs(fit.patches[0].curvature_y / b_curv - 1.0);
  const double err_three = std::abs(three.patches.at(0).curvature_y / b_curv - 1.0);
  EXPECT_LT(err_fit, 0.01);
  EXPECT_GT(err_three, err_fit);
  RecordProperty("B_fit_rel_err", std::to_string(err_fit));
  RecordProperty("B_three_point_rel_err", std::to_string(err_three));
}
