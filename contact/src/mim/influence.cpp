// Closed-form influence coefficients of a uniformly loaded rectangle on the half-space.
//
// References: Toumi (2016) annex B.3, eqs. (B.13)-(B.20); Love (1929) for A^zz.
// Known deviations: K = 0 (quasi-identical bodies), see influence.hpp.

#include "ferro/contact/mim/influence.hpp"

#include <cmath>
#include <numbers>

namespace ferro::contact::mim {
namespace {

// ln(u + rho) with rho = sqrt(u^2 + v^2), written without cancellation for u < 0:
// u + rho = v^2 / (rho - u).
double log_u_plus_rho(double u, double v, double rho) {
  if (u >= 0.0) return std::log(u + rho);
  return std::log(v * v / (rho - u));
}

// a * ln(b) with the convention 0 * ln(0) = 0 (a corner on an axis).
double times_log(double a, double log_b) {
  return a == 0.0 ? 0.0 : a * log_b;
}

struct Primitives {
  double i1 = 0.0;  // v ln(u + rho) + u ln(v + rho)
  double i2 = 0.0;  // v ln(u + rho)
  double i3 = 0.0;  // -rho
  double i4 = 0.0;  // u ln(v + rho)
};

Primitives primitives(double u, double v) {
  const double rho = std::hypot(u, v);
  Primitives p;
  if (rho == 0.0) return p;
  const double lu = log_u_plus_rho(u, v, rho);
  const double lv = log_u_plus_rho(v, u, rho);
  p.i2 = times_log(v, lu);
  p.i4 = times_log(u, lv);
  p.i1 = p.i2 + p.i4;
  p.i3 = -rho;
  return p;
}

}  // namespace

InfluenceCoefficients influence_coefficients(double x, double y, double dx, double dy,
                                             const CombinedMaterial& material) {
  // [[F]] = F(u2, v2) - F(u1, v2) - F(u2, v1) + F(u1, v1) with u = x - zeta, v = y - eta.
  const double u1 = x - 0.5 * dx;
  const double u2 = x + 0.5 * dx;
  const double v1 = y - 0.5 * dy;
  const double v2 = y + 0.5 * dy;
  const Primitives a = primitives(u2, v2);
  const Primitives b = primitives(u1, v2);
  const Primitives c = primitives(u2, v1);
  const Primitives d = primitives(u1, v1);
  const double i1 = a.i1 - b.i1 - c.i1 + d.i1;
  const double i2 = a.i2 - b.i2 - c.i2 + d.i2;
  const double i3 = a.i3 - b.i3 - c.i3 + d.i3;
  const double i4 = a.i4 - b.i4 - c.i4 + d.i4;

  const double nu = material.poisson;
  const double scale = 1.0 / (std::numbers::pi * material.shear_modulus);
  InfluenceCoefficients out;
  out.zz = scale * (1.0 - nu) * i1;
  out.xx = scale * ((1.0 - nu) * i1 + nu * i2);
  out.yy = scale * ((1.0 - nu) * i1 + nu * i4);
  out.xy = scale * nu * i3;
  return out;
}

}  // namespace ferro::contact::mim
