// FASTSIM (Kalker 1982). See fastsim.hpp for references and known deviations.
#include "ferro/contact/fastsim.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ferro::contact {
namespace {

struct Inverse {
  double f1, f2, f3;  // 1/L1, 1/L2, 1/L3 [Pa/m]
};

struct Accumulator {
  double fx = 0.0, fy = 0.0, mz = 0.0;
  double area = 0.0, adhesion_area = 0.0;
};

// One strip: leading edge at x = xc + l, material flows towards x = xc - l.
inline void strip_sweep(double y, double w, double xc, double l, double ppar, int mx,
                        const Creepage& cr, const Inverse& inv, double mu, Accumulator& acc,
                        TractionMap* map) {
  const double dx = 2.0 * l / mx;
  const double slip_x = cr.longitudinal * inv.f1 - cr.spin * y * inv.f3;  // d(px)/dx * -1
  const double half_spin = 0.5 * cr.spin * inv.f3;
  double px = 0.0, py = 0.0;
  double x_prev = xc + l;
  double sfx = 0.0, sfy = 0.0, smz = 0.0, adhesion = 0.0;
  const double inv_l2 = 1.0 / (l * l);
  for (int k = 0; k < mx; ++k) {
    const double x = xc + l - (k + 0.5) * dx;
    const double d = x_prev - x;
    // Exact integral of the rigid slip over [x, x_prev] (eqs. 27, 41-43).
    px -= slip_x * d;
    py -= cr.lateral * inv.f2 * d + half_spin * (x_prev * x_prev - x * x);
    const double u = x - xc;
    const double bound = mu * ppar * (1.0 - u * u * inv_l2);
    const double t2 = px * px + py * py;
    bool slipping = false;
    if (t2 > bound * bound) {
      const double scale = bound / std::sqrt(t2);
      px *= scale;
      py *= scale;
      slipping = true;
    } else {
      adhesion += 1.0;
    }
    sfx += px;
    sfy += py;
    smz += x * py - y * px;
    if (map != nullptr) {
      map->x.push_back(x);
      map->y.push_back(y);
      map->dx.push_back(dx);
      map->dy.push_back(w);
      map->pressure.push_back(ppar * (1.0 - u * u * inv_l2));
      map->traction_x.push_back(px);
      map->traction_y.push_back(py);
      map->slip.push_back(slipping ? 1 : 0);
    }
    x_prev = x;
  }
  const double da = dx * w;
  acc.fx += sfx * da;
  acc.fy += sfy * da;
  acc.mz += smz * da;
  acc.area += mx * da;
  acc.adhesion_area += adhesion * da;
}

}  // namespace

void FastsimOptions::validate() const {
  if (mx < 1 || mx > 10000) {
    throw std::invalid_argument(fmt::format("fastsim.mx: must lie in [1, 10000], got {}", mx));
  }
  if (my < 1 || my > 10000) {
    throw std::invalid_argument(fmt::format("fastsim.my: must lie in [1, 10000], got {}", my));
  }
}

FastsimModel::FastsimModel(FastsimOptions options) : options_(options) {
  options_.validate();
}

TangentialSolution FastsimModel::solve(const TangentialProblem& problem) const {
  problem.validate();
  constexpr double kPi = std::numbers::pi;
  const LinearCreepStiffness k = linear_creep_stiffness(problem, options_.source);
  const ContactPatch& patch = *problem.patch;
  const double a = k.a, b = k.b, g = k.shear_modulus;
  // Flexibilities, eq. (44), with the reduced coefficients.
  const double l1 = 8.0 * a / (3.0 * k.c.c11 * g);
  const double l2 = 8.0 * a / (3.0 * k.c.c22 * g);
  const double l3 = kPi * a * a / (4.0 * g * std::sqrt(a * b) * k.c.c23);
  Inverse inv{1.0 / l1, 1.0 / l2, 1.0 / l3};
  const Creepage& cr = problem.creepage;
  if (options_.flexibility == Flexibility::kWeighted) {
    const double c = std::sqrt(a * b);
    const double norm = std::sqrt(cr.longitudinal * cr.longitudinal + cr.lateral * cr.lateral +
                                  c * c * cr.spin * cr.spin);
    const double l = norm > 0.0 ? (std::abs(cr.longitudinal) * l1 + std::abs(cr.lateral) * l2 +
                                   c * std::abs(cr.spin) * l3) /
                                      norm
                                : l1;
    inv = Inverse{1.0 / l, 1.0 / l, 1.0 / l};
  }
  const double mu = problem.friction;
  if (problem.map != nullptr) problem.map->clear();
  Accumulator acc;
  if (patch.elliptic()) {
    const int my = options_.my;
    const double dy = 2.0 * b / my;
    const double p_scale = 2.0 * patch.normal_force / (kPi * a * b);  // parabolic pressure
    for (int j = 0; j < my; ++j) {
      const double y = -b + (j + 0.5) * dy;
      const double r = 1.0 - (y / b) * (y / b);
      strip_sweep(y, dy, 0.0, a * std::sqrt(r), p_scale * r, options_.mx, cr, inv, mu, acc,
                  problem.map);
    }
  } else {
    for (const PatchStrip& s : patch.strips) {
      if (!(s.half_length > 0.0)) continue;
      strip_sweep(s.y, s.width, s.x_center, s.half_length, 3.0 * kPi / 8.0 * s.peak_pressure,
                  options_.mx, cr, inv, mu, acc, problem.map);
    }
  }
  TangentialSolution out;
  out.force_x = acc.fx;
  out.force_y = acc.fy;
  out.moment_z = acc.mz;
  out.adhesion_fraction = acc.area > 0.0 ? acc.adhesion_area / acc.area : ContactPatch::kNaN;
  return out;
}

}  // namespace ferro::contact
