// Hertz normal contact, exact through K(e), E(e).
//
// References: Johnson, "Contact Mechanics" (1985) eqs. (3.64)-(3.72):
//   with a >= b the major/minor semi-axes, k = b/a, e^2 = 1 - k^2,
//   A_small / A_large curvature ratio rho = (E(e)/k^2 - K(e)) / (K(e) - E(e)),
//   a^3 = 3 F E(e) / (2 pi E* k^2 (A + B)),  delta = 3 F K(e) / (2 pi E* a),
//   p_max = 3 F / (2 pi a b).
// Toumi (2016) eqs. (5)-(13) give the same solution through the tabulated m, n, r.
// K and E by the arithmetic-geometric mean (elliptic.hpp).
// Known deviations: curvature ratios beyond kMaxCurvatureRatio (axis ratios below
// kMinAxisRatio) are rejected: the modulus then rounds to 1 in double precision.
#include "ferro/contact/normal/hertz.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ferro/contact/normal/elliptic.hpp"

namespace ferro::contact {
namespace {

constexpr double kPi = std::numbers::pi;

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
  const CompleteEllipticIntegrals ke = complete_elliptic_integrals(e);
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
    const CompleteEllipticIntegrals ke = complete_elliptic_integrals(std::sqrt(1.0 - k * k));
    kfirst = ke.first;
    ksecond = ke.second;
  }
  HertzCoefficients out;
  out.m = std::cbrt(2.0 * ksecond / (kPi * k * k));
  out.n = k * out.m;
  out.r = 2.0 * kfirst / (kPi * out.m);
  return out;
}

HertzCurvatures hertz_curvatures(double curvature_x, double curvature_y, const char* where) {
  if (std::isnan(curvature_x) || std::isnan(curvature_y) ||
      !(std::max(curvature_x, curvature_y) > 0.0) ||
      !std::isfinite(std::min(curvature_x, curvature_y))) {
    throw std::invalid_argument(fmt::format(
        "{}: relative curvatures A = {}, B = {} [1/m]: both must be finite and the larger > 0",
        where, curvature_x, curvature_y));
  }
  double ax = std::min(curvature_x, kHertzMaxCurvature);
  double ay = std::min(curvature_y, kHertzMaxCurvature);
  const double floor = kHertzMinCurvatureRatio * std::max(ax, ay);
  return HertzCurvatures{std::max(ax, floor), std::max(ay, floor)};
}

HertzSolution hertz_solve(double curvature_x_in, double curvature_y_in, double normal_force,
                          double contact_modulus) {
  const HertzCurvatures cv = hertz_curvatures(curvature_x_in, curvature_y_in, "hertz_solve");
  const double curvature_x = cv.x, curvature_y = cv.y;
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
    const CompleteEllipticIntegrals ke = complete_elliptic_integrals(std::sqrt(1.0 - k * k));
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

namespace {

// The Hertz relation at a given approach, as functions of u = ln(rho), rho = larger/smaller
// curvature: k = minor/major, g1 = sqrt(E/(k^2 K)), g2 = (2 pi/3) sqrt(E)/(k K^1.5), so that
// with S = A + B: major = g1 sqrt(delta/S), F = E* g2 delta^1.5 / sqrt(S) (from Johnson (3.64)-
// (3.72): delta = a^2 k^2 S K / E, F = 2 pi E* k^2 S a^3 / (3 E)). All three are analytic in u
// >= 0 (e^2 is analytic in rho - 1), so the stencil at u = 0 is closed by a ghost node
// extrapolated quadratically (not by symmetry: k(|u|) has a kink at u = 0).
class ApproachRelation {
 public:
  static constexpr int kNodes = 4096;
  static constexpr double kUMax = 13.815510557964274;  // ln(1e6)
  ApproachRelation() {
    h_ = kUMax / (kNodes - 1);
    inv_h_ = 1.0 / h_;
    for (int i = 0; i < kNodes + 2; ++i) exact(i * h_, lnk_[i], lng1_[i], lng2_[i]);
  }
  static void exact(double u, double& lnk, double& lng1, double& lng2) {
    const double k = hertz_axis_ratio(std::exp(u));
    double kk = 0.5 * kPi, ee = 0.5 * kPi;
    if (k < 1.0) {
      const CompleteEllipticIntegrals ke = complete_elliptic_integrals(std::sqrt(1.0 - k * k));
      kk = ke.first;
      ee = ke.second;
    }
    lnk = std::log(k);
    lng1 = 0.5 * (std::log(ee) - 2.0 * std::log(k) - std::log(kk));
    lng2 = std::log(2.0 * kPi / 3.0) + 0.5 * std::log(ee) - std::log(k) - 1.5 * std::log(kk);
  }
  // Catmull-Rom cubic on the uniform grid; exact evaluation beyond the table.
  void eval(double u, double& lnk, double& lng1, double& lng2) const {
    if (!(u < kUMax)) {
      exact(u, lnk, lng1, lng2);
      return;
    }
    const double s = u * inv_h_;
    const int i = static_cast<int>(s);
    const double t = s - i;
    const double t2 = t * t, t3 = t2 * t;
    const double w0 = -0.5 * t3 + t2 - 0.5 * t;
    const double w1 = 1.5 * t3 - 2.5 * t2 + 1.0;
    const double w2 = -1.5 * t3 + 2.0 * t2 + 0.5 * t;
    const double w3 = 0.5 * t3 - 0.5 * t2;
    auto at = [&](const std::array<double, kNodes + 2>& f) {
      const double before = i == 0 ? 3.0 * f[0] - 3.0 * f[1] + f[2] : f[i - 1];
      return w0 * before + w1 * f[i] + w2 * f[i + 1] + w3 * f[i + 2];
    };
    lnk = at(lnk_);
    lng1 = at(lng1_);
    lng2 = at(lng2_);
  }

 private:
  double h_ = 0.0, inv_h_ = 0.0;
  std::array<double, kNodes + 2> lnk_{}, lng1_{}, lng2_{};
};

const ApproachRelation& approach_relation() {
  static const ApproachRelation relation;
  return relation;
}

}  // namespace

HertzSolution hertz_solve_from_approach(double curvature_x_in, double curvature_y_in,
                                        double approach, double contact_modulus) {
  const HertzCurvatures cv =
      hertz_curvatures(curvature_x_in, curvature_y_in, "hertz_solve_from_approach");
  if (!(contact_modulus > 0.0) || !std::isfinite(contact_modulus)) {
    throw std::invalid_argument(
        fmt::format("hertz_solve_from_approach: contact_modulus must be finite and > 0 [Pa], "
                    "got {}",
                    contact_modulus));
  }
  if (std::isnan(approach) || std::isinf(approach)) {
    throw std::invalid_argument(
        fmt::format("hertz_solve_from_approach: approach must be finite [m], got {}", approach));
  }
  HertzSolution s;
  if (!(approach > 0.0)) {
    s.semi_axis_x = s.semi_axis_y = 0.0;
    s.approach = 0.0;
    s.peak_pressure = 0.0;
    s.normal_force = 0.0;
    return s;
  }
  const double small = std::min(cv.x, cv.y), large = std::max(cv.x, cv.y);
  double lnk, lng1, lng2;
  approach_relation().eval(std::log(large / small), lnk, lng1, lng2);
  const double sum = cv.x + cv.y;
  const double root = std::sqrt(approach / sum);
  const double major = std::exp(lng1) * root;
  const double minor = std::exp(lnk) * major;
  s.normal_force = contact_modulus * std::exp(lng2) * approach * root;
  s.semi_axis_x = cv.x <= cv.y ? major : minor;
  s.semi_axis_y = cv.x <= cv.y ? minor : major;
  s.approach = approach;
  s.peak_pressure = 3.0 * s.normal_force / (2.0 * kPi * major * minor);
  return s;
}

double HertzSolution::pressure(double x, double y) const {
  const double u =
      1.0 - (x / semi_axis_x) * (x / semi_axis_x) - (y / semi_axis_y) * (y / semi_axis_y);
  return u > 0.0 ? peak_pressure * std::sqrt(u) : 0.0;
}

}  // namespace ferro::contact
