// Semi-Hertz normal contact of one point of a profile-based source (the dynamics' entry point):
// on the thesis' Hertzian case (S1002 with a 1/10 conical tread on the R300 crown of UIC60
// inclined 1:10: flat cone on a circular crown, a locally quadratic gap) it must give the Hertz
// normal force and semi-axes of the point's curvatures at the same penetration; on S1002 / UIC60
// 1:40, where the flange's lateral relative curvature changes sign, its force must stay as
// continuous as the penetration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ferro/contact/geometry/point_normal_contact.hpp"
#include "ferro/contact/geometry/search_source.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "a22_pair.hpp"

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

// S1002 on UIC60 1:40 at roll -1 mrad, 0.1 mm below the touching reference, lateral shift 6.165
// -> 6.185 mm in 1 um steps: the right wheel touches at one point on the flange (contact angle
// 1.16 -> 1.21 rad), whose lateral relative curvature B passes through zero (+1.1, -0.5, -3.4,
// +11.7 1/m) while the penetration grows smoothly (44 -> 62 um). Oracle: the normal force is a
// function of the interpenetration, which moves by micrometres, so between neighbouring poses it
// moves by at most the local contact stiffness times the penetration's change: for a power law
// F ~ delta^p, dF = p F / delta d(delta), p = 3/2 for Hertz and less for a conformal (line-like)
// patch. kStiffnessFactor = 2 on p = 3/2 leaves room for the point's curvatures changing along
// the sweep (measured at most 1.3 for the semi-Hertz patches of the profiles' gap). Hertz at the
// point's curvatures is reported beside it: at B <= 0 its ellipse is floored (hertz_curvatures())
// and widens to ~0.3 m, giving ~0.65 MN against ~30 kN.
TEST(semi_hertz_contact, s1002_flange_curvature_sign_change_force_follows_penetration) {
  constexpr double kStiffnessFactor = 2.0;  // [-]
  constexpr double kExponent = 1.5;         // [-] Hertz
  constexpr double kStep = 1e-6;            // [m] of lateral shift
  constexpr double kRoll = -1e-3, kVertical = -1e-4, kY0 = 6.165e-3, kY1 = 6.185e-3;
  const auto pair = ferro::test::a22_pair();
  const fc::SearchContactSource search(pair);
  const fc::Material steel = fc::Material::from_young(210.0e9, 0.28);
  const double estar = fc::combine(steel, steel).contact_modulus;
  fc::SemiHertzScratch scratch;
  std::vector<fc::WheelRailContact> pts;
  double previous_force = NAN, previous_penetration = NAN;
  double worst_ratio = 0.0, worst_hertz_ratio = 0.0, previous_hertz = NAN;
  double smallest_b = INFINITY, largest_b = -INFINITY;
  const int n = static_cast<int>(std::lround((kY1 - kY0) / kStep));
  for (int i = 0; i <= n; ++i) {
    const fc::WheelsetPose pose{kY0 + i * kStep, kVertical, kRoll, 0.0};
    search.contacts(pose, pts);
    const fc::WheelRailContact* flange = nullptr;
    int right = 0;
    for (const fc::WheelRailContact& c : pts) {
      if (c.side != fc::Side::right) continue;
      ++right;
      flange = &c;
    }
    ASSERT_EQ(right, 1) << "y = " << pose.lateral;
    ASSERT_GT(flange->contact_angle, 1.1) << "y = " << pose.lateral;
    smallest_b = std::min(smallest_b, flange->curvature_b);
    largest_b = std::max(largest_b, flange->curvature_b);
    double force = 0.0;
    for (const fc::ContactPatch& p :
         fc::semi_hertz_patches_from_penetration(*pair, pose, *flange, steel, {}, scratch).patches) {
      force += p.normal_force;
    }
    const double hertz = fc::hertz_patch_from_penetration(*flange, estar).normal_force;
    ASSERT_GT(force, 0.0);
    if (i > 0) {
      const double d_penetration = std::abs(flange->penetration - previous_penetration);
      const double bound = kExponent * std::max(force, previous_force) /
                           std::min(flange->penetration, previous_penetration) * d_penetration;
      const double ratio = std::abs(force - previous_force) / bound;
      EXPECT_LT(ratio, kStiffnessFactor) << "y = " << pose.lateral;
      worst_ratio = std::max(worst_ratio, ratio);
      worst_hertz_ratio = std::max(worst_hertz_ratio, std::abs(hertz - previous_hertz) / bound);
    }
    previous_force = force;
    previous_hertz = hertz;
    previous_penetration = flange->penetration;
  }
  // The sweep is the one meant: B changes sign inside it.
  EXPECT_LT(smallest_b, 0.0);
  EXPECT_GT(largest_b, 5.0);
  std::printf("[ figures  ] flange B %.2f to %.2f 1/m: largest force step over 1.5 F/delta "
              "d(delta): semi-Hertz %.2f, Hertz at the point's curvatures %.1f\n",
              smallest_b, largest_b, worst_ratio, worst_hertz_ratio);
}
