// Boost.Odeint rosenbrock4 (linearly implicit, order 4, embedded error estimate, dense output).
// Built as C++17: see odeint_rosenbrock_raw.hpp.
#include "odeint_rosenbrock_raw.hpp"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ferro::vehicle::detail {
namespace odeint = boost::numeric::odeint;

RawResult rosenbrock4_run(std::size_t n, const std::vector<double>& x0,
                          const std::vector<double>& times, const RawSettings& s,
                          const std::function<int(double, const double*, double*)>& rhs,
                          const std::function<void(double, const double*, double*, double*)>& jac,
                          const std::function<bool(double, const double*)>& observe,
                          const std::function<std::string(double, const double*)>& check_step) {
  using State = boost::numeric::ublas::vector<double>;
  using Matrix = boost::numeric::ublas::matrix<double>;
  RawResult result;
  std::vector<double> xs(n), fs(n), jrows(n * n), dfdt_buf(n);
  auto sys = [&](const State& x, State& dxdt, double t) {
    std::copy(x.begin(), x.end(), xs.begin());
    const int rc = rhs(t, xs.data(), fs.data());
    if (rc != 0) {
      std::ostringstream msg;
      msg << "right-hand side returned " << rc
          << (rc > 0 ? " (recoverable; Odeint cannot retry)" : " (fatal)") << " at t = " << t
          << " s";
      throw std::runtime_error(msg.str());
    }
    std::copy(fs.begin(), fs.end(), dxdt.begin());
  };
  auto jacobian = [&](const State& x, Matrix& J, double t, State& dfdt) {
    std::copy(x.begin(), x.end(), xs.begin());
    jac(t, xs.data(), jrows.data(), dfdt_buf.data());
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) J(i, j) = jrows[i * n + j];
      dfdt[i] = dfdt_buf[i];
    }
  };
  auto stepper = odeint::make_dense_output(s.atol, s.rtol, s.max_dt, odeint::rosenbrock4<double>());
  State x(n), out(n);
  std::copy(x0.begin(), x0.end(), x.begin());
  auto record = [&](double t, const State& st) {
    result.t_reached = t;
    result.state.assign(st.begin(), st.end());
    return observe(t, result.state.data());
  };
  if (!record(times.front(), x)) {
    result.status = 1;
    return result;
  }
  const double span = times.back() - times.front();
  double dt0 = s.initial_step > 0.0 ? s.initial_step : std::max(span, 1e-12) * 1e-6;
  if (s.max_dt > 0.0) dt0 = std::min(dt0, s.max_dt);
  stepper.initialize(x, times.front(), dt0);
  std::size_t next = 1;
  long since_output = 0;
  try {
    while (next < times.size()) {
      while (next < times.size() && times[next] <= stepper.current_time()) {
        stepper.calc_state(times[next], out);
        if (!record(times[next], out)) {
          result.status = 1;
          return result;
        }
        ++next;
        since_output = 0;
      }
      if (next >= times.size()) break;
      if (++since_output > s.max_steps) {
        std::ostringstream msg;
        msg << "more than max_steps = " << s.max_steps
            << " steps before output t = " << times[next];
        throw std::runtime_error(msg.str());
      }
      stepper.do_step(std::make_pair(sys, jacobian));
      ++result.steps;
      const auto& xc = stepper.current_state();
      std::copy(xc.begin(), xc.end(), xs.begin());
      const std::string cause = check_step(stepper.current_time(), xs.data());
      if (!cause.empty()) throw std::runtime_error(cause);
    }
  } catch (const std::exception& e) {
    std::ostringstream msg;
    msg << "odeint_rosenbrock4 at t = " << stepper.current_time()
        << " s (last output t = " << result.t_reached << " s): " << e.what();
    result.status = 2;
    result.message = msg.str();
    result.t_reached = stepper.current_time();
    const auto& xc = stepper.current_state();
    result.state.assign(xc.begin(), xc.end());
  }
  return result;
}

}  // namespace ferro::vehicle::detail
