#pragma once
// Private parts of the integrator adapters: their factories and the checks they make after every
// step.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ferro/vehicle/integrator.hpp"

namespace ferro::vehicle::detail {
std::unique_ptr<Integrator> make_cvode(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_arkode_erk(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_arkode_dirk(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_odeint(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_bdf2(const IntegratorSettings& settings);

/// What every adapter checks between right-hand sides and after each accepted step: the stop
/// request, and the divergence guard (every state finite and within the system's
/// state_bounds()).
class StepMonitor {
 public:
  StepMonitor(const OdeSystem& system, const StopRequest& stop);
  [[nodiscard]] bool stop_requested() const { return stop_ && stop_(); }
  /// Empty when `x` (the state at the end of a step at time t) is finite and within bounds;
  /// otherwise the cause, naming the state, its value, the bound and t.
  [[nodiscard]] std::string divergence(double t, std::span<const double> x) const;

 private:
  const OdeSystem& system_;
  const StopRequest& stop_;
  std::vector<StateBound> bounds_;
};

/// Thrown from a right-hand-side wrapper when a stop was requested (Odeint adapters).
struct StopRequested {};

}  // namespace ferro::vehicle::detail
