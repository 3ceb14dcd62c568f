#pragma once
// Nonlinear critical speed of any OdeSystem family parametrised by speed:
//  - ramping: a run whose speed decreases slowly after a lateral disturbance; the speed where
//    the oscillation envelope falls below a threshold for good;
//  - periodic branch: constant-speed runs followed downward along the limit cycles, each speed
//    started from the previous limit cycle's final state, to the fold; the fold is bracketed by
//    bisection.
//
// References: Toumi 2016, chapter 4 (ramping from 110 m/s at -1 m/s^2; bifurcation diagram;
//   Vc = 273 km/h ramping, 280 km/h bifurcation on the Manchester vehicle); True, "On the theory
//   of nonlinear dynamics and its applications in vehicle systems dynamics" (1999): the
//   nonlinear critical speed is the fold of the periodic branch, at or below the Hopf speed.
// Known deviations: the ramp holds the speed constant over short pieces (`hold`), rebuilding the
//   system at each piece's mid speed, so it works on any speed-parametrised OdeSystem; a model
//   with its own speed profile does the same with a continuous v(t).

#include <functional>
#include <optional>
#include <vector>

#include "ferro/scenarios/analysis/limit_cycle.hpp"
#include "ferro/vehicle/stability.hpp"

namespace ferro::scenarios::analysis {

struct RampOptions {
  double speed_initial = 0.0;     ///< [m/s]
  double deceleration = 1.0;      ///< [m/s^2], > 0
  double speed_final = 0.0;       ///< the run stops at this speed [m/s]
  double hold = 0.1;              ///< duration of each constant-speed piece [s]
  double output_interval = 2e-3;  ///< [s]
  double envelope_window = 2.0;   ///< envelope = half the peak-to-peak over this trailing time [s]
  double threshold = 1e-4;        ///< oscillation died out when the envelope stays below [unit]
  double max_amplitude = 0.05;    ///< the run stops as diverged when any |x| exceeds this [unit]
  vehicle::IntegratorSettings solver;
  /// State indices watched (each wheelset's lateral displacement): the system's envelope is the
  /// largest of theirs.
  std::vector<std::size_t> observed;
};

struct RampResult {
  std::vector<double> time, speed;
  std::vector<std::vector<double>> signals;    ///< per observed state, at `time`
  std::vector<std::vector<double>> envelopes;  ///< per observed state, at `time`
  std::vector<double> envelope;  ///< the system's: the largest of `envelopes` at each time
  /// Speed where the system's envelope goes below the threshold for good [m/s]: every observed
  /// state's oscillation has died out.
  std::optional<double> decay_speed;
  double decay_time = NAN;            ///< [s]
  /// Which observed state held the envelope last above the threshold (the last to die out),
  /// or the largest at the end when none went below.
  std::size_t holder = 0;
  /// Speed at the system envelope's maximum [m/s]: where the oscillation stops growing. For a
  /// linear model and a ramp slow enough, the speed where the least damped mode's damping
  /// crosses zero; on a nonlinear vehicle (a cycle limited by the flange) only where the
  /// plateau is highest, which is no critical speed.
  double peak_speed = NAN;
  /// Envelope at its maximum over the envelope once the first full window has passed [-]
  /// (1 when the maximum is in the first window: no growth).
  double envelope_growth = NAN;
  bool completed = true;              ///< false when the solver failed (message says why)
  std::string message;
};

/// Ramping run from x0. Throws std::invalid_argument for bad options.
[[nodiscard]] RampResult ramp_down(const vehicle::SystemAtSpeed& factory,
                                   std::span<const double> x0, const RampOptions& options);

struct BranchPoint;

struct BranchOptions {
  double speed_start = 0.0;   ///< first (highest) speed [m/s]
  double speed_stop = 0.0;    ///< lowest speed followed [m/s]
  double speed_step = 1.0;    ///< downward step before bisection [m/s]
  double bracket = 0.1;       ///< bisection ends at this bracket width [m/s]
  SettleOptions settle;
  std::function<void(const BranchPoint&)> on_point;  ///< progress, after each run
};

struct BranchPoint {
  double speed = 0.0;  ///< [m/s]
  SettleResult run;
  bool bisection = false;  ///< computed while bracketing the fold
};

struct BranchResult {
  std::vector<BranchPoint> points;  ///< in the order computed
  /// Lowest speed with a sustained oscillation of any observed state found (upper end of the
  /// fold bracket): the system's nonlinear critical speed.
  std::optional<double> lowest_sustained;
  /// Which observed state holds the cycle at lowest_sustained (SettleResult::holder).
  std::size_t holder = 0;
  double bracket_low = NAN, bracket_high = NAN;  ///< the fold lies in [low, high] [m/s]
  bool fold_found = false;  ///< false: sustained at speed_stop, or not at speed_start
  /// Speed where the squared amplitude of the kOnsetPoints lowest cycles (steady or approaching;
  /// each cycle's largest observed amplitude, that of the state holding it), extrapolated
  /// linearly in speed, reaches zero [m/s]; NaN with fewer than two
  /// such points or no positive slope. A supercritical Hopf branch has A^2 proportional to
  /// V - V_Hopf near its onset; the two cycles nearest the fold are the ones in that range (a
  /// third may already be limited by another nonlinearity, e.g. the flange).
  double amplitude_squared_zero = NAN;
  /// The extrapolated zero lies within one bracket width of the fold bracket: the amplitude
  /// goes to zero at the fold (supercritical onset, the fold is the Hopf point) instead of
  /// jumping from a finite cycle to rest (subcritical, fold below the Hopf speed).
  bool supercritical = false;
  static constexpr int kOnsetPoints = 2;
};

/// Follows the periodic branch downward from x_disturbed at speed_start. Throws
/// std::invalid_argument for bad options.
[[nodiscard]] BranchResult follow_periodic_branch(const vehicle::SystemAtSpeed& factory,
                                                  std::span<const double> x_disturbed,
                                                  const BranchOptions& options);

}  // namespace ferro::scenarios::analysis
