#include "ferro/vehicle/integrator.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "integrator_impl.hpp"

namespace ferro::vehicle {

const std::vector<std::string>& available_integrators() {
  static const std::vector<std::string> kNames = {"cvode_bdf",     "cvode_adams",
                                                  "arkode_erk",    "arkode_dirk",
                                                  "odeint_dopri5", "odeint_rosenbrock4",
                                                  "odeint_bs3",    "bdf2"};
  return kNames;
}

bool takes_fixed_step(const std::string& method) {
  return method == "arkode_erk" || method == "arkode_dirk" || method == "odeint_bs3" ||
         method == "bdf2";
}

void IntegratorSettings::validate(const std::string& where) const {
  const auto& names = available_integrators();
  if (std::find(names.begin(), names.end(), method) == names.end()) {
    throw std::invalid_argument(fmt::format("{}.integrator: unknown integrator '{}'; allowed: {}",
                                            where, method, fmt::join(names, ", ")));
  }
  if (!(rtol > 0.0 && rtol < 1.0)) {
    throw std::invalid_argument(fmt::format("{}.rtol: must lie in (0, 1), got {}", where, rtol));
  }
  if (!(atol > 0.0) || !std::isfinite(atol)) {
    throw std::invalid_argument(
        fmt::format("{}.atol: must be finite and > 0, got {}", where, atol));
  }
  if (!(max_step > 0.0)) {
    throw std::invalid_argument(fmt::format("{}.max_step: must be > 0 s, got {}", where, max_step));
  }
  if (!(initial_step >= 0.0) || !std::isfinite(initial_step)) {
    throw std::invalid_argument(fmt::format(
        "{}.initial_step: must be >= 0 s (0 = automatic), got {}", where, initial_step));
  }
  if (linear_solver != "dense" && linear_solver != "band") {
    throw std::invalid_argument(
        fmt::format("{}.linear_solver: unknown '{}'; allowed: dense, band", where, linear_solver));
  }
  if (max_steps < 1) {
    throw std::invalid_argument(
        fmt::format("{}.max_steps: must be >= 1, got {}", where, max_steps));
  }
  if (max_order != 0 && method != "cvode_bdf" && method != "cvode_adams") {
    throw std::invalid_argument(fmt::format(
        "{}.max_order: only cvode_bdf (1..5) and cvode_adams (1..12) take an order cap; {} "
        "needs 0, got {}",
        where, method, max_order));
  }
  if (max_order < 0 || max_order > 12 || (method == "cvode_bdf" && max_order > 5)) {
    throw std::invalid_argument(fmt::format(
        "{}.max_order: must be 0 (the method's own) or 1..5 for cvode_bdf, 1..12 for "
        "cvode_adams, got {}",
        where, max_order));
  }
  if (!(fixed_step >= 0.0) || !std::isfinite(fixed_step)) {
    throw std::invalid_argument(fmt::format(
        "{}.fixed_step: must be >= 0 s (0 = adaptive steps), got {}", where, fixed_step));
  }
  if (fixed_step > 0.0 && !takes_fixed_step(method)) {
    throw std::invalid_argument(fmt::format(
        "{}.fixed_step: only arkode_erk, arkode_dirk, odeint_bs3 and bdf2 take a fixed step; {} needs "
        "0, got {}",
        where, method, fixed_step));
  }
  if ((method == "odeint_bs3" || method == "bdf2") && !(fixed_step > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "{}.fixed_step: {} runs at a fixed step only; give a step > 0 s", where, method));
  }
  if (jacobian_max_steps < 1) {
    throw std::invalid_argument(fmt::format(
        "{}.jacobian_max_steps: must be >= 1 (steps between two Jacobians), got {}", where,
        jacobian_max_steps));
  }
  if (erk_order < 2 || erk_order > 8) {
    throw std::invalid_argument(
        fmt::format("{}.erk_order: must lie in 2..8, got {}", where, erk_order));
  }
}

std::string to_string(IntegrationResult::Status status) {
  switch (status) {
    case IntegrationResult::Status::kCompleted:
      return "completed";
    case IntegrationResult::Status::kInterrupted:
      return "interrupted";
    case IntegrationResult::Status::kSolverFailure:
      return "solver_failure";
  }
  return "unknown";
}

std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings) {
  settings.validate();
  if (settings.method == "cvode_bdf" || settings.method == "cvode_adams") {
    return detail::make_cvode(settings);
  }
  if (settings.method == "arkode_erk") return detail::make_arkode_erk(settings);
  if (settings.method == "arkode_dirk") return detail::make_arkode_dirk(settings);
  if (settings.method == "bdf2") return detail::make_bdf2(settings);
  return detail::make_odeint(settings);
}

std::vector<double> output_grid(double t0, double t_end, double dt) {
  if (!(dt > 0.0) || !(t_end >= t0) || !std::isfinite(t_end)) {
    throw std::invalid_argument(fmt::format(
        "output_grid: need dt > 0 and t_end >= t0, got t0={}, t_end={}, dt={}", t0, t_end, dt));
  }
  std::vector<double> times;
  const auto n = static_cast<long>(std::floor((t_end - t0) / dt + 1e-9));
  times.reserve(static_cast<std::size_t>(n) + 2);
  for (long i = 0; i <= n; ++i) times.push_back(t0 + static_cast<double>(i) * dt);
  if (t_end - times.back() > 1e-9 * dt) times.push_back(t_end);
  return times;
}

}  // namespace ferro::vehicle
