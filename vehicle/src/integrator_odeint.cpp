// Boost.Odeint adapters: runge_kutta_dopri5 with dense output, rosenbrock4 (linearly
// implicit, 4th order) with a central-difference Jacobian of the system, and odeint_bs3: the
// order-3 Bogacki-Shampine formula at a fixed step with no error control, as Odeint's generic
// explicit Runge-Kutta stepper.
//
// References: Bogacki & Shampine, "A 3(2) pair of Runge-Kutta formulas", Appl. Math. Lett. 2
// (1989) 321-325: c = (0, 1/2, 3/4), a21 = 1/2, a31 = 0, a32 = 3/4, b = (2/9, 1/3, 4/9). The
// pair's fourth stage (first same as last) serves only its embedded error estimate, which a
// fixed step does not use, so a step takes 3 right-hand sides (the first one is the previous
// step's end slope). Outputs between two steps are read from the cubic Hermite interpolant of
// the step's end values and slopes (third order, as the method).
//
// Known deviations: Odeint has no notion of a recoverable right-hand-side error; a positive
// return code from rhs() is reported as a solver failure (with time, state and cause) instead of
// being retried with a smaller step as SUNDIALS does.
#include <fmt/format.h>

#include <boost/numeric/odeint/integrate/integrate.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/array.hpp>
#include <boost/fusion/include/make_vector.hpp>
#include <boost/numeric/odeint/stepper/explicit_generic_rk.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "integrator_impl.hpp"
#include "odeint_rosenbrock_raw.hpp"

namespace ferro::vehicle::detail {
namespace odeint = boost::numeric::odeint;
namespace {

struct RhsFailure : std::runtime_error {
  RhsFailure(int code, double t)
      : std::runtime_error(fmt::format("right-hand side returned {} ({}) at t = {:.9g} s", code,
                                       code > 0 ? "recoverable; Odeint cannot retry" : "fatal", t)),
        time(t) {}
  double time;
};

struct StepLimit : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws the cause when the state of a step that ended at t fails the divergence guard.
template <class V>
void throw_if_diverged(const StepMonitor& monitor, const V& x, double t) {
  std::string cause = monitor.divergence(t, std::span<const double>(&x[0], x.size()));
  if (!cause.empty()) throw std::runtime_error(cause);
}

// Runs a dense-output stepper through the output times. State type V is std::vector<double> or
// ublas::vector<double>.
template <class Dense, class System, class V>
IntegrationResult dense_loop(Dense& stepper, System sys, V x, const std::vector<double>& times,
                             const Observer& observer, const IntegratorSettings& s,
                             long& rhs_count, const StepMonitor& monitor) {
  IntegrationResult result;
  const std::size_t n = x.size();
  auto record = [&](double t, const V& state) {
    // The interpolant between two accepted steps may leave the bounds the step ends keep.
    if (t != times.front()) throw_if_diverged(monitor, state, t);
    result.t_reached = t;
    result.state.assign(state.begin(), state.end());
    return observer(t, result.state);
  };
  if (!record(times.front(), x)) {
    result.status = IntegrationResult::Status::kInterrupted;
    return result;
  }
  const double span = times.back() - times.front();
  double dt0 = s.initial_step > 0.0 ? s.initial_step : std::max(span, 1e-12) * 1e-6;
  if (std::isfinite(s.max_step)) dt0 = std::min(dt0, s.max_step);
  stepper.initialize(x, times.front(), dt0);
  std::size_t next = 1;
  long steps_since_output = 0;
  V out(n);
  try {
    while (next < times.size()) {
      while (next < times.size() && times[next] <= stepper.current_time()) {
        stepper.calc_state(times[next], out);
        if (!record(times[next], out)) {
          result.status = IntegrationResult::Status::kInterrupted;
          return result;
        }
        ++next;
        steps_since_output = 0;
      }
      if (next >= times.size()) break;
      if (++steps_since_output > s.max_steps) {
        throw StepLimit(fmt::format("more than max_steps = {} steps before output t = {:.9g} s",
                                    s.max_steps, times[next]));
      }
      stepper.do_step(sys);
      ++result.steps;
      if (monitor.stop_requested()) throw StopRequested{};
      throw_if_diverged(monitor, stepper.current_state(), stepper.current_time());
    }
  } catch (const StopRequested&) {
    // The stepper keeps the state of its last completed step.
    result.status = IntegrationResult::Status::kInterrupted;
    result.t_reached = stepper.current_time();
    const auto& xc = stepper.current_state();
    result.state.assign(xc.begin(), xc.end());
  } catch (const std::exception& e) {
    result.status = IntegrationResult::Status::kSolverFailure;
    result.message = fmt::format("{} at t = {:.9g} s (last output t = {:.9g} s): {}", s.method,
                                 stepper.current_time(), result.t_reached, e.what());
    result.t_reached = stepper.current_time();
    const auto& xc = stepper.current_state();
    result.state.assign(xc.begin(), xc.end());
  }
  result.rhs_evaluations = rhs_count;
  return result;
}

// Runs the Bogacki-Shampine formula at the fixed step s.fixed_step from times.front(): step k
// ends at t0 + k h exactly (no accumulated rounding), outputs on a step end take its state, the
// others the cubic Hermite interpolant of the step they fall in.
IntegrationResult bs3_fixed_step_loop(const OdeSystem& system, std::span<const double> x0,
                                      const std::vector<double>& times, const Observer& observer,
                                      const IntegratorSettings& s, const StepMonitor& monitor) {
  using State = std::vector<double>;
  using Bs3 = odeint::explicit_generic_rk<3, 3, State, double>;
  const boost::array<double, 1> a1 = {{0.5}};
  const boost::array<double, 2> a2 = {{0.0, 0.75}};
  const Bs3::coef_a_type a = boost::fusion::make_vector(a1, a2);
  const Bs3::coef_b_type b = {{2.0 / 9.0, 1.0 / 3.0, 4.0 / 9.0}};
  const Bs3::coef_c_type c = {{0.0, 0.5, 0.75}};
  Bs3 stepper(a, b, c);

  IntegrationResult result;
  const std::size_t n = system.size();
  long rhs_count = 0;
  auto sys = [&](const State& y, State& dydt, double t) {
    if (monitor.stop_requested()) throw StopRequested{};
    ++rhs_count;
    const int rc = system.rhs(t, y, dydt);
    if (rc != kRhsOk) throw RhsFailure(rc, t);
  };
  State x(x0.begin(), x0.end()), x_next(n), f(n), f_next(n), out(n);
  const double t0 = times.front();
  const double h = s.fixed_step;
  const double eps = 1e-9 * h;  // an output this close to a step end is on it
  auto record = [&](double t, const State& state) {
    // The interpolant between two steps may leave the bounds the step ends keep (the outputs
    // at the start itself are the initial state).
    if (t > t0 + eps) throw_if_diverged(monitor, state, t);
    result.t_reached = t;
    result.state.assign(state.begin(), state.end());
    return observer(t, result.state);
  };
  if (!record(t0, x)) {
    result.status = IntegrationResult::Status::kInterrupted;
    return result;
  }
  std::size_t next = 1;
  for (; next < times.size() && times[next] <= t0 + eps; ++next) {
    if (!record(times[next], x)) {  // outputs at the start itself
      result.status = IntegrationResult::Status::kInterrupted;
      return result;
    }
  }
  double t = t0;
  long steps_since_output = 0;
  try {
    if (next < times.size()) sys(x, f, t);
    while (next < times.size()) {
      if (++steps_since_output > s.max_steps) {
        throw StepLimit(fmt::format("more than max_steps = {} steps before output t = {:.9g} s",
                                    s.max_steps, times[next]));
      }
      const double t_next = t0 + static_cast<double>(result.steps + 1) * h;
      stepper.do_step(sys, x, f, t, x_next, h);
      ++result.steps;
      // A step that leaves the bounds ends the run with the offending state.
      if (std::string cause = monitor.divergence(t_next, x_next); !cause.empty()) {
        result.status = IntegrationResult::Status::kSolverFailure;
        result.message = fmt::format("{} at t = {:.9g} s (last output t = {:.9g} s): {}",
                                     s.method, t_next, result.t_reached, cause);
        result.t_reached = t_next;
        result.state = x_next;
        result.rhs_evaluations = rhs_count;
        return result;
      }
      // The end slope: the next step's first stage and the interpolant's second slope, needed
      // unless this step ends the run on its last output.
      const bool inside = times[next] < t_next - eps;
      const bool more = times.back() > t_next + eps;
      if (inside || more) sys(x_next, f_next, t_next);
      for (; next < times.size() && times[next] <= t_next + eps; ++next) {
        const double to = times[next];
        const bool on_step_end = to >= t_next - eps;
        if (!on_step_end) {
          const double th = (to - t) / h, u = 1.0 - th;
          const double h00 = (1.0 + 2.0 * th) * u * u, h10 = th * u * u * h;
          const double h01 = th * th * (3.0 - 2.0 * th), h11 = -th * th * u * h;
          for (std::size_t i = 0; i < n; ++i)
            out[i] = h00 * x[i] + h10 * f[i] + h01 * x_next[i] + h11 * f_next[i];
        }
        if (!record(to, on_step_end ? x_next : out)) {
          result.status = IntegrationResult::Status::kInterrupted;
          result.rhs_evaluations = rhs_count;
          return result;
        }
        steps_since_output = 0;
      }
      x.swap(x_next);
      f.swap(f_next);
      t = t_next;
      if (monitor.stop_requested()) throw StopRequested{};
    }
  } catch (const StopRequested&) {
    // x is the state at the end of the last completed step, t its time.
    result.status = IntegrationResult::Status::kInterrupted;
    result.t_reached = t;
    result.state.assign(x.begin(), x.end());
  } catch (const std::exception& e) {
    result.status = IntegrationResult::Status::kSolverFailure;
    result.message = fmt::format("{} at t = {:.9g} s (last output t = {:.9g} s): {}", s.method, t,
                                 result.t_reached, e.what());
    result.t_reached = t;
    result.state.assign(x.begin(), x.end());
  }
  result.rhs_evaluations = rhs_count;
  return result;
}

class OdeintIntegrator final : public Integrator {
 public:
  explicit OdeintIntegrator(IntegratorSettings s) : s_(std::move(s)) {}
  [[nodiscard]] std::string name() const override { return s_.method; }

  IntegrationResult integrate(const OdeSystem& system, std::span<const double> x0,
                              const std::vector<double>& times, const Observer& observer) override {
    const std::size_t n = system.size();
    long rhs_count = 0;
    const double max_dt = std::isfinite(s_.max_step) ? s_.max_step : 0.0;
    const StepMonitor monitor(system, stop_);
    if (s_.method == "odeint_bs3")
      return bs3_fixed_step_loop(system, x0, times, observer, s_, monitor);
    if (s_.method == "odeint_dopri5") {
      using State = std::vector<double>;
      auto sys = [&](const State& x, State& dxdt, double t) {
        if (monitor.stop_requested()) throw StopRequested{};
        ++rhs_count;
        const int rc = system.rhs(t, x, dxdt);
        if (rc != kRhsOk) throw RhsFailure(rc, t);
      };
      auto stepper =
          odeint::make_dense_output(s_.atol, s_.rtol, max_dt, odeint::runge_kutta_dopri5<State>());
      return dense_loop(stepper, sys, State(x0.begin(), x0.end()), times, observer, s_, rhs_count,
                        monitor);
    }
    // rosenbrock4 runs in a C++17 translation unit (see odeint_rosenbrock_raw.hpp).
    std::vector<double> fp(n), fm(n);
    bool stopped = false;  // a stop request ended a right-hand side
    auto rhs = [&](double t, const double* x, double* xdot) {
      if (monitor.stop_requested()) {
        stopped = true;
        return kRhsFatal;
      }
      ++rhs_count;
      return system.rhs(t, std::span<const double>(x, n), std::span<double>(xdot, n));
    };
    auto jac = [&](double t, const double* x, double* J, double* dfdt) {
      const std::span<const double> xs(x, n);
      const auto rows = numerical_jacobian(system, t, xs);
      std::copy(rows.begin(), rows.end(), J);
      const double ht = 1e-7 * std::max(1.0, std::abs(t));
      if (system.rhs(t + ht, xs, fp) != kRhsOk || system.rhs(t - ht, xs, fm) != kRhsOk) {
        throw RhsFailure(kRhsFatal, t);
      }
      rhs_count += 2 * static_cast<long>(n) + 2;
      for (std::size_t i = 0; i < n; ++i) dfdt[i] = (fp[i] - fm[i]) / (2.0 * ht);
    };
    std::string output_divergence;  // an interpolated output beyond the bounds
    auto observe = [&](double t, const double* x) {
      if (t != times.front()) {
        output_divergence = monitor.divergence(t, std::span<const double>(x, n));
        if (!output_divergence.empty()) return false;
      }
      return observer(t, std::span<const double>(x, n));
    };
    auto check_step = [&](double t, const double* x) {
      return monitor.divergence(t, std::span<const double>(x, n));
    };
    const RawSettings raw{s_.rtol, s_.atol, max_dt, s_.initial_step, s_.max_steps};
    RawResult r = rosenbrock4_run(n, std::vector<double>(x0.begin(), x0.end()), times, raw, rhs,
                                  jac, observe, check_step);
    IntegrationResult result;
    result.status = r.status == 0   ? IntegrationResult::Status::kCompleted
                    : r.status == 1 || stopped ? IntegrationResult::Status::kInterrupted
                                               : IntegrationResult::Status::kSolverFailure;
    result.t_reached = r.t_reached;
    result.state = std::move(r.state);
    if (!stopped) result.message = std::move(r.message);
    if (!output_divergence.empty()) {
      result.status = IntegrationResult::Status::kSolverFailure;
      result.message = fmt::format("odeint_rosenbrock4 at output t = {:.9g} s: {}", r.t_reached,
                                   output_divergence);
    }
    result.steps = r.steps;
    result.rhs_evaluations = rhs_count;
    return result;
  }

 private:
  IntegratorSettings s_;
};

}  // namespace

std::unique_ptr<Integrator> make_odeint(const IntegratorSettings& settings) {
  return std::make_unique<OdeintIntegrator>(settings);
}

}  // namespace ferro::vehicle::detail
