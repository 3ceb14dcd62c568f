// Hertz normal contact, exact through K(e), E(e).
//
// References: Johnson, "Contact Mechanics" (1985) eqs. (3.64)-(3.72):
//   with a >= b the major/minor semi-axes, k = b/a, e^2 = 1 - k^2,
//   A_small / A_large curvature ratio rho = (E(e)/k^2 - K(e)) / (K(e) - E(e)),
//   a^3 = 3 F E(e) / (2 pi E* k^2 (A + B)),  delta = 3 F K(e) / (2 pi E* a),
//   p_max = 3 F / (2 pi a b).
// Toumi (2016) eqs. (5)-(13) give the same solution through the tabulated m, n, r.
// K and E are the C++17 special functions std::comp_ellint_1/2 (modulus convention).
// Known deviations: curvature ratios beyond kMaxCurvatureRatio (axis ratios below
// kMinAxisRatio) are rejected: the modulus then rounds to 1 in double precision.
#include "ferro/contact/hertz.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ferro::contact {
namespace {

constexpr double kPi = std::numbers::pi;

struct EllipticKE {
  double first = 0.0;   // K(e)
  double second = 0.0;  // E(e)
};

EllipticKE complete_elliptic_integrals(double modulus) {
  return {std::comp_ellint_1(modulus), std::comp_ellint_2(modulus)};
}

// Curvature ratio rho(k) and d(rho)/dk for the axis ratio k in (0, 1).
struct RatioAndSlope {
  double rho = 1.0;
  double slope = 0.0;
  double kfirst = 0.0;
  double ksecond = 0.0;
};

RatioAndSlope ratio_of_axis(double k) {
  const double e2 = 1.0 - k * k;
  const double e = std::sqrt(e2);
  const EllipticKE ke = complete_elliptic_integrals(e);
  const double kk = ke.first, ee = ke.second;
  const double num = ee / (k * k) - kk;
  const double den = kk - ee;
  // dK/de = E/(e k^2) - K/e, dE/de = (E - K)/e, de/dk = -k/e.
  const double dk_de = ee / (e * k * k) - kk / e;
  const double de_de = (ee - kk) / e;
  const double dk2_de = -2.0 * e;  // d(k^2)/de
  const double dnum_de = de_de / (k * k) - ee * dk2_de / (k * k * k * k) - dk_de;
  const double dden_de = dk_de - de_de;
  const double drho_de = (dnum_de * den - num * dden_de) / (den * den);
  RatioAndSlope out;
  out.rho = num / den;
  out.slope = drho_de * (-k / e);
  out.kfirst = kk;
  out.ksecond = ee;
  return out;
}

// Below this eccentricity^2 the ellipse is treated as a circle (ratio error < 1e-13).
constexpr double kCircleE2 = 1e-13;

}  // namespace

double hertz_curvature_ratio(double axis_ratio) {
  if (!(axis_ratio >= kMinAxisRatio && axis_ratio <= 1.0)) {
    throw std::invalid_argument(fmt::format(
        "hertz_curvature_ratio: the axis ratio b/a must lie in [{}, 1], got {} (a thinner "
        "ellipse is a line contact, outside the elliptic Hertz theory)",
        kMinAxisRatio, axis_ratio));
  }
  if (1.0 - axis_ratio * axis_ratio < kCircleE2) return 1.0;
  return ratio_of_axis(axis_ratio).rho;
}

double hertz_axis_ratio(double curvature_ratio) {
  if (!(curvature_ratio >= 1.0) || !(curvature_ratio <= kMaxCurvatureRatio)) {
    throw std::invalid_argument(fmt::format(
        "hertz_axis_ratio: the curvature ratio (larger/smaller) must lie in [1, {:g}], got {} "
        "(a larger ratio is a line contact, outside the elliptic Hertz theory)",
        kMaxCurvatureRatio, curvature_ratio));
  }
  if (curvature_ratio - 1.0 < 1e-13) return 1.0;
  // Newton on ln(rho(k)) - ln(rho_target) with a bracket [lo, hi] kept for safety.
  // Start from Brewe & Hamrock's fit k ~ rho^(-0.636) / 1.0339 (a few % off).
  const double target = std::log(curvature_ratio);
  double lo = kMinAxisRatio, hi = 1.0;  // rho(kMinAxisRatio) > kMaxCurvatureRatio
  double k = std::exp(-0.636 * target) / 1.0339;
  k = std::clamp(k, kMinAxisRatio, 1.0 - 1e-9);
  for (int iter = 0; iter < 100; ++iter) {
    const RatioAndSlope rs = ratio_of_axis(k);
    const double f = std::log(rs.rho) - target;  // decreasing in k
    if (std::abs(f) < 1e-15) break;
    if (f > 0.0)
      lo = k;
    else
      hi = k;
    const double fp = rs.slope / rs.rho;
    double next = k - f / fp;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - k) <= 1e-15 * k) {
      k = next;
      break;
    }
    k = next;
    if (hi - lo < 1e-16) break;
  }
  return k;
}

HertzCoefficients hertz_coefficients(double theta) {
  if (!(theta > 0.0 && theta <= 0.5 * kPi + 1e-15)) {
    throw std::invalid_argument(
        fmt::format("hertz_coefficients: theta must lie in (0, pi/2] rad, got {}", theta));
  }
  const double c = std::cos(theta);  // (rho - 1)/(rho + 1)
  const double rho = c >= 1.0 ? INFINITY : (1.0 + c) / (1.0 - c);
  const double k = hertz_axis_ratio(std::max(rho, 1.0));
  double kfirst = 0.5 * kPi, ksecond = 0.5 * kPi;
  if (k < 1.0) {
    const EllipticKE ke = complete_elliptic_integrals(std::sqrt(1.0 - k * k));
    kfirst = ke.first;
    ksecond = ke.second;
  }
  HertzCoefficients out;
  out.m = std::cbrt(2.0 * ksecond / (kPi * k * k));
  out.n = k * out.m;
  out.r = 2.0 * kfirst / (kPi * out.m);
  return out;
}

HertzSolution hertz_solve(double curvature_x, double curvature_y, double normal_force,
                          double contact_modulus) {
  if (!(curvature_x > 0.0) || !std::isfinite(curvature_x)) {
    throw std::invalid_argument(fmt::format(
        "hertz_solve: curvature_x (A) must be finite and > 0 [1/m], got {}", curvature_x));
  }
  if (!(curvature_y > 0.0) || !std::isfinite(curvature_y)) {
    throw std::invalid_argument(fmt::format(
        "hertz_solve: curvature_y (B) must be finite and > 0 [1/m], got {}", curvature_y));
  }
  if (!(normal_force >= 0.0) || !std::isfinite(normal_force)) {
    throw std::invalid_argument(
        fmt::format("hertz_solve: normal_force must be finite and >= 0 [N], got {}", normal_force));
  }
  if (!(contact_modulus > 0.0) || !std::isfinite(contact_modulus)) {
    throw std::invalid_argument(fmt::format(
        "hertz_solve: contact_modulus must be finite and > 0 [Pa], got {}", contact_modulus));
  }
  const double small = std::min(curvature_x, curvature_y);
  const double large = std::max(curvature_x, curvature_y);
  if (large / small > kMaxCurvatureRatio) {
    throw std::invalid_argument(fmt::format(
        "hertz_solve: the curvatures A = {} and B = {} [1/m] differ by a factor {:.3g}, beyond "
        "{:g}: the patch is a line contact, outside the elliptic Hertz theory (check the "
        "curvatures or radii; semi_hertz takes a non-elliptic gap)",
        curvature_x, curvature_y, large / small, kMaxCurvatureRatio));
  }
  const double k = hertz_axis_ratio(large / small);
  double kfirst = 0.5 * kPi, ksecond = 0.5 * kPi;
  if (k < 1.0) {
    const EllipticKE ke = complete_elliptic_integrals(std::sqrt(1.0 - k * k));
    kfirst = ke.first;
    ksecond = ke.second;
  }
  const double sum = curvature_x + curvature_y;
  const double major =
      std::cbrt(3.0 * normal_force * ksecond / (2.0 * kPi * contact_modulus * k * k * sum));
  const double minor = k * major;
  HertzSolution s;
  s.normal_force = normal_force;
  // The major axis lies along the direction of the smaller curvature.
  s.semi_axis_x = curvature_x <= curvature_y ? major : minor;
  s.semi_axis_y = curvature_x <= curvature_y ? minor : major;
  if (normal_force > 0.0) {
    s.approach = 3.0 * normal_force * kfirst / (2.0 * kPi * contact_modulus * major);
    s.peak_pressure = 3.0 * normal_force / (2.0 * kPi * major * minor);
  } else {
    s.approach = 0.0;
    s.peak_pressure = 0.0;
  }
  return s;
}

double HertzSolution::pressure(double x, double y) const {
  const double u =
      1.0 - (x / semi_axis_x) * (x / semi_axis_x) - (y / semi_axis_y) * (y / semi_axis_y);
  return u > 0.0 ? peak_pressure * std::sqrt(u) : 0.0;
}

}  // namespace ferro::contact
