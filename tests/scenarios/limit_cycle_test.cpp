// Limit-cycle amplitude, periodic-branch continuation and ramping against the Hopf normal forms,
// whose limit cycles and folds are known in closed form:
//   supercritical  r' = mu r - r^3:          amplitude sqrt(mu) for mu > 0;
//   subcritical    r' = mu r + r^3 - r^5:    stable cycle r^2 = (1 + sqrt(1 + 4 mu))/2 for
//                                            mu >= -1/4, fold at mu = -1/4 with r = sqrt(1/2).
// Written in Cartesian form with angular frequency omega; the "speed" V maps to mu = V - 1, so
// the Hopf point is V = 1 and the subcritical fold V = 0.75.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/limit_cycle.hpp"

namespace ferro::scenarios::analysis {
namespace {

class HopfNormalForm final : public vehicle::OdeSystem {
 public:
  HopfNormalForm(double mu, bool subcritical) : mu_(mu), sub_(subcritical) {}
  [[nodiscard]] std::size_t size() const override { return 2; }
  int rhs(double, std::span<const double> x, std::span<double> xd) const override {
    const double r2 = x[0] * x[0] + x[1] * x[1];
    const double g = sub_ ? mu_ + r2 - r2 * r2 : mu_ - r2;
    xd[0] = g * x[0] - kOmega * x[1];
    xd[1] = kOmega * x[0] + g * x[1];
    return vehicle::kRhsOk;
  }
  [[nodiscard]] std::vector<vehicle::SignalInfo> state_info() const override {
    return {{"x", "-", ""}, {"y", "-", ""}};
  }
  static constexpr double kOmega = 2.0 * M_PI;  // 1 Hz

 private:
  double mu_;
  bool sub_;
};

/// Two uncoupled subcritical normal forms, a "front" one with mu = V - 1 (fold at V = 0.75) and a
/// "rear" one with mu = V - 1 + shift (fold at 0.75 - shift): a vehicle whose rear bogie keeps a
/// cycle below the speed where the front one loses it. States x1, y1, x2, y2.
class TwoBogies final : public vehicle::OdeSystem {
 public:
  TwoBogies(double v, double shift) : front_(v - 1.0, true), rear_(v - 1.0 + shift, true) {}
  [[nodiscard]] std::size_t size() const override { return 4; }
  int rhs(double t, std::span<const double> x, std::span<double> xd) const override;
  [[nodiscard]] std::vector<vehicle::SignalInfo> state_info() const override {
    return {{"x1", "-", ""}, {"y1", "-", ""}, {"x2", "-", ""}, {"y2", "-", ""}};
  }

 private:
  HopfNormalForm front_, rear_;
};

int TwoBogies::rhs(double t, std::span<const double> x, std::span<double> xd) const {
  front_.rhs(t, x.subspan(0, 2), xd.subspan(0, 2));
  return rear_.rhs(t, x.subspan(2, 2), xd.subspan(2, 2));
}

double subcritical_amplitude(double mu) { return std::sqrt(0.5 * (1.0 + std::sqrt(1.0 + 4.0 * mu))); }

vehicle::SystemAtSpeed factory(bool subcritical) {
  return [subcritical](double v) { return std::make_unique<HopfNormalForm>(v - 1.0, subcritical); };
}

SettleOptions settle_options() {
  SettleOptions o;
  o.solver.method = "cvode_bdf";
  o.solver.rtol = 1e-10;
  o.solver.atol = 1e-12;
  o.segment = 10.0;
  o.max_time = 300.0;
  o.output_interval = 2e-3;
  o.zero_amplitude = 1e-3;
  o.max_amplitude = 10.0;
  o.amplitude.periods = 5;
  o.amplitude.rel_tol = 1e-3;
  o.observed = {0, 1};
  return o;
}

TEST(SteadyAmplitude, SineWithOffsetAndRipple) {
  std::vector<double> t, x;
  for (int i = 0; i <= 20000; ++i) {
    t.push_back(1e-3 * i);
    x.push_back(0.3 + 2.0 * std::sin(2 * M_PI * 1.7 * t.back()) +
                0.05 * std::sin(2 * M_PI * 23.0 * t.back()));
  }
  const auto a = steady_amplitude(t, x, {5, 1e-3});
  // Peak of 2 sin + 0.05 sin(13.5x harmonic) lies within [2, 2.05]: the amplitude with ripple.
  EXPECT_GT(a.amplitude, 2.0);
  EXPECT_LT(a.amplitude, 2.05);
  // The ripple shifts each crossing by up to 0.05 / (2 * 2 pi 1.7) s; a period from 5 periods
  // is off by at most twice that over 5.
  EXPECT_NEAR(a.period, 1.0 / 1.7, 2.0 * 0.05 / (2.0 * 2.0 * M_PI * 1.7) / 5.0);
  EXPECT_NEAR(a.mean, 0.3, 0.05);
  EXPECT_TRUE(a.converged);
}

TEST(SteadyAmplitude, DecayingSineIsNotConverged) {
  std::vector<double> t, x;
  for (int i = 0; i <= 20000; ++i) {
    t.push_back(1e-3 * i);
    x.push_back(std::exp(-0.05 * t.back()) * std::sin(2 * M_PI * t.back()));
  }
  const auto a = steady_amplitude(t, x, {5, 1e-3});
  EXPECT_FALSE(a.converged);
  EXPECT_LT(a.amplitude, a.previous);
}

TEST(LimitCycle, SupercriticalAmplitudeIsSqrtMu) {
  const auto o = settle_options();
  for (double mu : {0.04, 0.25, 1.0}) {
    HopfNormalForm sys(mu, false);
    const std::vector<double> x0 = {0.01, 0.0};
    const auto r = run_until_settled(sys, x0, o);
    ASSERT_EQ(r.outcome, Oscillation::kSteady) << mu << " " << r.message;
    // Convergence tolerance 1e-3 relative, plus the 2 ms sampling of a 1 Hz cycle (2e-5).
    EXPECT_NEAR(r.amplitude[0], std::sqrt(mu), 2e-3 * std::sqrt(mu)) << mu;
    std::printf("[ figures  ] supercritical mu = %g: amplitude %.7f, sqrt(mu) %.7f\n", mu,
                r.amplitude[0], std::sqrt(mu));
    EXPECT_NEAR(r.period, 1.0, 1e-4) << mu;
  }
  HopfNormalForm stable(-0.2, false);
  const std::vector<double> x0 = {0.5, 0.0};
  EXPECT_EQ(run_until_settled(stable, x0, o).outcome, Oscillation::kDecayed);
}

// The supercritical normal form is exactly the amplitude equation d ln r/dt = mu - r^2
// (sigma = mu, beta = 1); its r^2 follows the logistic law r^2(t) = mu / (1 + (mu/r0^2 - 1)
// e^(-2 mu t)), so with mu = 0.01 a start at r0 = 0.3 is still at r = 0.13, decaying, after
// 40 s: the run has not converged, but it is heading for the cycle r = 0.1.
TEST(AmplitudeEquation, SupercriticalUnconvergedRunApproachesSqrtMu) {
  auto o = settle_options();
  o.max_time = 40.0;
  for (double mu : {0.01, 0.02}) {
    HopfNormalForm sys(mu, false);
    const std::vector<double> x0 = {0.3, 0.0};
    const auto r = run_until_settled(sys, x0, o);
    ASSERT_EQ(r.outcome, Oscillation::kApproaching) << mu << " " << r.message;
    std::printf(
        "[ figures  ] supercritical mu = %g after 40 s: sigma %.6f +- %.1e, beta %.5f, "
        "cycle %.6f (sqrt(mu) %.6f)\n",
        mu, r.fit.sigma, r.fit.sigma_error, r.fit.beta, r.amplitude[0], std::sqrt(mu));
    // Envelope from sampled peaks (2 ms of a 1 Hz cycle: ~1e-6 relative after the parabolic
    // refinement) and central differences of ln A over two periods, whose truncation error
    // (d^3 ln A/dt^3) T^2 / 6 is below 1e-4 /s here; 2e-3 /s is 10-20 % of mu.
    constexpr double kRateTol = 2e-3;  // [1/s]
    EXPECT_NEAR(r.fit.sigma, mu, kRateTol) << mu;
    EXPECT_NEAR(r.fit.beta, 1.0, 0.05) << mu;
    EXPECT_NEAR(r.amplitude[0], std::sqrt(mu), 0.05 * std::sqrt(mu)) << mu;
  }
  // Below the Hopf point the same slow decay goes to rest: sigma = mu < 0.
  HopfNormalForm stable(-0.01, false);
  const std::vector<double> x0 = {0.3, 0.0};
  const auto r = run_until_settled(stable, x0, o);
  EXPECT_EQ(r.outcome, Oscillation::kDecaying) << r.message;
  EXPECT_NEAR(r.fit.sigma, -0.01, 2e-3);
  EXPECT_FALSE(sustained(r.outcome));
}

// Subcritical normal form near its fold mu = -1/4: above it (mu = -0.245) a start at r = 1 is
// still creeping down towards the stable cycle r^2 = (1 + sqrt(1 + 4 mu))/2 = 0.6118 after
// 30 s; below it (mu = -0.255) the run lingers near r^2 = 1/2 (the ghost of the fold) and
// then collapses: no cycle. The fit is the tangent of d ln r/dt = mu + r^2 - r^4 at the
// visited amplitudes, which predicts the nearby cycle (or its absence) correctly.
TEST(AmplitudeEquation, SubcriticalNearFoldClassifiedByTheFit) {
  auto o = settle_options();
  o.max_time = 30.0;
  HopfNormalForm above(-0.245, true);
  const std::vector<double> x0 = {1.0, 0.0};
  const auto r = run_until_settled(above, x0, o);
  ASSERT_EQ(r.outcome, Oscillation::kApproaching) << r.message;
  std::printf("[ figures  ] subcritical mu = -0.245 after 30 s: cycle %.5f (exact %.5f)\n",
              r.amplitude[0], subcritical_amplitude(-0.245));
  // The tangent at r^2 ~ 0.62-0.65 of a law curved by -r^4: its root lies within
  // (r^2 - r*^2)^2 / |1 - 2 r*^2| ~ 1e-2 of r*^2, i.e. ~1 % in r.
  EXPECT_NEAR(r.amplitude[0], subcritical_amplitude(-0.245), 0.01 * subcritical_amplitude(-0.245));
  HopfNormalForm below(-0.255, true);
  const auto b = run_until_settled(below, x0, o);
  EXPECT_FALSE(sustained(b.outcome)) << to_string(b.outcome) << " " << b.message;
  // Small amplitudes below the Hopf point: sigma is the eigenvalue's real part mu, the cubic
  // coefficient destabilising (beta = -1 less the quintic's pull, r^2 <= 0.04 here: 0.04).
  auto small = settle_options();
  small.max_time = 20.0;
  small.zero_amplitude = 1e-6;
  HopfNormalForm decaying(-0.05, true);
  const std::vector<double> x_small = {0.2, 0.0};
  const auto d = run_until_settled(decaying, x_small, small);
  ASSERT_EQ(d.outcome, Oscillation::kDecaying) << d.message;
  EXPECT_NEAR(d.fit.sigma, -0.05, 2e-3);
  EXPECT_NEAR(d.fit.beta, -1.0, 0.08);
}

// The supercritical normal form inside a wall at r = 1.5: the right-hand side fails beyond it.
class WalledHopf final : public vehicle::OdeSystem {
 public:
  explicit WalledHopf(double mu) : free_(mu, false) {}
  [[nodiscard]] std::size_t size() const override { return 2; }
  int rhs(double t, std::span<const double> x, std::span<double> xd) const override {
    if (x[0] * x[0] + x[1] * x[1] > kWall * kWall) return vehicle::kRhsFatal;
    return free_.rhs(t, x, xd);
  }
  [[nodiscard]] std::vector<vehicle::SignalInfo> state_info() const override {
    return free_.state_info();
  }
  static constexpr double kWall = 1.5;

 private:
  HopfNormalForm free_;
};

TEST(LimitCycle, FailureAtTheStartIsAnErrorNotAnOscillation) {
  const auto o = settle_options();
  // mu = 4: the cycle (r = 2) lies beyond the wall, so a small start grows into the wall after
  // a few periods: an oscillation that diverged.
  WalledHopf sys(4.0);
  const std::vector<double> small = {0.01, 0.0};
  const auto grown = run_until_settled(sys, small, o);
  EXPECT_EQ(grown.outcome, Oscillation::kDiverged);
  EXPECT_GT(grown.time, 0.5);  // r grows as e^(4t) from 0.01 to 1.5: t ~ 1.25 s
  // A start beyond the wall cannot be integrated at all: an error, not a sustained cycle.
  const std::vector<double> inside_wall = {2.0, 0.0};
  try {
    (void)run_until_settled(sys, inside_wall, o);
    FAIL() << "a failing start was taken for an oscillation";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("failed at its start"), std::string::npos) << e.what();
  }
}

TEST(LimitCycle, SubcriticalBistability) {
  // Between the fold and the Hopf point both the rest state and the large cycle are stable.
  const auto o = settle_options();
  HopfNormalForm sys(-0.1, true);
  const std::vector<double> small = {0.1, 0.0}, large = {1.0, 0.0};
  EXPECT_EQ(run_until_settled(sys, small, o).outcome, Oscillation::kDecayed);
  const auto r = run_until_settled(sys, large, o);
  ASSERT_EQ(r.outcome, Oscillation::kSteady);
  EXPECT_NEAR(r.amplitude[0], subcritical_amplitude(-0.1), 2e-3);
}

TEST(PeriodicBranch, SubcriticalFoldAtMuMinusQuarter) {
  BranchOptions o;
  o.settle = settle_options();
  o.speed_start = 1.3;
  o.speed_stop = 0.5;
  o.speed_step = 0.1;
  o.bracket = 2e-3;
  const std::vector<double> x0 = {1.2, 0.0};
  const auto b = follow_periodic_branch(factory(true), x0, o);
  ASSERT_TRUE(b.fold_found);
  ASSERT_TRUE(b.lowest_sustained.has_value());
  EXPECT_LE(b.bracket_high - b.bracket_low, o.bracket);
  std::printf("[ figures  ] subcritical fold: bracket [%.6f, %.6f] (exact 0.75), %zu runs\n",
              b.bracket_low, b.bracket_high, b.points.size());
  // The fold V = 0.75 lies in the bracket, up to the slow passage near the fold, which a
  // convergence test with relative tolerance 1e-3 over 5 periods cannot tell from a cycle when
  // mu + 1/4 < ~2e-4 (drift 0.707 (mu + 1/4) per second against 1e-3 r over 5 s).
  constexpr double kSlowPassage = 5e-4;
  EXPECT_LE(b.bracket_low, 0.75 + 1e-12);
  EXPECT_GE(b.bracket_high, 0.75 - kSlowPassage);
  // Every steady point sits on the analytic branch.
  int steady = 0;
  for (const auto& p : b.points) {
    if (p.run.outcome != Oscillation::kSteady) continue;
    ++steady;
    const double expected = subcritical_amplitude(p.speed - 1.0);
    // Near the fold the branch is steep (dr/dmu ~ 1/sqrt(mu + 1/4)); allow the drift above.
    const double tol = p.speed - 0.75 < 0.01 ? 2e-2 : 2e-3;
    EXPECT_NEAR(p.run.amplitude[0], expected, tol * expected) << p.speed;
  }
  EXPECT_GE(steady, 6);
  // A finite cycle at the fold: the A^2 line through the lowest cycles reaches zero far below.
  EXPECT_FALSE(b.supercritical) << b.amplitude_squared_zero;
}

TEST(PeriodicBranch, SupercriticalFoldIsTheHopfPointWithShortRuns) {
  // 60 s per speed: near V = 1 (mu -> 0) the runs end unconverged (relaxation rate 2 mu), and
  // the amplitude equation must still put the fold at the Hopf point V = 1 and A^2 = V - 1 must
  // extrapolate to it.
  BranchOptions o;
  o.settle = settle_options();
  o.settle.max_time = 60.0;
  o.speed_start = 1.3;
  o.speed_stop = 0.8;
  o.speed_step = 0.1;
  o.bracket = 2e-3;
  const std::vector<double> x0 = {0.6, 0.0};
  const auto b = follow_periodic_branch(factory(false), x0, o);
  ASSERT_TRUE(b.fold_found);
  std::printf(
      "[ figures  ] supercritical fold: bracket [%.6f, %.6f], A^2 zero at %.6f (exact 1), "
      "%zu runs\n",
      b.bracket_low, b.bracket_high, b.amplitude_squared_zero, b.points.size());
  // The sign of sigma = V - 1 is known from the fit once |sigma| exceeds its two standard
  // errors; with 1e-10 integration tolerances that is far inside the bracket width.
  EXPECT_LE(b.bracket_low, 1.0);
  EXPECT_GE(b.bracket_high, 1.0);
  EXPECT_TRUE(b.supercritical);
  // Two cycles within a few bracket widths of V = 1, on the line A^2 = V - 1 up to the
  // predicted cycles' error (5 % in A above).
  EXPECT_NEAR(b.amplitude_squared_zero, 1.0, 2.0 * o.bracket);
}

TEST(PeriodicBranch, NoOscillationAtStart) {
  BranchOptions o;
  o.settle = settle_options();
  o.speed_start = 0.7;
  o.speed_stop = 0.5;
  const std::vector<double> x0 = {1.2, 0.0};
  const auto b = follow_periodic_branch(factory(true), x0, o);
  EXPECT_FALSE(b.fold_found);
  EXPECT_FALSE(b.lowest_sustained.has_value());
}

TEST(Ramp, SupercriticalDecaySpeed) {
  // Slow ramp a = 1e-3 per s from V = 1.5: the amplitude follows sqrt(V - 1) and falls below
  // 0.3 at V = 1.09, lagging by ~ a / (2 mu) = 0.006 in mu (relaxation rate 2 mu) plus the
  // 2 s envelope window (0.002).
  RampOptions o;
  o.speed_initial = 1.5;
  o.speed_final = 0.95;
  o.deceleration = 1e-3;
  o.hold = 1.0;
  o.output_interval = 1e-2;
  o.threshold = 0.3;
  o.max_amplitude = 10.0;
  o.solver.rtol = 1e-9;
  o.solver.atol = 1e-12;
  o.observed = {0, 1};
  const std::vector<double> x0 = {0.05, 0.0};
  const auto r = ramp_down(factory(false), x0, o);
  ASSERT_TRUE(r.completed) << r.message;
  ASSERT_TRUE(r.decay_speed.has_value());
  std::printf("[ figures  ] ramp decay speed %.6f (quasi-static 1.09)\n", *r.decay_speed);
  constexpr double kLag = 0.012;  // lag estimate above, doubled
  EXPECT_LT(*r.decay_speed, 1.09 + 1e-3);
  EXPECT_GT(*r.decay_speed, 1.09 - kLag);
}

// The rear pair (fold 0.65) keeps its cycle at V = 0.7 while the front pair (fold 0.75) decays:
// the system is sustained, held by the rear pair, whose amplitude is the analytic cycle.
TEST(LimitCycle, SustainedWhenAnyObservedStateKeepsACycle) {
  constexpr double kShift = 0.1;
  auto o = settle_options();
  o.observed = {0, 2};
  TwoBogies sys(0.7, kShift);
  const std::vector<double> x0 = {1.0, 0.0, 1.0, 0.0};
  const auto r = run_until_settled(sys, x0, o);
  ASSERT_EQ(r.outcome, Oscillation::kSteady) << r.message;
  EXPECT_EQ(r.holder, 1u);
  const double expected = subcritical_amplitude(0.7 - 1.0 + kShift);
  EXPECT_NEAR(r.amplitude[1], expected, 2e-3 * expected);
  // The front pair has died out beside it (below 1 % of the cycle: a settled run).
  EXPECT_LT(r.amplitude[0], 0.01 * r.amplitude[1]) << "the front pair decays";
  // Watched alone, the front pair decays: the old single-state decision.
  o.observed = {0};
  EXPECT_EQ(run_until_settled(sys, x0, o).outcome, Oscillation::kDecayed);
}

// The fold of the system is the lowest speed where any pair keeps a cycle: the rear pair's
// 0.75 - shift, not the front pair's 0.75; the bisection continues from the rear pair's cycle.
TEST(PeriodicBranch, FoldIsTheLowestSpeedWhereAnyStateKeepsACycle) {
  constexpr double kShift = 0.1;
  BranchOptions o;
  o.settle = settle_options();
  o.settle.observed = {0, 2};
  o.speed_start = 1.2;
  o.speed_stop = 0.4;
  o.speed_step = 0.1;
  o.bracket = 2e-3;
  const vehicle::SystemAtSpeed factory2 = [](double v) -> std::unique_ptr<vehicle::OdeSystem> {
    return std::make_unique<TwoBogies>(v, 0.1);
  };
  const std::vector<double> x0 = {1.2, 0.0, 1.2, 0.0};
  const auto b = follow_periodic_branch(factory2, x0, o);
  ASSERT_TRUE(b.fold_found);
  std::printf("[ figures  ] two pairs, folds 0.75 and %.2f: bracket [%.6f, %.6f], held by %zu\n",
              0.75 - kShift, b.bracket_low, b.bracket_high, b.holder);
  constexpr double kSlowPassage = 5e-4;  // as in SubcriticalFoldAtMuMinusQuarter
  EXPECT_LE(b.bracket_low, 0.75 - kShift + 1e-12);
  EXPECT_GE(b.bracket_high, 0.75 - kShift - kSlowPassage);
  EXPECT_EQ(b.holder, 1u);
  // Below the front pair's fold every sustained run is held by the rear pair, with the front
  // pair at rest.
  for (const auto& p : b.points) {
    if (p.speed < 0.75 - 1e-3 && sustained(p.run.outcome)) {
      EXPECT_EQ(p.run.holder, 1u) << p.speed;
      EXPECT_LT(p.run.amplitude[0], 0.01 * p.run.amplitude[1]) << p.speed;
    }
  }
}

}  // namespace
}  // namespace ferro::scenarios::analysis
