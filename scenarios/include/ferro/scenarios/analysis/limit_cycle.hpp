#pragma once
// Steady oscillation amplitude of a time series, and runs at constant speed until the
// oscillation has settled (limit cycle), died out, or diverged.
//
// References: Toumi 2016, chapter 4 (bifurcation diagram from constant-speed runs; nonlinear
//   critical speed as the lowest speed with a non-zero limit cycle); Seydel, "Practical
//   Bifurcation and Stability Analysis" (periodic branches, folds).
//   Landau 1944 / Stuart 1960 amplitude equation dA/dt = sigma A - beta A^3, the cubic normal
//   form of a Hopf bifurcation (Kuznetsov, "Elements of Applied Bifurcation Theory", 3rd ed.,
//   sec. 3.5): sigma is the real part of the critical eigenvalue, sqrt(sigma/beta) the cycle.
// Known deviations: the amplitude is half the peak-to-peak of the last N periods (periods from
//   up-crossings of the mid-line), not a Poincare-section fixed point. A run that neither
//   settles nor leaves [zero, max] amplitude by the time limit is classified by the amplitude
//   equation fitted to its envelope over the last two segments; that fit is the tangent of the
//   true amplitude law at the amplitudes the run visited, so its sigma equals the eigenvalue's
//   real part only for small amplitudes near a Hopf point (elsewhere it still predicts the
//   nearest cycle and its stability; near a fold the quintic term carries the curvature). When
//   the fit's conclusion (rest or not) changes within two standard errors, the trend decides.

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/ode_system.hpp"

namespace ferro::scenarios::analysis {

struct AmplitudeOptions {
  int periods = 5;         ///< N: periods in the window the amplitude is measured over
  double rel_tol = 2e-3;   ///< converged when the last N periods and the N before differ less
};

struct SteadyAmplitude {
  double amplitude = 0.0;      ///< (max - min)/2 over the last N periods [signal unit]
  double previous = 0.0;       ///< the same over the N periods before (NaN when too short)
  double period = 0.0;         ///< mean period of the last N [s] (NaN when too short)
  double mean = 0.0;           ///< centre (max + min)/2 of the last N periods
  int crossings = 0;           ///< mid-line up-crossings found
  bool converged = false;      ///< 2N full periods present and |amplitude - previous| small
};

/// Amplitude of the last N periods of x(t). With fewer than N + 1 up-crossings, the amplitude
/// of the last half of the series and converged = false.
[[nodiscard]] SteadyAmplitude steady_amplitude(std::span<const double> t,
                                               std::span<const double> x,
                                               const AmplitudeOptions& options = {});

/// The amplitude equation d ln A/dt = g(A^2) = sigma - beta A^2 - gamma A^4 fitted to an
/// oscillation's envelope: A_k = half the peak-to-peak of each period between mid-line
/// up-crossings, the log-derivative by central differences over neighbouring periods, least
/// squares of the log-derivative on A^2. gamma (the quintic term of a degenerate Hopf point,
/// which bends the law into a fold) is fitted only when significant, else 0 (Landau).
struct AmplitudeEquation {
  double sigma = NAN;        ///< linear growth rate g(0) [1/s] (Re of the critical eigenvalue)
  double beta = NAN;         ///< Landau coefficient -g'(0) [1/(s unit^2)]; > 0: saturating
  double gamma = 0.0;        ///< quintic coefficient [1/(s unit^4)]
  double sigma_error = NAN;  ///< standard error of sigma [1/s]
  double beta_error = NAN;   ///< standard error of beta [1/(s unit^2)]
  double amplitude = NAN;    ///< envelope of the last period fitted [unit]
  /// Where the fitted law takes the amplitude from `amplitude`: the first zero of g in the
  /// direction of g's sign (a stable cycle), 0 when it decays to rest, +inf when it grows
  /// without bound [unit]. NaN for an invalid fit.
  double destination = NAN;
  /// The destination's kind (rest or not) is the same for the fitted law shifted by two
  /// standard errors of its level and tilted by two of its slope, each way.
  bool conclusive = false;
  int periods = 0;  ///< log-derivative samples fitted
  /// At least kMinPeriods samples and finite estimates.
  [[nodiscard]] bool valid() const;
  /// A stable cycle (0 < destination < inf) and a conclusive fit: its amplitude, else NaN.
  [[nodiscard]] double cycle_amplitude() const;
  /// Conclusive and the destination is not rest (a cycle, or unbounded growth).
  [[nodiscard]] bool sustained() const;
  static constexpr int kMinPeriods = 4;
};

/// Fits the amplitude equation to x(t) (see AmplitudeEquation). Returns an invalid fit (periods
/// < kMinPeriods) for a series with too few periods.
[[nodiscard]] AmplitudeEquation fit_amplitude_equation(std::span<const double> t,
                                                       std::span<const double> x);

/// Outcome of a constant-speed run.
enum class Oscillation {
  kDecayed,      ///< amplitude fell below zero_amplitude: no limit cycle reached
  kSteady,       ///< settled on a limit cycle (converged amplitude)
  kDiverged,     ///< left max_amplitude (or the solver failed on the way): unbounded growth
  kGrowing,      ///< time limit reached, amplitude still growing
  kDecaying,     ///< time limit reached, amplitude still decreasing (to zero, by the fit)
  kApproaching,  ///< time limit reached, amplitude still changing towards the stable cycle the
                 ///< fitted amplitude equation predicts (its amplitude is reported)
};
[[nodiscard]] std::string to_string(Oscillation o);
/// True for a sustained oscillation: steady, approaching a cycle, growing or diverged.
[[nodiscard]] bool sustained(Oscillation o);

struct SettleOptions {
  vehicle::IntegratorSettings solver;
  double segment = 10.0;          ///< simulated time between checks [s]; >= N periods (the
                                  ///< amplitude is measured over the last two segments)
  double max_time = 60.0;         ///< simulated time limit [s]
  double output_interval = 2e-3;  ///< sampling of the observed states [s]
  double zero_amplitude = 1e-5;   ///< below: decayed [observed unit]
  double max_amplitude = 0.05;    ///< above: diverged [observed unit]
  AmplitudeOptions amplitude;
  /// State indices measured (each wheelset's y): every one of them takes part in the decision.
  std::vector<std::size_t> observed;
};

struct SettleResult {
  /// Outcome of the system: the most sustained of its observed states (diverged or growing,
  /// then steady or approaching, then decaying; decayed when every one has decayed).
  Oscillation outcome = Oscillation::kDecayed;
  /// Which of `observed` holds the outcome: the state that left max_amplitude (diverged), the
  /// largest oscillation (steady, decayed), or the state whose trend or fitted amplitude
  /// equation gave the outcome (runs ended by the time limit).
  std::size_t holder = 0;
  std::vector<double> amplitude;  ///< per observed state (0 when decayed; when approaching, the
                                  ///< holder's predicted cycle, every state scaled alike)
  std::vector<AmplitudeEquation> fits;  ///< per observed state, for runs ended by the time limit
  AmplitudeEquation fit;          ///< the holder's (fits[holder]); invalid when none was fitted
  double period = 0.0;            ///< of the holder [s] (NaN when not found)
  double time = 0.0;              ///< simulated [s]
  long rhs_evaluations = 0;
  std::vector<double> final_state;
  std::string message;            ///< solver failure cause, if any
};

/// Integrates `system` from x0 in segments until its oscillation settles, decays or diverges
/// (or max_time), deciding on every observed state: diverged as soon as any observed state
/// leaves max_amplitude; decayed when every observed amplitude is below zero_amplitude; steady
/// when the largest oscillation (the holder) has converged within the segment and agrees with
/// its own amplitude of the segment before, and every other observed state has converged too
/// or is below 1 % of the holder's amplitude (a dying transient); at the time limit, each
/// observed state not negligible beside the largest (1 %: a motion the others force on it) is
/// classified by its fitted amplitude equation (or trend) and the system takes the most
/// sustained of them. So a vehicle whose rear bogie keeps hunting while the front one decays
/// is sustained, held by a rear wheelset. Throws std::invalid_argument for bad options, and
/// std::runtime_error when the solver fails before any observed state has swung across zero
/// and back once: a start that cannot be integrated (e.g. a wheel put into the rail by the
/// disturbance) is no oscillation.
[[nodiscard]] SettleResult run_until_settled(const vehicle::OdeSystem& system,
                                             std::span<const double> x0,
                                             const SettleOptions& options);

}  // namespace ferro::scenarios::analysis
