// FaStrip (Sichani, Enblom & Berg 2016). See fastrip.hpp for references and known deviations.
#include "ferro/contact/tangential/fastrip.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ferro/contact/tangential/fastsim.hpp"

namespace ferro::contact {
namespace {

constexpr double kPi = std::numbers::pi;

// Integral of sqrt(1 - t^2) from 0 to s, s clamped to [-1, 1].
inline double half_disc(double s) {
  if (s >= 1.0) return 0.25 * kPi;
  if (s <= -1.0) return -0.25 * kPi;
  return 0.5 * (s * std::sqrt(1.0 - s * s) + std::asin(s));
}

struct StripInput {
  double y, width, xc, l;  // strip centre y, width, centre x, half-length [m]
  double p_peak;           // p0 of the strip (load-corrected) [Pa]
  double tau;              // Carter's reduced creepage of the strip [-]
  double dir_x, dir_y;     // unit direction of Kalker's weighted creepage (zero when tau = 0)
  double spin_gain;        // phi / (2 L3) (spin-corrected) [Pa/m^2]
  double rate_x, rate_y;   // slip-zone traction rates (xi - phi y)/L, eta/L [Pa/m]
};

// One strip, leading edge x = xc + l, material flowing towards -x. Element averages: the bound
// mu p0 mean(sqrt(1 - s^2)) (shape), Carter's traction bound - mu p0 u^2 mean(sqrt(1 - s'^2)),
// s' = 1 - (1 - s)/u over the adhesion zone, and the spin traction -phi/(2 L3) (x_lead^2 -
// mean(x^2)).
void sweep(const StripInput& s, const std::vector<double>& shape, double mu, StripSums& acc,
           TractionMap* map) {
  const int mx = static_cast<int>(shape.size());
  const double dx = 2.0 * s.l / mx;
  const double ds = 2.0 / mx;
  const double bound_peak = mu * s.p_peak;
  const double u = std::max(0.0, 1.0 - s.tau);  // adhesion half-length / l of the creepages
  const double u2 = u * u;
  double e_prev = u > 0.0 ? half_disc(1.0) : -0.25 * kPi;
  double q_prev = 0.0;
  double x_edge = s.xc + s.l;
  double sq_prev = x_edge * x_edge;
  double tx = 0.0, ty = 0.0;
  double sfx = 0.0, sfy = 0.0, smz = 0.0, adhesion = 0.0;
  // Carter's adhesion zone ends at x_end; the first element past it blends Carter's value (the
  // bound) into FASTSIM's update by how close x_end is to its leading edge, so that the forces
  // are continuous in the creepages when x_end crosses an element boundary.
  const double x_end = s.xc + s.l * (1.0 - 2.0 * u);
  bool first_past = true;
  const auto cap = [](double& vx, double& vy, double bound) {
    const double v2 = vx * vx + vy * vy;
    if (v2 > bound * bound) {
      const double scale = bound / std::sqrt(v2);
      vx *= scale;
      vy *= scale;
    }
  };
  for (int k = 0; k < mx; ++k) {
    const double bound_shape = shape[static_cast<std::size_t>(k)];
    const double bound = bound_peak * bound_shape;
    const double x_next = x_edge - dx;
    const double sq = (x_edge * x_edge + x_edge * x_next + x_next * x_next) / 3.0;
    const double spin_y = -s.spin_gain * (sq_prev - sq);
    if (k == 0 || e_prev > -0.25 * kPi) {
      // Carter's adhesion zone of the creepages (and the leading element): Carter's increment.
      double inner = 0.0;
      if (e_prev > -0.25 * kPi) {
        const double e_next = half_disc(1.0 - (static_cast<double>(k + 1) * ds) / u);
        inner = u2 * (e_prev - e_next) / ds;
        e_prev = e_next;
      }
      const double q = bound_peak * (bound_shape - inner);
      tx -= s.dir_x * (q - q_prev);
      ty -= s.dir_y * (q - q_prev) - spin_y;
      q_prev = q;
      cap(tx, ty, bound);
    } else {
      // Past it: the rigid-slip increment with one flexibility turns the traction towards the
      // slip direction (FASTSIM's update), the bound caps it.
      double ax = tx - s.rate_x * dx, ay = ty - s.rate_y * dx + spin_y;
      cap(ax, ay, bound);
      if (first_past) {
        first_past = false;
        const double beta = std::clamp(1.0 - (x_end - x_edge) / dx, 0.0, 1.0);
        double bx = tx - s.dir_x * (bound - q_prev), by = ty - s.dir_y * (bound - q_prev) + spin_y;
        cap(bx, by, bound);
        ax += beta * (bx - ax);
        ay += beta * (by - ay);
      }
      tx = ax;
      ty = ay;
    }
    const double t2 = tx * tx + ty * ty;
    // On the bound (to round-off) counts as slip: Carter's slip zone lies exactly on it.
    const bool slipping = t2 >= bound * bound * (1.0 - 1e-12);
    if (!slipping) adhesion += 1.0;
    const double x = x_edge - 0.5 * dx;
    sfx += tx;
    sfy += ty;
    smz += x * ty - s.y * tx;
    if (map != nullptr) {
      map->x.push_back(x);
      map->y.push_back(s.y);
      map->dx.push_back(dx);
      map->dy.push_back(s.width);
      map->pressure.push_back(s.p_peak * bound_shape);
      map->traction_x.push_back(tx);
      map->traction_y.push_back(ty);
      map->slip.push_back(slipping ? 1 : 0);
    }
    sq_prev = sq;
    x_edge = x_next;
  }
  acc.add_strip(sfx, sfy, smz, mx, adhesion, dx * s.width);
}

}  // namespace

void FastripOptions::validate() const {
  validate_strip_grid("fastrip", mx, my);
}

FastripModel::FastripModel(FastripOptions options) : options_(options) {
  options_.validate();
  const int mx = options_.mx;
  const double ds = 2.0 / mx;
  shape_.resize(static_cast<std::size_t>(mx));
  for (int k = 0; k < mx; ++k) {
    const double s0 = 1.0 - k * ds, s1 = 1.0 - (k + 1) * ds;
    shape_[static_cast<std::size_t>(k)] = (half_disc(s0) - half_disc(s1)) / ds;
  }
}

TangentialSolution FastripModel::solve(const TangentialProblem& problem) const {
  problem.validate();
  const LinearCreepStiffness k = linear_creep_stiffness(problem, options_.source);
  const ContactPatch& patch = *problem.patch;
  const double a = k.a, b = k.b, g = k.shear_modulus;
  const double mu = problem.friction;
  const double fn = patch.normal_force;
  const Creepage& cr = problem.creepage;
  // Flexibilities of eq. (44) with the reduced coefficients.
  const double l1 = 8.0 * a / (3.0 * k.c.c11 * g);
  const double l2 = 8.0 * a / (3.0 * k.c.c22 * g);
  const double l3 = kPi * a * a / (4.0 * g * std::sqrt(a * b) * k.c.c23);
  double lx = l1, ly = l1;  // slip-zone flexibility
  if (options_.slip_flexibility == SlipFlexibility::kThree) ly = l2;
  if (options_.slip_flexibility == SlipFlexibility::kWeighted) {
    const double c = std::sqrt(a * b);
    const double norm = std::sqrt(cr.longitudinal * cr.longitudinal + cr.lateral * cr.lateral +
                                  c * c * cr.spin * cr.spin);
    if (norm > 0.0) {
      lx = ly = (std::abs(cr.longitudinal) * l1 + std::abs(cr.lateral) * l2 +
                 c * std::abs(cr.spin) * l3) /
                norm;
    }
  }
  // Kalker's weighted creepage w = G a b (C11 (xi - phi y), C22 eta) / (2 mu F_n): the linear
  // force is 2 mu F_n w; each strip's Carter creepage is tau_i = w T / p0_i (Carter's saturation
  // creepage is proportional to the strip's own peak pressure), T such that sum 2 mu P_i tau_i =
  // 2 mu F_n |w| (P_i: strip loads), i.e. Kalker's linear slopes.
  const double limit = mu * fn;
  const double wx_scale = limit > 0.0 ? g * a * b * k.c.c11 / (2.0 * limit) : 0.0;
  const double wy = limit > 0.0 ? g * a * b * k.c.c22 * cr.lateral / (2.0 * limit) : 0.0;
  if (problem.map != nullptr) problem.map->clear();
  StripSums acc;
  const auto strip = [&](double y, double width, double xc, double l, double p_peak,
                         double tau_factor, double spin_gain) {
    const double xi = cr.longitudinal - cr.spin * y;
    const double wx = wx_scale * xi;
    const double w = std::hypot(wx, wy);
    StripInput in{
        y,   width, xc,        l,       p_peak,         limit > 0.0 ? w * tau_factor : 1.0,
        0.0, 0.0,   spin_gain, xi / lx, cr.lateral / ly};
    if (w > 0.0 && limit > 0.0) {
      in.dir_x = wx / w;
      in.dir_y = wy / w;
    }
    sweep(in, shape_, mu, acc, problem.map);
  };
  if (patch.elliptic()) {
    const int my = options_.my;
    const double dy = 2.0 * b / my;
    // Strip j: r_j = sqrt(1 - y_j^2/b^2), l_j = a r_j, p0_j ~ r_j, load ~ r_j^2 dy. The loads
    // are scaled to sum to F_n; the spin flexibility so that sum (4/3) l_j^3 dy equals its exact
    // integral pi a^3 b / 2 (FASTSIM's linear spin force G (ab)^1.5 C23 phi).
    double load = 0.0, spin_integral = 0.0, tau_integral = 0.0;
    for (int j = 0; j < my; ++j) {
      const double y = -b + (j + 0.5) * dy;
      const double r2 = 1.0 - (y / b) * (y / b);
      load += r2 * dy;
      spin_integral += r2 * std::sqrt(r2) * dy;
      tau_integral += std::sqrt(r2) * dy;
    }
    const double p0_scale = 2.0 * fn / (kPi * a * load);  // p0_j = p0_scale r_j
    const double spin_gain = 0.5 * cr.spin / l3 * (0.375 * kPi * b) / spin_integral;
    const double tau_scale = load / tau_integral;  // tau_j = |w_j| tau_scale / r_j
    for (int j = 0; j < my; ++j) {
      const double y = -b + (j + 0.5) * dy;
      const double r = std::sqrt(1.0 - (y / b) * (y / b));
      strip(y, dy, 0.0, a * r, p0_scale * r, tau_scale / r, spin_gain);
    }
  } else {
    double load = 0.0, tau_integral = 0.0;
    for (const PatchStrip& s : patch.strips) {
      if (!(s.half_length > 0.0) || !(s.peak_pressure > 0.0)) continue;
      const double p = s.peak_pressure * s.half_length * s.width;
      load += p;
      tau_integral += p / s.peak_pressure;
    }
    const double tau_scale = tau_integral > 0.0 ? load / tau_integral : 0.0;
    const double spin_gain = 0.5 * cr.spin / l3;
    for (const PatchStrip& s : patch.strips) {
      if (!(s.half_length > 0.0) || !(s.peak_pressure > 0.0)) continue;
      strip(s.y, s.width, s.x_center, s.half_length, s.peak_pressure, tau_scale / s.peak_pressure,
            spin_gain);
    }
  }
  return acc.solution();
}

std::unique_ptr<TangentialModel> FastripModel::from_options(const ModelOptions& options) {
  check_option_keys("fastrip", options, {"coefficients", "mx", "my", "slip_flexibility"});
  FastripOptions o;
  o.source = coefficients_option(options);
  o.mx = option_int(options, "mx", o.mx);
  o.my = option_int(options, "my", o.my);
  o.slip_flexibility =
      option_choice<SlipFlexibility>("fastrip", options, "slip_flexibility",
                                     {{"longitudinal", SlipFlexibility::kLongitudinal},
                                      {"weighted", SlipFlexibility::kWeighted},
                                      {"three", SlipFlexibility::kThree}},
                                     "longitudinal");
  return std::make_unique<FastripModel>(o);
}

}  // namespace ferro::contact
