#pragma once
// C++17-compatible bridge to Boost.Odeint's rosenbrock4. Boost 1.74's uBLAS (which rosenbrock4
// needs) does not compile as C++20, so that one translation unit is built as C++17 and talks
// to the rest of the library through this plain interface.
#include <functional>
#include <string>
#include <vector>

namespace ferro::vehicle::detail {

struct RawSettings {
  double rtol, atol, max_dt, initial_step;
  long max_steps;
};

struct RawResult {
  int status = 0;  // 0 completed, 1 interrupted, 2 failure
  double t_reached = 0.0;
  std::vector<double> state;
  std::string message;
  long steps = 0;
};

// rhs(t, x, xdot) returns the OdeSystem code; jac(t, x, J row-major, dfdt) throws on failure;
// observe(t, x) returns false to stop; check_step(t, x) after every step returns the cause of a
// divergence (empty: the state is acceptable).
RawResult rosenbrock4_run(std::size_t n, const std::vector<double>& x0,
                          const std::vector<double>& times, const RawSettings& settings,
                          const std::function<int(double, const double*, double*)>& rhs,
                          const std::function<void(double, const double*, double*, double*)>& jac,
                          const std::function<bool(double, const double*)>& observe,
                          const std::function<std::string(double, const double*)>& check_step);

}  // namespace ferro::vehicle::detail
