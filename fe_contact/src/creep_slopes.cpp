// K_ij from initial creep-curve slopes of two operators on one grid; creep curves.
//
// References: Toumi (2016) section 3.1.3.4, eqs. (146)-(147), (156).
// Known deviations: see creep_slopes.hpp (secant at a probe creepage; tau_c as a bound cap).

#include "ferro/fe_contact/creep_slopes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ferro::fe_contact {

namespace mim = contact::mim;

void SlopeOptions::validate(const std::string& where) const {
  if (!(probe_creepage > 0.0 && probe_creepage < 1.0e-3)) {
    throw std::invalid_argument(
        fmt::format("{}.probe_creepage: must be in (0, 1e-3), got {}", where, probe_creepage));
  }
  if (!(probe_spin_times_a > 0.0 && probe_spin_times_a < 1.0e-3)) {
    throw std::invalid_argument(fmt::format("{}.probe_spin_times_a: must be in (0, 1e-3), got {}",
                                            where, probe_spin_times_a));
  }
  mim.normal.validate(where + ".mim.normal");
  mim.tangential.validate(where + ".mim.tangential");
}

void SlopeCase::validate(const std::string& where) const {
  if (!(normal_force > 0.0) || !std::isfinite(normal_force)) {
    throw std::invalid_argument(
        fmt::format("{}.normal_force: must be finite and > 0 N, got {}", where, normal_force));
  }
  if (!(friction > 0.0) || !std::isfinite(friction)) {
    throw std::invalid_argument(
        fmt::format("{}.friction: must be finite and > 0, got {}", where, friction));
  }
  if (!(yield_shear > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{}.yield_shear: must be > 0 Pa (inf: no cap), got {}", where, yield_shear));
  }
  if (!(semi_axis_x > 0.0) || !std::isfinite(semi_axis_x)) {
    throw std::invalid_argument(
        fmt::format("{}.semi_axis_x: must be finite and > 0 m, got {}", where, semi_axis_x));
  }
}

mim::Field capped_pressure(const mim::Field& pressure, double friction, double yield_shear) {
  mim::Field p = pressure;
  if (std::isfinite(yield_shear)) {
    const double cap = yield_shear / friction;
    for (double& v : p) v = std::min(v, cap);
  }
  return p;
}

namespace {

mim::NormalGridSolution normal_solve(mim::ComplianceOperator& op, const mim::Field& gap,
                                     const SlopeCase& c, const SlopeOptions& options) {
  mim::NormalGridSolution n = mim::solve_normal_force(op, gap, c.normal_force, options.mim.normal);
  if (n.boundary_contact_elements > 0) {
    throw std::runtime_error(fmt::format(
        "creep_stiffness: the contact patch reaches the grid boundary ({} elements); enlarge "
        "the grid",
        n.boundary_contact_elements));
  }
  return n;
}

mim::TangentialGridSolution rolling(mim::ComplianceOperator& op, const mim::Field& bound_pressure,
                                    double friction, double xi_x, double xi_y, double spin,
                                    const SlopeOptions& options) {
  mim::RollingInput in;
  in.creepage_x = xi_x;
  in.creepage_y = xi_y;
  in.spin = spin;
  in.friction = friction;
  mim::TangentialSolverOptions t = options.mim.tangential;
  t.nested = t.nested && op.has_coarse();
  return mim::solve_steady_rolling(op, bound_pressure, in, t);
}

}  // namespace

CreepStiffness creep_stiffness(mim::ComplianceOperator& op, const mim::Field& gap,
                               const SlopeCase& c, const SlopeOptions& options) {
  c.validate();
  options.validate();
  const mim::NormalGridSolution n = normal_solve(op, gap, c, options);
  const mim::Field p = capped_pressure(n.pressure, c.friction, c.yield_shear);
  const double xi = options.probe_creepage;
  const double phi = options.probe_spin_times_a / c.semi_axis_x;
  const mim::TangentialGridSolution rx = rolling(op, p, c.friction, xi, 0.0, 0.0, options);
  const mim::TangentialGridSolution ry = rolling(op, p, c.friction, 0.0, xi, 0.0, options);
  const mim::TangentialGridSolution rs = rolling(op, p, c.friction, 0.0, 0.0, phi, options);
  // Moment about the patch centre: the grid is centred on the contact point.
  CreepStiffness s;
  s.s11 = -rx.force_x / xi;
  s.s22 = -ry.force_y / xi;
  s.s23 = -rs.force_y / phi;
  s.s33 = -rs.moment_z / phi;
  s.normal_force = n.normal_force;
  s.contact_elements = n.contact_elements;
  s.converged = n.converged && rx.converged && ry.converged && rs.converged;
  return s;
}

SlopeResult reduction_factors(mim::ComplianceOperator& modified,
                              mim::ComplianceOperator& half_space, const mim::Field& gap,
                              const SlopeCase& c, const SlopeOptions& options) {
  const mim::Grid& a = modified.grid();
  const mim::Grid& b = half_space.grid();
  if (a.nx != b.nx || a.ny != b.ny || a.dx != b.dx || a.dy != b.dy || a.x0 != b.x0 ||
      a.y0 != b.y0) {
    throw std::invalid_argument(
        "reduction_factors: the modified and half-space operators must be on the same grid");
  }
  SlopeResult r;
  r.modified = creep_stiffness(modified, gap, c, options);
  r.half_space = creep_stiffness(half_space, gap, c, options);
  r.update_ratios();
  return r;
}

void SlopeResult::update_ratios() {
  k.k11 = modified.s11 / half_space.s11;
  k.k22 = modified.s22 / half_space.s22;
  k.k23 = modified.s23 / half_space.s23;
  k.k33 = modified.s33 / half_space.s33;
  converged = modified.converged && half_space.converged;
}

CreepCurve creep_curve(mim::ComplianceOperator& op, const mim::Field& gap, const SlopeCase& c,
                       char direction, const std::vector<double>& creepages,
                       const SlopeOptions& options) {
  c.validate();
  options.validate();
  if (direction != 'x' && direction != 'y') {
    throw std::invalid_argument(
        fmt::format("creep_curve: direction must be 'x' or 'y', got '{}'", direction));
  }
  const mim::NormalGridSolution n = normal_solve(op, gap, c, options);
  const mim::Field p = capped_pressure(n.pressure, c.friction, c.yield_shear);
  CreepCurve out;
  out.direction = direction;
  out.converged = n.converged;
  for (std::size_t i = 0; i < creepages.size(); ++i) {
    const double xi = creepages[i];
    if (!std::isfinite(xi) || (i > 0 && !(xi > creepages[i - 1]))) {
      throw std::invalid_argument(fmt::format(
          "creep_curve: creepages must be finite and strictly increasing (index {})", i));
    }
    const mim::TangentialGridSolution t = direction == 'x'
                                              ? rolling(op, p, c.friction, xi, 0.0, 0.0, options)
                                              : rolling(op, p, c.friction, 0.0, xi, 0.0, options);
    out.creepage.push_back(xi);
    out.force.push_back(direction == 'x' ? t.force_x : t.force_y);
    out.converged = out.converged && t.converged;
    out.derivative.push_back(
        i == 0 ? kNaN : (out.force[i] - out.force[i - 1]) / (xi - creepages[i - 1]));
  }
  return out;
}

}  // namespace ferro::fe_contact
