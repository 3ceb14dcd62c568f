// FASTSIM (Kalker 1982). See fastsim.hpp for references and known deviations.
#include "ferro/contact/tangential/fastsim.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ferro::contact {
namespace {

// tau^2 beyond which the adaptive stiffening stays constant (tau = 3: full slip everywhere).
constexpr double kAdaptiveCap = 9.0;

struct Inverse {
  double f1, f2, f3;  // 1/L1, 1/L2, 1/L3 [Pa/m]
};

// Pressure shape along a strip, s = (x - xc) / l in [-1, 1].
inline double bound_shape(TractionBound bound, double s2) {
  return bound == TractionBound::kParabolic ? 1.0 - s2 : std::sqrt(std::max(0.0, 1.0 - s2));
}

// Midpoint sum of the shape over mx elements of [-1, 1] times 2/mx, and the exact integral
// (4/3 parabolic, pi/2 elliptic): their ratio scales the element pressures so that the strip
// carries its load exactly (the full-slip force is then mu F_n, never above).
inline double strip_load_correction(TractionBound bound, int mx) {
  double sum = 0.0;
  for (int k = 0; k < mx; ++k) {
    const double s = 1.0 - (k + 0.5) * 2.0 / mx;
    sum += bound_shape(bound, s * s);
  }
  const double exact = bound == TractionBound::kParabolic ? 4.0 / 3.0 : 0.5 * std::numbers::pi;
  return exact / (sum * 2.0 / mx);
}

// One strip: leading edge at x = xc + l, material flows towards x = xc - l. ppar: peak of the
// strip's pressure (already corrected by strip_load_correction).
inline void strip_sweep(double y, double w, double xc, double l, double ppar, int mx,
                        TractionBound shape, const Creepage& cr, const Inverse& inv, double mu,
                        StripSums& acc, TractionMap* map) {
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
    const double pressure = ppar * bound_shape(shape, u * u * inv_l2);
    const double bound = mu * pressure;
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
      map->pressure.push_back(pressure);
      map->traction_x.push_back(px);
      map->traction_y.push_back(py);
      map->slip.push_back(slipping ? 1 : 0);
    }
    x_prev = x;
  }
  acc.add_strip(sfx, sfy, smz, mx, adhesion, dx * w);
}

}  // namespace

void validate_strip_grid(const char* model, int mx, int my) {
  if (mx < 1 || mx > 10000) {
    throw std::invalid_argument(fmt::format("{}.mx: must lie in [1, 10000], got {}", model, mx));
  }
  if (my < 1 || my > 10000) {
    throw std::invalid_argument(fmt::format("{}.my: must lie in [1, 10000], got {}", model, my));
  }
}

void FastsimOptions::validate() const {
  validate_strip_grid("fastsim", mx, my);
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
  if (options_.flexibility == Flexibility::kAdaptive) {
    const TangentialSolution lin = k.forces(cr);
    const double limit = problem.friction * patch.normal_force;
    const double tau = limit > 0.0 ? std::hypot(lin.force_x, lin.force_y) / limit : 0.0;
    const double stiff = 1.0 + options_.stiffening * std::min(tau * tau, kAdaptiveCap);
    inv = Inverse{stiff / l1, stiff / l2, stiff / l3};
  }
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
  StripSums acc;
  const TractionBound shape = options_.bound;
  const bool parabolic = shape == TractionBound::kParabolic;
  const double along = strip_load_correction(shape, options_.mx);
  if (patch.elliptic()) {
    const int my = options_.my;
    const double dy = 2.0 * b / my;
    // Strip peak pressures p_j = p_scale r_j^e (parabolic: p = 2F/(pi ab)(1 - x^2/a^2 - y^2/b^2),
    // e = 1; Hertz: p0 = 3F/(2 pi ab), e = 1/2), strip loads p_j l_j * (4/3 or pi/2); their sum
    // over the strips is scaled to F_n.
    double p_scale = parabolic ? 2.0 * patch.normal_force / (kPi * a * b)
                               : 1.5 * patch.normal_force / (kPi * a * b);
    double load = 0.0;
    for (int j = 0; j < my; ++j) {
      const double y = -b + (j + 0.5) * dy;
      const double r = 1.0 - (y / b) * (y / b);
      const double peak = parabolic ? p_scale * r : p_scale * std::sqrt(r);
      load += peak * a * std::sqrt(r) * dy * (parabolic ? 4.0 / 3.0 : 0.5 * kPi);
    }
    p_scale *= patch.normal_force / load * along;
    for (int j = 0; j < my; ++j) {
      const double y = -b + (j + 0.5) * dy;
      const double r = 1.0 - (y / b) * (y / b);
      const double peak = parabolic ? p_scale * r : p_scale * std::sqrt(r);
      strip_sweep(y, dy, 0.0, a * std::sqrt(r), peak, options_.mx, shape, cr, inv, mu, acc,
                  problem.map);
    }
  } else {
    for (const PatchStrip& s : patch.strips) {
      if (!(s.half_length > 0.0)) continue;
      const double peak = (parabolic ? 3.0 * kPi / 8.0 : 1.0) * s.peak_pressure * along;
      strip_sweep(s.y, s.width, s.x_center, s.half_length, peak, options_.mx, shape, cr, inv, mu,
                  acc, problem.map);
    }
  }
  return acc.solution();
}

std::unique_ptr<TangentialModel> FastsimModel::from_options(const ModelOptions& options) {
  check_option_keys("fastsim", options,
                    {"coefficients", "mx", "my", "flexibility", "bound", "stiffening"});
  FastsimOptions o;
  o.source = coefficients_option(options);
  o.mx = option_int(options, "mx", o.mx);
  o.my = option_int(options, "my", o.my);
  o.flexibility = option_choice<Flexibility>("fastsim", options, "flexibility",
                                             {{"three", Flexibility::kThree},
                                              {"weighted", Flexibility::kWeighted},
                                              {"adaptive", Flexibility::kAdaptive}},
                                             "three");
  o.stiffening = option_double(options, "stiffening", o.stiffening);
  if (!(o.stiffening >= 0.0 && o.stiffening <= 1.0)) {
    throw std::invalid_argument(
        fmt::format("fastsim option 'stiffening': must lie in [0, 1], got {}", o.stiffening));
  }
  o.bound = option_choice<TractionBound>(
      "fastsim", options, "bound",
      {{"parabolic", TractionBound::kParabolic}, {"elliptic", TractionBound::kElliptic}},
      "parabolic");
  return std::make_unique<FastsimModel>(o);
}

}  // namespace ferro::contact
