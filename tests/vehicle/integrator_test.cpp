// Integrator adapters against closed forms: a damped oscillator x'' + 2 z w x' + w^2 x = 0 has an
// exact solution; every adapter must reproduce it, report failures with time and cause, and stop
// when the observer asks.
#include "ferro/vehicle/integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace ferro::vehicle {
namespace {

constexpr double kOmega = 2.0 * std::numbers::pi * 1.5;  // [rad/s]
constexpr double kZeta = 0.05;

class DampedOscillator final : public OdeSystem {
 public:
  explicit DampedOscillator(double fail_after = INFINITY) : fail_after_(fail_after) {}
  std::size_t size() const override { return 2; }
  int rhs(double t, std::span<const double> x, std::span<double> xd) const override {
    if (t > fail_after_) return kRhsFatal;
    xd[0] = x[1];
    xd[1] = -kOmega * kOmega * x[0] - 2.0 * kZeta * kOmega * x[1];
    return kRhsOk;
  }
  std::vector<SignalInfo> state_info() const override { return {{"x", "m", ""}, {"v", "m/s", ""}}; }

 private:
  double fail_after_;
};

double exact(double t) {  // x(0) = 1, v(0) = 0
  const double wd = kOmega * std::sqrt(1.0 - kZeta * kZeta);
  return std::exp(-kZeta * kOmega * t) *
         (std::cos(wd * t) + kZeta * kOmega / wd * std::sin(wd * t));
}

class EveryIntegrator : public ::testing::TestWithParam<std::string> {
 protected:
  /// The method under test; odeint_bs3, which runs at a fixed step only, at 1 ms (global error
  /// ~3e-7 on the oscillator, inside kGlobalErrorTol; outputs every 10 ms land on steps); bdf2
  /// (second order) at 10 us (~1.5e-7).
  IntegratorSettings settings() const {
    IntegratorSettings s;
    s.method = GetParam();
    if (s.method == "odeint_bs3") s.fixed_step = 1e-3;
    if (s.method == "bdf2") s.fixed_step = 1e-5;
    return s;
  }
};

TEST_P(EveryIntegrator, damped_oscillator_closed_form) {
  IntegratorSettings s = settings();
  s.rtol = 1e-9;
  s.atol = 1e-12;
  auto integ = make_integrator(s);
  DampedOscillator sys;
  const auto times = output_grid(0.0, 5.0, 0.01);
  double max_err = 0.0;
  std::size_t calls = 0;
  const std::vector<double> x0{1.0, 0.0};
  const auto r = integ->integrate(sys, x0, times, [&](double t, std::span<const double> x) {
    EXPECT_DOUBLE_EQ(t, times[calls]);
    ++calls;
    max_err = std::max(max_err, std::abs(x[0] - exact(t)));
    return true;
  });
  EXPECT_EQ(r.status, IntegrationResult::Status::kCompleted) << r.message;
  EXPECT_EQ(calls, times.size());
  // Global error of a tolerance-controlled method over ~7 periods: within 1000 x rtol of the
  // unit amplitude is generous for every method at rtol = 1e-9 and still catches a wrong
  // adapter (a wrong sign or a stale state gives O(1) errors); the fixed-step method's 1 ms
  // keeps it below too.
  constexpr double kGlobalErrorTol = 1e-6;
  EXPECT_LT(max_err, kGlobalErrorTol) << GetParam();
  EXPECT_GT(r.steps, 0);
  EXPECT_GT(r.rhs_evaluations, 0);
}

TEST_P(EveryIntegrator, fatal_rhs_is_reported_with_time_and_state) {
  const IntegratorSettings s = settings();
  auto integ = make_integrator(s);
  DampedOscillator sys(/*fail_after=*/0.7);
  const auto times = output_grid(0.0, 2.0, 0.1);
  double last_output = -1.0;
  const std::vector<double> x0{1.0, 0.0};
  const auto r = integ->integrate(sys, x0, times, [&](double t, std::span<const double>) {
    last_output = t;
    return true;
  });
  EXPECT_EQ(r.status, IntegrationResult::Status::kSolverFailure);
  EXPECT_LE(last_output, 0.7 + 1e-12);
  EXPECT_GE(last_output, 0.6 - 1e-12);
  // The failure is reported where the solver stood: within a step of the failing time.
  EXPECT_LE(r.t_reached, 0.71);
  EXPECT_GE(r.t_reached, 0.6);
  EXPECT_EQ(r.state.size(), 2u);
  EXPECT_NE(r.message.find("t = "), std::string::npos) << r.message;
}

TEST_P(EveryIntegrator, observer_stops_the_run) {
  const IntegratorSettings s = settings();
  auto integ = make_integrator(s);
  DampedOscillator sys;
  const auto times = output_grid(0.0, 2.0, 0.1);
  const std::vector<double> x0{1.0, 0.0};
  int calls = 0;
  const auto r = integ->integrate(sys, x0, times,
                                  [&](double, std::span<const double>) { return ++calls < 5; });
  EXPECT_EQ(r.status, IntegrationResult::Status::kInterrupted);
  EXPECT_EQ(calls, 5);
  EXPECT_NEAR(r.t_reached, 0.4, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Adapters, EveryIntegrator, ::testing::ValuesIn(available_integrators()));

TEST(IntegratorSettings, unknown_method_names_the_allowed_ones) {
  IntegratorSettings s;
  s.method = "euler";
  try {
    s.validate();
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("cvode_bdf"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("euler"), std::string::npos);
  }
}

TEST(IntegratorSettings, banded_newton_matches_dense) {
  for (const char* method : {"cvode_bdf", "arkode_dirk"}) {
    DampedOscillator sys;
    const auto times = output_grid(0.0, 3.0, 0.05);
    const std::vector<double> x0{1.0, 0.0};
    std::vector<double> dense, band;
    for (const char* ls : {"dense", "band"}) {
      IntegratorSettings s;
      s.method = method;
      s.linear_solver = ls;
      s.rtol = 1e-10;
      s.atol = 1e-13;
      auto& out = std::string(ls) == "dense" ? dense : band;
      make_integrator(s)->integrate(sys, x0, times, [&](double, std::span<const double> x) {
        out.push_back(x[0]);
        return true;
      });
    }
    // The two Newton solvers also form their Jacobians by different difference quotients, so
    // they agree to the integration error, not to round-off: each within 1000 x rtol of the
    // closed form, as in damped_oscillator_closed_form.
    constexpr double kGlobalErrorTol = 1e-7;
    ASSERT_EQ(dense.size(), times.size());
    ASSERT_EQ(band.size(), times.size());
    for (std::size_t i = 0; i < times.size(); ++i) {
      EXPECT_NEAR(dense[i], exact(times[i]), kGlobalErrorTol) << method << " dense";
      EXPECT_NEAR(band[i], exact(times[i]), kGlobalErrorTol) << method << " band";
    }
  }
}

TEST(IntegratorSettings, max_order_outside_the_method_range_is_rejected) {
  IntegratorSettings s;
  s.max_order = 6;
  try {
    s.validate("solver");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("solver.max_order"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1..5"), std::string::npos) << e.what();
  }
  s.method = "cvode_adams";
  EXPECT_NO_THROW(s.validate("solver"));
  s.method = "odeint_dopri5";  // no order to cap: refused, not ignored
  EXPECT_THROW(s.validate("solver"), std::invalid_argument);
}

TEST(IntegratorSettings, jacobian_max_steps_below_one_is_rejected) {
  IntegratorSettings s;
  s.jacobian_max_steps = 0;
  try {
    s.validate("solver");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("solver.jacobian_max_steps"), std::string::npos)
        << e.what();
  }
}

TEST(IntegratorSettings, fixed_step_only_for_the_fixed_step_methods) {
  IntegratorSettings s;
  s.fixed_step = 1e-3;
  s.method = "cvode_bdf";  // adaptive only: refused, not ignored
  try {
    s.validate("solver");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("solver.fixed_step"), std::string::npos) << e.what();
  }
  s.method = "arkode_erk";
  EXPECT_NO_THROW(s.validate("solver"));
  s.method = "odeint_bs3";
  EXPECT_NO_THROW(s.validate("solver"));
  s.fixed_step = -1e-3;
  EXPECT_THROW(s.validate("solver"), std::invalid_argument);
  s.fixed_step = 0.0;  // odeint_bs3 has no error control: a step is required
  try {
    s.validate("solver");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("odeint_bs3 runs at a fixed step only"),
              std::string::npos)
        << e.what();
  }
}

// Largest deviation from the closed form over 5 s with a constant step h.
double fixed_step_error(const std::string& method, int erk_order, double h, long* steps) {
  IntegratorSettings s;
  s.method = method;
  s.erk_order = erk_order;
  s.fixed_step = h;
  s.rtol = 1e-6;  // only the implicit method's Newton test uses it
  s.atol = 1e-12;
  auto integ = make_integrator(s);
  DampedOscillator sys;
  const auto times = output_grid(0.0, 5.0, 0.05);
  double max_err = 0.0;
  const std::vector<double> x0{1.0, 0.0};
  const auto r = integ->integrate(sys, x0, times, [&](double t, std::span<const double> x) {
    max_err = std::max(max_err, std::abs(x[0] - exact(t)));
    return true;
  });
  EXPECT_EQ(r.status, IntegrationResult::Status::kCompleted) << r.message;
  *steps = r.steps;
  return max_err;
}

TEST(FixedStep, takes_the_given_step_and_converges_at_the_method_order) {
  // Without error control the global error of an order-p method falls as h^p: halving the step
  // divides it by 2^p. The observed ratio of two runs (h = 5 ms and 2.5 ms, hw = 0.047 and
  // 0.024 on this oscillator, well inside the asymptotic range) must lie within a factor
  // kOrderBand of 2^p: the leading error term's share at these hw leaves the ratio within
  // 0.3 % of 2^p (measured 16.01 / 8.02 / 4.00 / 16.00, odeint_bs3 8.02), and 10 % still
  // separates neighbouring orders (2^p against 2^(p+-1): a factor 2); a run that ignored the
  // fixed step (error control at rtol 1e-6) or used the wrong order would miss it by far.
  constexpr double kOrderBand = 1.1;
  struct Case { const char* method; int erk_order; int order; };
  for (const Case c : {Case{"arkode_erk", 4, 4}, Case{"arkode_erk", 3, 3},
                       Case{"arkode_erk", 2, 2}, Case{"arkode_dirk", 4, 4},
                       Case{"odeint_bs3", 4, 3}, Case{"bdf2", 4, 2}}) {
    long n1 = 0, n2 = 0;
    const double e1 = fixed_step_error(c.method, c.erk_order, 5e-3, &n1);
    const double e2 = fixed_step_error(c.method, c.erk_order, 2.5e-3, &n2);
    // 5 s in steps of h, the last one possibly past the end (the output is interpolated).
    EXPECT_NEAR(static_cast<double>(n1), 1000.0, 1.0) << c.method << c.erk_order;
    EXPECT_NEAR(static_cast<double>(n2), 2000.0, 1.0) << c.method << c.erk_order;
    const double ratio = e1 / e2;
    const double expected = std::pow(2.0, c.order);
    EXPECT_GT(ratio, expected / kOrderBand) << c.method << " order " << c.erk_order;
    EXPECT_LT(ratio, expected * kOrderBand) << c.method << " order " << c.erk_order;
  }
}

// Prothero-Robinson: x' = lambda (x - cos t) - sin t has the smooth solution cos t and every
// other solution approaches it at rate lambda. Started 1 off it with lambda = -1e6 and a step
// of 10 ms (h lambda = -1e4), an L-stable method is back on it after one step (BDF2's and the
// implicit Euler start's amplification tends to 0 as h lambda -> -inf; the trapezoidal rule's
// would be -1, leaving the offset); its error is then the method's on cos t, O(h^2).
class ProtheroRobinson final : public OdeSystem {
 public:
  std::size_t size() const override { return 1; }
  int rhs(double t, std::span<const double> x, std::span<double> xd) const override {
    xd[0] = kLambda * (x[0] - std::cos(t)) - std::sin(t);
    return kRhsOk;
  }
  std::vector<SignalInfo> state_info() const override { return {{"x", "-", ""}}; }
  static constexpr double kLambda = -1e6;
};

TEST(FixedStep, bdf2_damps_a_stiff_component_in_one_step) {
  IntegratorSettings s;
  s.method = "bdf2";
  s.fixed_step = 0.01;
  s.rtol = 1e-8;
  s.atol = 1e-10;
  ProtheroRobinson sys;
  const std::vector<double> x0{2.0};
  double max_err = 0.0;
  const auto r = make_integrator(s)->integrate(
      sys, x0, output_grid(0.0, 2.0, 0.01), [&](double t, std::span<const double> x) {
        if (t > 0.0) max_err = std::max(max_err, std::abs(x[0] - std::cos(t)));
        return true;
      });
  ASSERT_EQ(r.status, IntegrationResult::Status::kCompleted) << r.message;
  // A first step by implicit Euler from the offset leaves 1 / (1 - h lambda) = 1e-4 of it;
  // BDF2's own error on cos t at h = 0.01 is ~ h^2 / lambda-scaled, far below that.
  EXPECT_LT(max_err, 2e-4);
  // Linear: Newton with the exact Jacobian converges at its first correction, every step, and
  // never splits; one right-hand side per iteration, one more per Jacobian column.
  EXPECT_EQ(r.step_splits, 0);
  EXPECT_GE(r.newton_iterations, r.steps);
  EXPECT_LE(r.newton_iterations, 2 * r.steps);
  EXPECT_GE(r.jacobians, 1);
  EXPECT_GE(r.rhs_evaluations, r.newton_iterations + r.jacobians);
}

// x' = -1 for x > 0, +1 for x <= 0: f jumps at 0, where the solution sticks (chatters within
// round-off). Newton cannot converge across the jump at a finite step; bdf2 must split the step
// until the correction is negligible and go on, staying at 0 to within a split step's reach.
class Sign final : public OdeSystem {
 public:
  std::size_t size() const override { return 1; }
  int rhs(double, std::span<const double> x, std::span<double> xd) const override {
    xd[0] = x[0] > 0.0 ? -1.0 : 1.0;
    return kRhsOk;
  }
  std::vector<SignalInfo> state_info() const override { return {{"x", "-", ""}}; }
};

TEST(FixedStep, bdf2_steps_over_a_discontinuity_of_the_right_hand_side) {
  IntegratorSettings s;
  s.method = "bdf2";
  s.fixed_step = 0.01;
  s.rtol = 1e-3;  // the Newton test: corrections below 1e-5 end the iteration
  s.atol = 1e-3;
  Sign sys;
  const std::vector<double> x0{0.25};
  double last = 1.0;
  const auto r = make_integrator(s)->integrate(
      sys, x0, output_grid(0.0, 1.0, 0.01), [&](double t, std::span<const double> x) {
        if (t <= 0.2 + 1e-12) EXPECT_NEAR(x[0], 0.25 - t, 1e-12) << t;  // before the jump
        last = x[0];
        return true;
      });
  ASSERT_EQ(r.status, IntegrationResult::Status::kCompleted) << r.message;
  EXPECT_LT(std::abs(last), 1e-2 * s.fixed_step);
  // Sticking at the jump, no implicit step of the full size has a solution: the steps after
  // t = 0.25 split, every one of them.
  EXPECT_GE(r.step_splits, 70);
}

TEST(FixedStep, odeint_bs3_interpolates_outputs_between_steps_at_the_method_order) {
  // Outputs every 50 ms on steps of 3 ms and 1.5 ms fall inside steps and are read from the
  // cubic Hermite interpolant (local error O(h^4)): the global error must still fall as h^3,
  // within kOrderBand of 8 (measured 8.02); a linear interpolant (O(h^2)) would give ~4.
  constexpr double kOrderBand = 1.1;
  long n1 = 0, n2 = 0;
  const double e1 = fixed_step_error("odeint_bs3", 4, 3e-3, &n1);
  const double e2 = fixed_step_error("odeint_bs3", 4, 1.5e-3, &n2);
  EXPECT_EQ(n1, 1667);  // 5 s / 3 ms, the last step past the end
  EXPECT_EQ(n2, 3334);
  EXPECT_GT(e1 / e2, 8.0 / kOrderBand);
  EXPECT_LT(e1 / e2, 8.0 * kOrderBand);
}

/// Van der Pol's oscillator (mu = 1): nonlinear, so two integrators agree to round-off only if
/// they evaluate the same formula.
class VanDerPol final : public OdeSystem {
 public:
  std::size_t size() const override { return 2; }
  int rhs(double, std::span<const double> x, std::span<double> xd) const override {
    xd[0] = x[1];
    xd[1] = (1.0 - x[0] * x[0]) * x[1] - x[0];
    return kRhsOk;
  }
  std::vector<SignalInfo> state_info() const override { return {{"x", "-", ""}, {"v", "-", ""}}; }
};

TEST(FixedStep, odeint_bs3_is_the_formula_of_arkodes_order_3_method) {
  // ARKODE's order-3 explicit method is Bogacki and Shampine's 3(2) pair, whose third-order
  // solution odeint_bs3 computes: at the same fixed step the two runs must agree to round-off
  // (measured 5e-13 over 2 000 steps, the operations grouped differently), while another
  // order-3 formula differs by its truncation error: Heun's order-3 formula at the same 5 ms
  // step by 9e-8 (Bogacki-Shampine's own error against a 1.25 ms step: 6e-7). kSameFormula
  // lies 200x above the one and 900x below the other.
  constexpr double kSameFormula = 1e-10;
  VanDerPol sys;
  const auto times = output_grid(0.0, 10.0, 0.05);
  const std::vector<double> x0{2.0, 0.0};
  std::vector<std::vector<double>> runs;
  for (const char* method : {"odeint_bs3", "arkode_erk"}) {
    IntegratorSettings s;
    s.method = method;
    s.erk_order = 3;
    s.fixed_step = 5e-3;
    std::vector<double> xs;
    const auto r = make_integrator(s)->integrate(sys, x0, times, [&](double, std::span<const double> x) {
      xs.push_back(x[0]);
      xs.push_back(x[1]);
      return true;
    });
    ASSERT_EQ(r.status, IntegrationResult::Status::kCompleted) << r.message;
    runs.push_back(xs);
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  double worst = 0.0;
  for (std::size_t i = 0; i < runs[0].size(); ++i)
    worst = std::max(worst, std::abs(runs[0][i] - runs[1][i]));
  EXPECT_LT(worst, kSameFormula);
}

/// Stiff and nonlinear, with a closed form: x' = -k x^2 (x = x0 / (1 + k x0 t), Jacobian -2 k x
/// changing by two orders of magnitude over the run) beside the damped oscillator.
class StiffDecay final : public OdeSystem {
 public:
  static constexpr double kRate = 1.0e4;  // [1/(unit s)]
  std::size_t size() const override { return 3; }
  int rhs(double, std::span<const double> x, std::span<double> xd) const override {
    xd[0] = x[1];
    xd[1] = -kOmega * kOmega * x[0] - 2.0 * kZeta * kOmega * x[1];
    xd[2] = -kRate * x[2] * x[2];
    return kRhsOk;
  }
  std::vector<SignalInfo> state_info() const override {
    return {{"x", "m", ""}, {"v", "m/s", ""}, {"c", "-", ""}};
  }
};

TEST(JacobianAge, a_stale_jacobian_costs_iterations_not_accuracy) {
  // The error test does not depend on the Newton matrix, so the closed-form error must stay
  // within the same bound (1000 x rtol, as above) at every Jacobian age. (What the age saves
  // depends on the system: on these 3 states a Jacobian costs 3 right-hand sides and ARKODE
  // spends more on iterations with an old one; on a 74-state vehicle it saves a third.)
  for (const std::string method : {"cvode_bdf", "arkode_dirk"}) {
    for (const long age : {1L, 51L, 1000L}) {
      IntegratorSettings s;
      s.method = method;
      s.rtol = 1e-8;
      s.atol = 1e-12;
      s.jacobian_max_steps = age;
      StiffDecay sys;
      const auto times = output_grid(0.0, 5.0, 0.01);
      const std::vector<double> x0{1.0, 0.0, 1.0};
      double err_x = 0.0, err_c = 0.0;
      const auto r = make_integrator(s)->integrate(
          sys, x0, times, [&](double t, std::span<const double> x) {
            err_x = std::max(err_x, std::abs(x[0] - exact(t)));
            const double c = 1.0 / (1.0 + StiffDecay::kRate * t);
            err_c = std::max(err_c, std::abs(x[2] - c) / c);
            return true;
          });
      ASSERT_EQ(r.status, IntegrationResult::Status::kCompleted) << method << " " << r.message;
      constexpr double kGlobalErrorTol = 1e-5;  // 1000 x rtol
      EXPECT_LT(err_x, kGlobalErrorTol) << method << " age " << age;
      EXPECT_LT(err_c, kGlobalErrorTol) << method << " age " << age;
    }
  }
}

TEST(OutputGrid, includes_end_point) {
  const auto g = output_grid(0.0, 1.05, 0.1);
  EXPECT_DOUBLE_EQ(g.front(), 0.0);
  EXPECT_DOUBLE_EQ(g.back(), 1.05);
  EXPECT_EQ(g.size(), 12u);
}

}  // namespace
}  // namespace ferro::vehicle

namespace ferro::vehicle {
namespace {

// x' = -k x from x0 = 1 stays positive; a trial step that overshoots below zero gets a
// recoverable code. SUNDIALS must retry with a smaller step and still match exp(-k t).
class PositiveDecay final : public OdeSystem {
 public:
  std::size_t size() const override { return 1; }
  int rhs(double, std::span<const double> x, std::span<double> xd) const override {
    if (x[0] < 0.0) return kRhsRecoverable;
    xd[0] = -kRate * x[0];
    return kRhsOk;
  }
  std::vector<SignalInfo> state_info() const override { return {{"x", "-", ""}}; }
  static constexpr double kRate = 40.0;
};

TEST(RecoverableRhs, implicit_sundials_methods_retry_with_a_smaller_step) {
  for (const char* method : {"cvode_bdf", "cvode_adams", "arkode_dirk"}) {
    IntegratorSettings s;
    s.method = method;
    s.rtol = 1e-6;
    s.atol = 1e-10;
    s.initial_step = 0.2;  // 8 time constants: the first trial step overshoots
    PositiveDecay sys;
    const std::vector<double> x0{1.0};
    double max_err = 0.0;
    const auto r = make_integrator(s)->integrate(
        sys, x0, output_grid(0.0, 0.5, 0.05), [&](double t, std::span<const double> x) {
          max_err = std::max(max_err, std::abs(x[0] - std::exp(-PositiveDecay::kRate * t)));
          return true;
        });
    EXPECT_EQ(r.status, IntegrationResult::Status::kCompleted) << method << ": " << r.message;
    EXPECT_LT(max_err, 1e-4) << method;
  }
}

// Explicit methods cannot recover (ARKODE's ERKStep by design, Odeint has no retry): they must
// report the failure with its time instead of carrying on.
TEST(RecoverableRhs, explicit_methods_report_it_as_a_failure) {
  for (const char* method : {"arkode_erk", "odeint_dopri5", "odeint_bs3"}) {
    IntegratorSettings s;
    s.method = method;
    s.initial_step = 0.2;
    if (std::string(method) == "odeint_bs3") s.fixed_step = 0.06;  // h rate 2.4: overshoots
    PositiveDecay sys;
    const std::vector<double> x0{1.0};
    const auto r = make_integrator(s)->integrate(
        sys, x0, output_grid(0.0, 0.5, 0.05), [](double, std::span<const double>) { return true; });
    EXPECT_EQ(r.status, IntegrationResult::Status::kSolverFailure) << method;
    EXPECT_NE(r.message.find("t = "), std::string::npos) << r.message;
    if (std::string(method) == "odeint_bs3") {
      // The failing step's start and state, and the cause, are reported.
      EXPECT_NE(r.message.find("right-hand side returned 1"), std::string::npos) << r.message;
      ASSERT_EQ(r.state.size(), 1u);
      EXPECT_GE(r.state[0], 0.0) << r.message;
      EXPECT_NEAR(std::fmod(r.t_reached + 1e-12, 0.06), 0.0, 1e-9) << r.message;
    }
  }
}

}  // namespace
}  // namespace ferro::vehicle
