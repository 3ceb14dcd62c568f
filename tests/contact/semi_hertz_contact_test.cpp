// Semi-Hertz normal contact of one point of a profile-based source (the dynamics' entry point):
// on the thesis' Hertzian case (S1002 with a 1/10 conical tread on the R300 crown of UIC60
// inclined 1:10: flat cone on a circular crown, a locally quadratic gap) it must give the Hertz
// normal force and semi-axes of the point's curvatures at the same penetration.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ferro/contact/geometry/point_normal_contact.hpp"
#include "ferro/contact/geometry/search_source.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace fc = ferro::contact;

namespace {

const std::string kData = FERRO_DATA_DIR;

fc::WheelRailPair thesis_1in10_pair() {
  fc::WheelRailPairParams p;
  p.track_gauge = 1.435;
  p.flange_back_distance = 1.360;
  p.flange_back_y = -0.070;
  p.nominal_radius = 0.460;
  p.rail_inclination = std::atan(0.1) - std::atan(1.0 / 40.0);  // file is 1:40 already
  return fc::WheelRailPair(fc::splice_conical_tread(fc::make_s1002_wheel(), 0.1, -0.015),
                           fc::read_simpack_profile(kData + "/profiles/MBench_UIC60_v3.prr"), p);
}

}  // namespace

// Oracle: Hertz at the point's curvatures. The gap is a circle (R300 crown) under a flat cone:
// its quartic term y^2 / (4 R^2) is <= 1e-4 over the patch; the gap is sampled every b/16
// (piecewise linear: <= 5e-4 of h0) and cut into 200 strips (1e-4, docs/VALIDATION.md
// semi-Hertz rows); the least-squares reference curvature over the sampled lobe then enters the
// load as B^(-1/2). kTol = 0.5 % holds all of these with margin.
TEST(semi_hertz_contact, quadratic_gap_gives_hertz_force_and_semi_axes) {
  constexpr double kTol = 5e-3;
  const fc::WheelRailPair pair = thesis_1in10_pair();
  const fc::Material steel{82.0e9, 0.28};
  const double estar = fc::combine(steel, steel).contact_modulus;
  fc::SemiHertzScratch scratch;
  double worst = 0.0;
  int checked = 0;
  for (double lateral : {-2.0e-3, 0.0, 3.0e-3}) {
    fc::WheelsetPose pose = fc::solve_rigid_contact(pair, lateral).pose;
    for (double drop : {20e-6, 80e-6}) {
      fc::WheelsetPose p = pose;
      p.vertical += drop;
      for (const fc::ContactPoint& q : fc::search_contacts(pair, p)) {
        const fc::WheelRailContact c = fc::to_wheel_rail_contact(q);
        ASSERT_NEAR(std::tan(c.contact_angle), 0.1, 0.02) << "not on the cone";
        const fc::ContactPatch h = fc::hertz_patch_from_penetration(c, estar);
        const fc::NormalSolution& s =
            fc::semi_hertz_patches_from_penetration(pair, p, c, steel, {}, scratch);
        ASSERT_EQ(s.patches.size(), 1u);
        const fc::ContactPatch& sp = s.patches[0];
        EXPECT_NEAR(sp.normal_force / h.normal_force, 1.0, kTol) << "y = " << lateral;
        EXPECT_NEAR(sp.semi_axis_x / h.semi_axis_x, 1.0, kTol) << "y = " << lateral;
        EXPECT_NEAR(sp.semi_axis_y / h.semi_axis_y, 1.0, kTol) << "y = " << lateral;
        EXPECT_NEAR(sp.peak_pressure / h.peak_pressure, 1.0, kTol) << "y = " << lateral;
        EXPECT_EQ(sp.approach, c.penetration);
        for (double r : {sp.normal_force / h.normal_force, sp.semi_axis_x / h.semi_axis_x,
                         sp.semi_axis_y / h.semi_axis_y}) {
          worst = std::max(worst, std::abs(r - 1.0));
        }
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 12);
  std::printf("semi-Hertz against Hertz on the 1/10 cone on R300: largest deviation %.2e\n",
              worst);
}

// The penetration enters through eq. (21): zero or negative penetration gives no patch, NaN throws.
TEST(semi_hertz_contact, no_penetration_no_patch_nan_throws) {
  const fc::WheelRailPair pair = thesis_1in10_pair();
  const fc::Material steel{82.0e9, 0.28};
  fc::WheelsetPose pose = fc::solve_rigid_contact(pair, 0.0).pose;
  pose.vertical += 50e-6;
  const auto pts = fc::search_contacts(pair, pose);
  ASSERT_FALSE(pts.empty());
  fc::WheelRailContact c = fc::to_wheel_rail_contact(pts.front());
  fc::SemiHertzScratch scratch;
  c.penetration = 0.0;
  EXPECT_TRUE(
      fc::semi_hertz_patches_from_penetration(pair, pose, c, steel, {}, scratch).patches.empty());
  c.penetration = NAN;
  EXPECT_THROW((void)fc::semi_hertz_patches_from_penetration(pair, pose, c, steel, {}, scratch),
               std::invalid_argument);
}
