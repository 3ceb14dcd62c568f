// Hertz gap from a contact ellipse.
//
// References: Johnson (1985) eqs. (3.63)-(3.64); Toumi (2016) eqs. (5)-(13).
// Known deviations: none.

#include "ferro/contact/mim/hertz_gap.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ferro/contact/normal/elliptic.hpp"

namespace ferro::contact::mim {

HertzGap hertz_gap_for_ellipse(double a, double b, double normal_force, double contact_modulus) {
  if (!(a > 0.0) || !(b > 0.0) || !(normal_force > 0.0) || !(contact_modulus > 0.0)) {
    throw std::invalid_argument(
        fmt::format("hertz_gap_for_ellipse: semi_axis_x {}, semi_axis_y {}, normal_force {} and "
                    "contact_modulus {} must all be > 0",
                    a, b, normal_force, contact_modulus));
  }
  const double major = std::max(a, b);
  const double minor = std::min(a, b);
  const double p0 = 3.0 * normal_force / (2.0 * std::numbers::pi * a * b);
  const double e2 = 1.0 - (minor * minor) / (major * major);
  const double pre = p0 * minor / (contact_modulus * major * major);
  double c_major = 0.0;  // curvature along the major axis
  double c_minor = 0.0;
  double k = 0.0;
  if (e2 < 1.0e-8) {
    c_major = c_minor = pre * std::numbers::pi / 4.0;
    k = std::numbers::pi / 2.0;
  } else {
    const double e = std::sqrt(e2);
    const CompleteEllipticIntegrals ke = complete_elliptic_integrals(e);
    k = ke.first;
    const double ee = ke.second;
    c_major = pre * (k - ee) / e2;
    c_minor = pre * ((major * major) / (minor * minor) * ee - k) / e2;
  }
  HertzGap g;
  g.curvature_x = a >= b ? c_major : c_minor;
  g.curvature_y = a >= b ? c_minor : c_major;
  g.approach = p0 * minor * k / contact_modulus;
  g.max_pressure = p0;
  return g;
}

Grid grid_for_ellipse(double a, double b, int elements_minor, double margin) {
  if (!(a > 0.0) || !(b > 0.0) || elements_minor < 2 || !(margin >= 0.0)) {
    throw std::invalid_argument(fmt::format(
        "grid_for_ellipse: need semi axes > 0 m, elements_minor >= 2 and margin >= 0, got "
        "a = {}, b = {}, elements_minor = {}, margin = {}",
        a, b, elements_minor, margin));
  }
  const double h = 2.0 * std::min(a, b) * (1.0 + margin) / elements_minor;
  // Counts depend only on the shape (a/b, margin): round-off must not add an element.
  auto count = [&](double length) {
    return static_cast<int>(std::ceil(length * (1.0 + margin) / h * (1.0 - 1.0e-12)));
  };
  const int nx = std::max(2, count(2.0 * a));
  const int ny = std::max(1, count(2.0 * b));
  return Grid::centred(nx, ny, h, h);
}

Grid grid_over_ellipse(double a, double b, int elements, double margin) {
  if (!(a > 0.0) || !(b > 0.0) || elements < 2 || !(margin >= 0.0)) {
    throw std::invalid_argument(fmt::format(
        "grid_over_ellipse: need semi axes > 0 m, elements >= 2 and margin >= 0, got "
        "a = {}, b = {}, elements = {}, margin = {}",
        a, b, elements, margin));
  }
  return Grid::centred(elements, elements, 2.0 * a * (1.0 + margin) / elements,
                       2.0 * b * (1.0 + margin) / elements);
}

Field quadratic_gap(const Grid& grid, double cx, double cy) {
  return sample(grid, [&](double x, double y) { return cx * x * x + cy * y * y; });
}

}  // namespace ferro::contact::mim
