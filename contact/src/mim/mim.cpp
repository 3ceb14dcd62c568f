// One-call MIM rolling contact: normal, then steady rolling.
//
// References: Toumi (2016) chapter 2, eqs. (74)-(123).
// Known deviations: see normal_solver.hpp and tangential_solver.hpp.

#include "ferro/contact/mim/mim.hpp"

#include "ferro/contact/mim/hertz_gap.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ferro::contact::mim {

void NormalLoad::validate(const std::string& where) const {
  const bool has_force = !std::isnan(normal_force);
  const bool has_approach = !std::isnan(approach);
  if (has_force == has_approach) {
    throw std::invalid_argument(fmt::format(
        "{}: set exactly one of normal_force (N) and approach (m), got {} and {}", where,
        normal_force, approach));
  }
  if (has_force && !(normal_force > 0.0 && std::isfinite(normal_force))) {
    throw std::invalid_argument(
        fmt::format("{}.normal_force: must be finite and > 0 N, got {}", where, normal_force));
  }
  if (has_approach && !std::isfinite(approach)) {
    throw std::invalid_argument(fmt::format("{}.approach: must be finite (m), got {}", where, approach));
  }
}

void HertzRollingInput::validate(const std::string& where) const {
  if (!(semi_axis_x > 0.0) || !(semi_axis_y > 0.0)) {
    throw std::invalid_argument(fmt::format("{}.semi_axis_x/semi_axis_y: must be > 0 m, got {} and {}",
                                            where, semi_axis_x, semi_axis_y));
  }
  if (!(normal_force > 0.0) || !std::isfinite(normal_force)) {
    throw std::invalid_argument(fmt::format("{}.normal_force: must be > 0 N, got {}", where, normal_force));
  }
  if (elements_minor < 4) {
    throw std::invalid_argument(fmt::format("{}.elements_minor: must be >= 4, got {}", where, elements_minor));
  }
  rolling.validate(where + ".rolling");
  body1.validate(where + ".body1");
  body2.validate(where + ".body2");
}

MimResult solve_rolling_contact(InfluenceOperator& op, const Field& gap, const NormalLoad& load,
                                const RollingInput& rolling, const MimOptions& options) {
  load.validate();
  rolling.validate();
  const NormalSolution n = std::isnan(load.normal_force)
                               ? solve_normal_approach(op, gap, load.approach, options.normal)
                               : solve_normal_force(op, gap, load.normal_force, options.normal);
  const TangentialSolution t = solve_steady_rolling(op, n.pressure, rolling, options.tangential);
  MimResult r;
  r.grid = op.grid();
  r.normal_force = n.normal_force;
  r.approach = n.approach;
  r.force_x = t.force_x;
  r.force_y = t.force_y;
  r.moment_z = t.moment_z;
  r.pressure = n.pressure;
  r.traction_x = t.traction_x;
  r.traction_y = t.traction_y;
  r.slip_x = t.slip_x;
  r.slip_y = t.slip_y;
  r.state = t.state;
  r.normal_iterations = n.iterations;
  r.gap_residual = n.gap_residual;
  r.penetration_residual = n.penetration_residual;
  r.tangential_matvecs = t.matvecs;
  r.stick_residual = t.stick_residual;
  r.direction_residual = t.direction_residual;
  r.coulomb_residual = t.coulomb_residual;
  r.converged = n.converged && t.converged;
  return r;
}

MimResult solve_hertz_rolling(const HertzRollingInput& input, const MimOptions& options) {
  input.validate();
  const CombinedMaterial m = combine(input.body1, input.body2);
  const HertzGap hg = hertz_gap_for_ellipse(input.semi_axis_x, input.semi_axis_y,
                                            input.normal_force, m.contact_modulus);
  const Grid grid = grid_for_ellipse(input.semi_axis_x, input.semi_axis_y, input.elements_minor);
  InfluenceOperator op(grid, m);
  NormalLoad load;
  load.normal_force = input.normal_force;
  return solve_rolling_contact(op, quadratic_gap(grid, hg.curvature_x, hg.curvature_y), load,
                               input.rolling, options);
}

}  // namespace ferro::contact::mim
