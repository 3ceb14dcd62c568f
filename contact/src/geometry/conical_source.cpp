// Analytic conical wheels on knife-edge rail crowns as a contact geometry source.
//
// References: see conical_source.hpp (Wickens 2003 ch. 2).
// Known deviations: see conical_source.hpp.

#include "ferro/contact/geometry/conical_source.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ferro::contact {

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

ConicalContactSource::ConicalContactSource(const ConicalContactParams& params) : params_(params) {
  params_.validate();
}

WheelRailContact ConicalContactSource::wheel_point(const WheelsetPose& pose, Side side) const {
  const double s = side_sign(side);
  const double g = params_.conicity, e = params_.contact_half_distance;
  const double r0 = params_.nominal_radius;
  const WheelsetFrame frame(pose, r0);
  const double cphi = frame.cos_roll, sphi = frame.sin_roll;
  // Section y_w over the crown line: y_c + y_w cos(phi) - (r0 + g e - s g y_w) sin(phi) = s e.
  const double yw = (s * e - pose.lateral + (r0 + g * e) * sphi) / (cphi + s * g * sphi);
  const double radius = r0 + g * e - s * g * yw;
  const double zc = frame.centre_z;
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

void ConicalContactSource::contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out,
                                    ContactScratch& /*scratch*/) const {
  out.clear();
  for (const Side side : {Side::left, Side::right}) {
    const WheelRailContact c = wheel_point(pose, side);
    if (c.vertical_gap < 0.0) out.push_back(c);
  }
}

}  // namespace ferro::contact
