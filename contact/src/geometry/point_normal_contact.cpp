// Normal contact of one point of a geometry source: the Hertz patch from its penetration (or its
// reference Hertz state), and the semi-Hertz patches of a profile-based source: the undeformed
// gap of the wheel and rail profiles across the point's contact plane, cut to the point's own
// basin, then semi_hertz_solve_from_approach() at the point's penetration.
//
// References: Johnson (1985) eqs. (3.64)-(3.72); Ayasse & Chollet, Vehicle System Dynamics 43
// (2005) 161-172; Toumi (2016) eqs. (1), (5)-(13), (17)-(23).
// Known deviations: see point_normal_contact.hpp.

#include "ferro/contact/geometry/point_normal_contact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "ferro/contact/normal/hertz.hpp"

namespace ferro::contact {

ContactPatch hertz_patch_from_penetration(const WheelRailContact& c, double contact_modulus) {
  if (std::isnan(c.penetration)) {
    throw std::invalid_argument(
        "hertz_patch_from_penetration: WheelRailContact.penetration is NaN");
  }
  ContactPatch p;
  p.approach = c.penetration;
  if (!(c.penetration > 0.0)) {
    p.semi_axis_x = p.semi_axis_y = p.normal_force = p.peak_pressure = 0.0;
    p.approach = 0.0;
    p.curvature_x = c.curvature_a;
    p.curvature_y = c.curvature_b;
    return p;
  }
  if (c.has_reference_state()) {
    if (!(c.ref_penetration > 0.0) || !(c.ref_semi_axis_a > 0.0) || !(c.ref_semi_axis_b > 0.0) ||
        !(c.ref_normal_force > 0.0)) {
      throw std::invalid_argument(fmt::format(
          "hertz_patch_from_penetration: reference state must be > 0: ref_normal_force = {} N, "
          "ref_penetration = {} m, ref_semi_axis_a = {} m, ref_semi_axis_b = {} m",
          c.ref_normal_force, c.ref_penetration, c.ref_semi_axis_a, c.ref_semi_axis_b));
    }
    const double ratio = c.penetration / c.ref_penetration;
    const double root = std::sqrt(ratio);  // (F/F0)^(1/3) = (d/d0)^(1/2)
    p = elliptic_patch(c.ref_semi_axis_a * root, c.ref_semi_axis_b * root,
                       c.ref_normal_force * ratio * root, c.curvature_a, c.curvature_b);
    p.approach = c.penetration;
    p.c11 = c.c11;  // the source's own coefficients, when it gives them (NaN otherwise)
    p.c22 = c.c22;
    p.c23 = c.c23;
    return p;
  }
  const HertzSolution h =
      hertz_solve_from_approach(c.curvature_a, c.curvature_b, c.penetration, contact_modulus);
  const HertzCurvatures cv =
      hertz_curvatures(c.curvature_a, c.curvature_b, "hertz_patch_from_penetration");
  p = hertz_patch(h, cv.x, cv.y);
  p.approach = c.penetration;
  return p;
}
namespace {

// Gap samples across the point's Hertz semi-axis b: the semi-Hertz validation's quadratic case
// is within 1e-4 of Hertz with 600 samples over +-30 mm (~100 per b) and the least-squares
// curvature fit needs >= 5 samples in the lobe; 16 per b keeps the piecewise-linear gap within
// (1/16)^2 / 8 ~ 5e-4 of h0 on a quadratic gap.
constexpr double kSamplesPerSemiAxis = 16.0;  // [-]
constexpr double kMaxStep = 0.25e-3;          // [m]
constexpr double kMinStep = 2.0e-6;           // [m]
// A side ends once the gap exceeds its lowest value by 1.1 delta: the loaded lobe (h0 = b^2 B of
// the reference ellipse) lies inside the rigid interpenetration (gap < delta), so beyond it.
constexpr double kReach = 1.1;  // [-]
// A rise and fall of more than this ends the basin at its top: the next local minimum of the
// gap is another point of the source (the search's candidate prominence).
constexpr double kProminence = 1.0e-6;    // [m]
constexpr int kMaxSamplesPerSide = 1000;  // [-]

// Samples the gap outwards from the point along s = dir k ds (k >= 1) into `side`, up to the
// basin's end (reach, barrier top, end of a profile).
void walk(const ContactPlaneGap& plane, double z0, double dir, double ds, double delta,
          std::vector<double>& side) {
  side.clear();
  double lo = z0, hi = z0;   // lowest so far, highest since then
  std::size_t hi_count = 0;  // samples kept up to the highest
  for (int k = 1; k <= kMaxSamplesPerSide; ++k) {
    const double z = plane.at(0.0, dir * k * ds);
    if (!std::isfinite(z)) return;
    side.push_back(z);
    if (z < lo) {
      lo = hi = z;
      hi_count = side.size();
      continue;
    }
    if (z > hi) {
      hi = z;
      hi_count = side.size();
    }
    if (hi - lo > kProminence && z < hi - kProminence) {
      side.resize(hi_count);  // a barrier: the next basin is another point's
      return;
    }
    if (z - lo > kReach * delta) return;
  }
}

}  // namespace

NormalSolution& semi_hertz_patches_from_penetration(
    const WheelRailPair& pair, const WheelsetPose& pose, const WheelRailContact& contact,
    const Material& material, const SemiHertzOptions& options, SemiHertzScratch& scratch) {
  NormalSolution& out = scratch.solution;
  if (std::isnan(contact.penetration)) {
    throw std::invalid_argument(
        "semi_hertz_patches_from_penetration: WheelRailContact.penetration is NaN");
  }
  if (!(contact.penetration > 0.0)) {
    out.patches.clear();
    out.approach = 0.0;
    return out;
  }
  const double delta = contact.penetration;
  const double estar = combine(material, material).contact_modulus;
  const ContactPatch hertz = hertz_patch_from_penetration(contact, estar);
  const double ds = std::clamp(hertz.semi_axis_y / kSamplesPerSemiAxis, kMinStep, kMaxStep);

  ContactPoint point;
  point.side = contact.side;
  point.x = contact.x;
  point.y = contact.y;
  point.z = contact.z;
  point.rail_y = contact.rail_y;
  const ContactPlaneGap plane(pair, pose, point, contact.contact_angle);
  const double z0 = plane.at(0.0, 0.0);
  if (!std::isfinite(z0)) {
    throw std::runtime_error(fmt::format(
        "semi_hertz: no gap at the contact point (wheel_y = {} m, rail_y = {} m): a profile "
        "ends there",
        contact.wheel_y, contact.rail_y));
  }
  walk(plane, z0, -1.0, ds, delta, scratch.left);
  walk(plane, z0, 1.0, ds, delta, scratch.right);

  NormalProblem& p = scratch.problem;
  const std::size_t nl = scratch.left.size(), nr = scratch.right.size();
  p.gap_y.resize(nl + 1 + nr);
  p.gap_z.resize(nl + 1 + nr);
  for (std::size_t k = 0; k < nl; ++k) {
    p.gap_y[k] = -static_cast<double>(nl - k) * ds;
    p.gap_z[k] = scratch.left[nl - 1 - k];
  }
  p.gap_y[nl] = 0.0;
  p.gap_z[nl] = z0;
  for (std::size_t k = 0; k < nr; ++k) {
    p.gap_y[nl + 1 + k] = static_cast<double>(k + 1) * ds;
    p.gap_z[nl + 1 + k] = scratch.right[k];
  }
  p.curvature_x = contact.curvature_a;
  // First estimate of B_ref: the point's curvature (continuous along the source's branch).
  p.curvature_y = contact.curvature_b > 0.0 ? contact.curvature_b : ContactPatch::kNaN;
  p.normal_force = ContactPatch::kNaN;
  p.body1 = material;
  p.body2 = material;
  semi_hertz_solve_from_approach(p, delta, options, scratch.work, out);
  for (ContactPatch& patch : out.patches) patch.approach = delta;
  return out;
}

}  // namespace ferro::contact
