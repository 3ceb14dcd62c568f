// References: Toumi (2016) eq. (12). Known deviations: none.
#include "ferro/contact/normal/contact_patch.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ferro::contact {

void ContactPatch::validate(const char* where) const {
  auto positive = [&](double v, const char* field) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::invalid_argument(
          fmt::format("{}.{}: must be finite and > 0, got {}", where, field, v));
    }
  };
  positive(semi_axis_x, "semi_axis_x");
  positive(semi_axis_y, "semi_axis_y");
  if (!(normal_force >= 0.0) || !std::isfinite(normal_force)) {
    throw std::invalid_argument(
        fmt::format("{}.normal_force: must be finite and >= 0 [N], got {}", where, normal_force));
  }
}

ContactPatch elliptic_patch(double semi_axis_x, double semi_axis_y, double normal_force,
                            double curvature_x, double curvature_y) {
  ContactPatch p;
  p.semi_axis_x = semi_axis_x;
  p.semi_axis_y = semi_axis_y;
  p.normal_force = normal_force;
  p.peak_pressure = 3.0 * normal_force / (2.0 * std::numbers::pi * semi_axis_x * semi_axis_y);
  p.curvature_x = curvature_x;
  p.curvature_y = curvature_y;
  p.validate("elliptic_patch");
  return p;
}

ContactPatch hertz_patch(const HertzSolution& hertz, double curvature_x, double curvature_y) {
  ContactPatch p;
  p.semi_axis_x = hertz.semi_axis_x;
  p.semi_axis_y = hertz.semi_axis_y;
  p.normal_force = hertz.normal_force;
  p.peak_pressure = hertz.peak_pressure;
  p.approach = hertz.approach;
  p.curvature_x = curvature_x;
  p.curvature_y = curvature_y;
  return p;
}

}  // namespace ferro::contact
