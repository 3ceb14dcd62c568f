// Online-search and conical contact sources; the normal patch from a point's penetration.
//
// References: see contact_sources.hpp (Wickens 2003 ch. 2; Johnson 1985 (3.64)-(3.72)).
// Known deviations: see contact_sources.hpp.

#include "ferro/contact/geometry/contact_sources.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ferro/contact/hertz.hpp"

namespace ferro::contact {

ContactPatch hertz_patch_from_penetration(const WheelRailContact& c, double contact_modulus) {
  if (std::isnan(c.penetration)) {
    throw std::invalid_argument("hertz_patch_from_penetration: WheelRailContact.penetration is NaN");
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
  const HertzSolution h = hertz_solve_from_approach(c.curvature_a, c.curvature_b, c.penetration,
                                                    contact_modulus);
  const HertzCurvatures cv =
      hertz_curvatures(c.curvature_a, c.curvature_b, "hertz_patch_from_penetration");
  p = hertz_patch(h, cv.x, cv.y);
  p.approach = c.penetration;
  return p;
}

WheelRailContact to_wheel_rail_contact(const ContactPoint& q) {
  WheelRailContact c = WheelRailContact::geometry_of(q);
  c.penetration = q.penetration;
  c.vertical_gap = q.vertical_gap;
  return c;
}

SearchContactSource::SearchContactSource(std::shared_ptr<const WheelRailPair> pair)
    : pair_(std::move(pair)) {
  if (!pair_) throw std::invalid_argument("SearchContactSource: the wheel-rail pair is null");
}

void SearchContactSource::contacts(const WheelsetPose& pose,
                                   std::vector<WheelRailContact>& out) const {
  out.clear();
  for (const ContactPoint& q : search_contacts(*pair_, pose)) {
    out.push_back(to_wheel_rail_contact(q));
  }
}

void ConicalContactParams::validate() const {
  auto bad = [](const char* field, double v, const char* range) {
    throw std::invalid_argument(
        fmt::format("ConicalContactParams.{}: must be {}, got {}", field, range, v));
  };
  if (!(conicity >= 0.0 && conicity < 1.0)) bad("conicity", conicity, "in [0, 1) [-]");
  if (!(contact_half_distance > 0.1 && contact_half_distance < 2.0)) {
    bad("contact_half_distance", contact_half_distance, "in (0.1, 2) m");
  }
  if (!(nominal_radius > 0.1 && nominal_radius < 2.0)) {
    bad("nominal_radius", nominal_radius, "in (0.1, 2) m");
  }
  if (!(curvature_a > 0.0) || !std::isfinite(curvature_a)) {
    bad("curvature_a", curvature_a, "finite and > 0 [1/m]");
  }
  if (!(curvature_b > 0.0) || !std::isfinite(curvature_b)) {
    bad("curvature_b", curvature_b, "finite and > 0 [1/m]");
  }
}

ConicalContactSource::ConicalContactSource(const ConicalContactParams& params)
    : params_(params) {
  params_.validate();
}

WheelRailContact ConicalContactSource::wheel_point(const WheelsetPose& pose, Side side) const {
  const double s = side == Side::right ? 1.0 : -1.0;
  const double g = params_.conicity, e = params_.contact_half_distance;
  const double r0 = params_.nominal_radius;
  const double cphi = std::cos(pose.roll), sphi = std::sin(pose.roll);
  // Section y_w over the crown line: y_c + y_w cos(phi) - (r0 + g e - s g y_w) sin(phi) = s e.
  const double yw = (s * e - pose.lateral + (r0 + g * e) * sphi) / (cphi + s * g * sphi);
  const double radius = r0 + g * e - s * g * yw;
  const double zc = -r0 + pose.vertical;
  const double z_wheel = zc + yw * sphi + radius * cphi;  // lowest point of the section (down)
  WheelRailContact c;
  c.side = side;
  c.x = 0.0;
  c.y = s * e;
  c.z = 0.0;
  c.contact_angle = std::atan(g) - s * pose.roll;
  c.rolling_radius = radius;
  c.vertical_gap = -z_wheel;
  c.penetration = std::max(0.0, z_wheel * std::cos(c.contact_angle));
  c.curvature_a = params_.curvature_a;
  c.curvature_b = params_.curvature_b;
  return c;
}

void ConicalContactSource::contacts(const WheelsetPose& pose,
                                    std::vector<WheelRailContact>& out) const {
  out.clear();
  for (const Side side : {Side::left, Side::right}) {
    const WheelRailContact c = wheel_point(pose, side);
    if (c.vertical_gap < 0.0) out.push_back(c);
  }
}

}  // namespace ferro::contact
