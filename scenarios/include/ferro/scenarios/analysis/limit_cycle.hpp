#pragma once
// Steady oscillation amplitude of a time series, and runs at constant speed until the
// oscillation has settled (limit cycle), died out, or diverged.
//
// References: Toumi 2016, chapter 4 (bifurcation diagram from constant-speed runs; nonlinear
//   critical speed as the lowest speed with a non-zero limit cycle); Seydel, "Practical
//   Bifurcation and Stability Analysis" (periodic branches, folds).
// Known deviations: the amplitude is half the peak-to-peak of the last N periods (periods from
//   up-crossings of the mid-line), not a Poincare-section fixed point; a run that neither settles
//   nor leaves [zero, max] amplitude by the time limit is classified by its trend.

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

/// Outcome of a constant-speed run.
enum class Oscillation {
  kDecayed,    ///< amplitude fell below zero_amplitude: no limit cycle reached
  kSteady,     ///< settled on a limit cycle (converged amplitude)
  kDiverged,   ///< left max_amplitude (or the solver failed on the way): unbounded growth
  kGrowing,    ///< time limit reached, amplitude still growing
  kDecaying,   ///< time limit reached, amplitude still decreasing
};
[[nodiscard]] std::string to_string(Oscillation o);
/// True for a sustained oscillation: steady, growing or diverged.
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
  std::vector<std::size_t> observed;  ///< state indices measured (e.g. each wheelset's y)
  std::size_t reference = 0;          ///< which of `observed` decides the outcome
};

struct SettleResult {
  Oscillation outcome = Oscillation::kDecayed;
  std::vector<double> amplitude;  ///< per observed state (0 when decayed)
  double period = 0.0;            ///< of the reference state [s] (NaN when not found)
  double time = 0.0;              ///< simulated [s]
  long rhs_evaluations = 0;
  std::vector<double> final_state;
  std::string message;            ///< solver failure cause, if any
};

/// Integrates `system` from x0 in segments until the reference amplitude settles, decays or
/// diverges (or max_time). Throws std::invalid_argument for bad options, and
/// std::runtime_error when the solver fails before the reference state has swung across zero
/// and back once: a start that cannot be integrated (e.g. a wheel put into the rail by the
/// disturbance) is no oscillation.
[[nodiscard]] SettleResult run_until_settled(const vehicle::OdeSystem& system,
                                             std::span<const double> x0,
                                             const SettleOptions& options);

}  // namespace ferro::scenarios::analysis
