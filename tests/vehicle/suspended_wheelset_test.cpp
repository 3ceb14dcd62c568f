// Single suspended wheelset (Toumi eqs. 150-151): the eigenvalue critical speed against the
// closed form, and time simulations that decay below and grow above it with every integrator.
#include "ferro/vehicle/suspended_wheelset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/stability.hpp"

namespace ferro::vehicle {
namespace {

struct Case {
  const char* name;
  SuspendedWheelsetParams params;
  LinearCreepParams creep;
};

// Parameter sets that satisfy the closed form's assumptions: C11 = C22 ("equal"),
// I_zz = m e^2, no primary damping. Kx != Ky in two of them, which is where a wrong factor 2 in
// eq. (150)'s off-diagonal terms would show (SPEC_DIGEST §5).
std::vector<Case> closed_form_cases() {
  std::vector<Case> cases;
  auto make = [](const char* name, double m, double e, double R, double gamma, double kx, double ky,
                 double a, double b) {
    Case c{name, {}, {}};
    c.params.mass = m;
    c.params.half_gauge = e;
    c.params.yaw_inertia = m * e * e;
    c.params.rolling_radius = R;
    c.params.conicity = gamma;
    c.params.primary_stiffness_x = kx;
    c.params.primary_stiffness_y = ky;
    c.creep.semi_axis_a = a;
    c.creep.semi_axis_b = b;
    c.creep.coefficients = "equal";
    return c;
  };
  cases.push_back(
      make("equal_stiffness", 1813.0, 0.7465, 0.46, 0.20, 0.8e6, 0.8e6, 6.0e-3, 4.0e-3));
  cases.push_back(
      make("stiff_longitudinal", 1500.0, 0.75, 0.50, 0.15, 1.5e6, 0.6e6, 5.0e-3, 5.0e-3));
  cases.push_back(
      make("soft_longitudinal", 1200.0, 0.70, 0.43, 0.30, 0.3e6, 1.1e6, 7.0e-3, 3.5e-3));
  return cases;
}

SystemAtSpeed factory_for(const Case& c) {
  const auto creep = creep_coefficients(c.creep);
  return [c, creep](double v) { return std::make_unique<SuspendedWheelset>(c.params, creep, v); };
}

TEST(SuspendedWheelset, eigen_critical_speed_matches_formula_151) {
  // The eigenvalues of the linear model give the Routh-Hurwitz boundary exactly; the only
  // error sources are the central-difference Jacobian of a linear system (round-off, ~1e-9)
  // and the bisection width (1e-10). The issue asks for 1 %; we hold 1e-6.
  constexpr double kEigenVsClosedFormRelTol = 1e-6;
  const std::vector<double> x_eq(4, 0.0);
  for (const auto& c : closed_form_cases()) {
    const double vc_formula = analytic_critical_speed(c.params, creep_coefficients(c.creep));
    ASSERT_TRUE(std::isfinite(vc_formula)) << c.name;
    ASSERT_GT(vc_formula, 5.0) << c.name;
    const auto vc_eig = critical_speed(factory_for(c), 1.0, 4.0 * vc_formula, x_eq);
    ASSERT_TRUE(vc_eig.has_value()) << c.name;
    std::printf("[ figures  ] %-20s eig %.6f m/s, eq. (151) %.6f m/s, rel. diff %.2e\n", c.name,
                *vc_eig, vc_formula, *vc_eig / vc_formula - 1.0);
    EXPECT_NEAR(*vc_eig / vc_formula, 1.0, kEigenVsClosedFormRelTol)
        << c.name << ": eig " << *vc_eig << " m/s, formula " << vc_formula << " m/s";
  }
}

TEST(SuspendedWheelset, unequal_coefficients_shift_the_critical_speed) {
  // With Kalker's table C22 != C11 the closed form no longer applies; the eigen analysis still
  // finds a crossing, and it differs from the "equal" assumption (a test that would fail if the
  // model ignored C22).
  // (With Kx = Ky the crossing depends on f11 only, so use a case with Kx != Ky.)
  auto c = closed_form_cases()[1];
  const std::vector<double> x_eq(4, 0.0);
  const double v_equal = *critical_speed(factory_for(c), 1.0, 400.0, x_eq);
  c.creep.coefficients = "kalker_table";
  const double v_table = *critical_speed(factory_for(c), 1.0, 400.0, x_eq);
  EXPECT_GT(std::abs(v_table / v_equal - 1.0), 1e-3);
}

// Peak |y| in the first and last `window` seconds of a run from y0 = 1 mm.
std::pair<double, double> first_last_amplitude(const std::string& method, const Case& c,
                                               double speed, double t_end, double window,
                                               std::vector<double>* trace = nullptr) {
  IntegratorSettings s;
  s.method = method;
  s.rtol = 1e-8;
  s.atol = 1e-12;
  // Fixed-step-only methods: 0.1 ms, a tenth of the output interval (hunting period ~0.5 s).
  if (method == "odeint_bs3" || method == "bdf2") s.fixed_step = 1e-4;
  const SuspendedWheelset sys(c.params, creep_coefficients(c.creep), speed);
  const std::vector<double> x0{1e-3, 0.0, 0.0, 0.0};
  double first = 0.0, last = 0.0;
  const auto r = make_integrator(s)->integrate(sys, x0, output_grid(0.0, t_end, 1e-3),
                                               [&](double t, std::span<const double> x) {
                                                 if (t <= window)
                                                   first = std::max(first, std::abs(x[0]));
                                                 if (t >= t_end - window)
                                                   last = std::max(last, std::abs(x[0]));
                                                 if (trace != nullptr) trace->push_back(x[0]);
                                                 return true;
                                               });
  EXPECT_EQ(r.status, IntegrationResult::Status::kCompleted) << r.message;
  return {first, last};
}

class WheelsetEveryIntegrator : public ::testing::TestWithParam<std::string> {};

TEST_P(WheelsetEveryIntegrator, decays_below_and_grows_above_critical_speed) {
  const auto c = closed_form_cases()[0];
  const double vc = analytic_critical_speed(c.params, creep_coefficients(c.creep));
  // Window of two hunting periods, at the kinematic (Klingel) wavelength 2 pi sqrt(e R / gamma).
  const double wavelength =
      2.0 * std::numbers::pi *
      std::sqrt(c.params.half_gauge * c.params.rolling_radius / c.params.conicity);
  const double period = wavelength / vc;
  const double t_end = 60.0 * period;
  const auto [below_first, below_last] =
      first_last_amplitude(GetParam(), c, 0.95 * vc, t_end, 2 * period);
  const auto [above_first, above_last] =
      first_last_amplitude(GetParam(), c, 1.05 * vc, t_end, 2 * period);
  // Growth or decay must be unmistakable over 60 periods: at least a factor 1.5 either way.
  constexpr double kClearTrend = 1.5;
  std::printf(
      "[ figures  ] %-20s peak |y| first/last 2 periods: 0.95 Vc %.3e -> %.3e m, 1.05 Vc %.3e -> "
      "%.3e m\n",
      GetParam().c_str(), below_first, below_last, above_first, above_last);
  EXPECT_LT(below_last * kClearTrend, below_first)
      << "0.95 Vc: " << below_first << " -> " << below_last;
  EXPECT_GT(above_last, kClearTrend * above_first)
      << "1.05 Vc: " << above_first << " -> " << above_last;
}

INSTANTIATE_TEST_SUITE_P(Adapters, WheelsetEveryIntegrator,
                         ::testing::ValuesIn(available_integrators()));

TEST(SuspendedWheelset, cvode_odeint_and_arkode_dirk_trajectories_agree) {
  const auto c = closed_form_cases()[1];
  const double vc = analytic_critical_speed(c.params, creep_coefficients(c.creep));
  std::vector<double> bdf, dopri, rosen, dirk;
  first_last_amplitude("cvode_bdf", c, 1.02 * vc, 3.0, 0.1, &bdf);
  first_last_amplitude("odeint_dopri5", c, 1.02 * vc, 3.0, 0.1, &dopri);
  first_last_amplitude("odeint_rosenbrock4", c, 1.02 * vc, 3.0, 0.1, &rosen);
  first_last_amplitude("arkode_dirk", c, 1.02 * vc, 3.0, 0.1, &dirk);
  ASSERT_EQ(bdf.size(), dopri.size());
  ASSERT_EQ(bdf.size(), rosen.size());
  ASSERT_EQ(bdf.size(), dirk.size());
  double peak = 0.0, diff_dopri = 0.0, diff_rosen = 0.0, diff_dirk = 0.0;
  for (std::size_t i = 0; i < bdf.size(); ++i) {
    peak = std::max(peak, std::abs(bdf[i]));
    diff_dopri = std::max(diff_dopri, std::abs(bdf[i] - dopri[i]));
    diff_rosen = std::max(diff_rosen, std::abs(bdf[i] - rosen[i]));
    diff_dirk = std::max(diff_dirk, std::abs(bdf[i] - dirk[i]));
  }
  // The set tolerance is rtol = 1e-8 per step; over ~30 hunting periods the global errors of
  // two independent methods may each reach a few hundred times that. 1e-5 of the peak is
  // 1000 x rtol: tight enough that a wrong adapter (stale state, wrong time) fails.
  constexpr double kAgreementRelToPeak = 1e-5;
  std::printf(
      "[ figures  ] max |y_cvode - y_other| / peak: dopri5 %.2e, rosenbrock4 %.2e, arkode_dirk "
      "%.2e\n",
      diff_dopri / peak, diff_rosen / peak, diff_dirk / peak);
  EXPECT_LT(diff_dopri / peak, kAgreementRelToPeak);
  EXPECT_LT(diff_rosen / peak, kAgreementRelToPeak);
  EXPECT_LT(diff_dirk / peak, kAgreementRelToPeak);
}

TEST(SuspendedWheelset, invalid_parameters_name_the_field) {
  auto c = closed_form_cases()[0];
  c.params.mass = -1.0;
  try {
    c.params.validate("model.wheelset");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("model.wheelset.mass"), std::string::npos) << e.what();
  }
}

// The wheelset of eq. (151) beside a decoupled, lightly *negatively* damped oscillator (8 Hz,
// zeta = -2e-4): the numerical picture of an undamped structural mode (a wheelset bouncing on
// the Hertz contact stiffness) whose computed damping is noise of either sign. The critical
// speed must still be the wheelset's Routh-Hurwitz speed, not the start of the range.
class WheelsetWithNeutralMode final : public OdeSystem {
 public:
  explicit WheelsetWithNeutralMode(std::unique_ptr<OdeSystem> wheelset)
      : wheelset_(std::move(wheelset)) {}
  [[nodiscard]] std::size_t size() const override { return wheelset_->size() + 2; }
  int rhs(double t, std::span<const double> x, std::span<double> xdot) const override {
    const std::size_t n = wheelset_->size();
    const int flag = wheelset_->rhs(t, x.first(n), xdot.first(n));
    constexpr double kOmega = 2.0 * std::numbers::pi * 8.0;
    constexpr double kZeta = -2e-4;
    xdot[n] = x[n + 1];
    xdot[n + 1] = -kOmega * kOmega * x[n] - 2.0 * kZeta * kOmega * x[n + 1];
    return flag;
  }
  [[nodiscard]] std::vector<SignalInfo> state_info() const override {
    auto info = wheelset_->state_info();
    info.push_back({"q", "m", "neutral oscillator"});
    info.push_back({"q_dot", "m/s", "its rate"});
    return info;
  }

 private:
  std::unique_ptr<OdeSystem> wheelset_;
};

TEST(SuspendedWheelset, critical_speed_ignores_a_neutral_mode_of_either_sign) {
  // Same oracle and tolerance as eigen_critical_speed_matches_formula_151.
  constexpr double kEigenVsClosedFormRelTol = 1e-6;
  const std::vector<double> x_eq(6, 0.0);
  for (const auto& c : closed_form_cases()) {
    const double vc_formula = analytic_critical_speed(c.params, creep_coefficients(c.creep));
    const auto wheelset = factory_for(c);
    const SystemAtSpeed with_neutral = [&](double v) {
      return std::make_unique<WheelsetWithNeutralMode>(wheelset(v));
    };
    const auto vc = critical_speed(with_neutral, 1.0, 4.0 * vc_formula, x_eq);
    ASSERT_TRUE(vc.has_value()) << c.name;
    EXPECT_NEAR(*vc / vc_formula, 1.0, kEigenVsClosedFormRelTol) << c.name;
  }
}

}  // namespace
}  // namespace ferro::vehicle
