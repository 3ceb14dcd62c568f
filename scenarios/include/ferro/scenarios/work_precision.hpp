#pragma once
// Work-precision study of a scene: every integrator setting of a list runs the same scene from
// the same initial state; each run's error is measured against a tight-tolerance reference run
// and set beside its CPU time, steps and right-hand-side calls.
//
// Error of a run: the largest, over the compared states, of max_t |x(t) - x_ref(t)| divided by
// max_t |x_ref(t)| (each state relative to its own peak), on the scene's output grid. The
// compared states default to every wheelset's lateral displacement and yaw angle.
//
// On a limit cycle that error measures phase more than the cycle: a period off by 0.1 % moves
// the motion by 0.6 % of its amplitude per period, and where a transient decides between
// coexisting cycles, a tolerance change can pick the other one. For hunting runs the study
// therefore also reports a cycle error, the largest relative deviation of each compared state's
// amplitude (half its peak-to-peak) and frequency (from its mean crossings) from the
// reference's, and can start every run from a state on the reference's settled motion
// (`settle`): the reference integrates [0, settle] from the scene's initial state and every run,
// the reference included, then covers [settle, settle + t_end] from where it ended.

#include <optional>
#include <string>
#include <vector>

#include "ferro/scenarios/parameters.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/vehicle/integrator.hpp"

namespace ferro::scenarios {

struct WorkPrecisionOptions {
  /// Integrators to compare, each "method" or "method:max_order" (e.g. cvode_bdf:2).
  std::vector<std::string> integrators = {"cvode_bdf", "cvode_bdf:2"};
  std::vector<double> rtols = {1e-3, 1e-4, 1e-5, 1e-6};
  /// atol = rtol * atol_per_rtol [state units].
  double atol_per_rtol = 1e-2;
  /// Reference: cvode_bdf at this rtol (atol likewise scaled).
  double reference_rtol = 1e-9;
  /// States compared; empty: every "<wheelset>.y" and "<wheelset>.yaw".
  std::vector<std::string> states;
  /// Error the best choice must meet [-].
  double target_error = 1e-2;
  /// Settling time [s] before the compared interval (see above); 0: start from the scene's state.
  double settle = 0.0;
  /// Error that picks the best choice: "pointwise" or "cycle".
  std::string metric = "pointwise";
};

/// The options as parameters (see parameters.hpp).
[[nodiscard]] Parameters parameters(WorkPrecisionOptions& options);

/// Amplitude and frequency of a sampled oscillation: amplitude = half of (max - min), each
/// extremum refined by the parabola through it and its two neighbours; frequency from the upward
/// crossings of the mean, located by linear interpolation: (crossings - 1) / (last - first),
/// NaN with fewer than two crossings.
struct CycleStatistics {
  double amplitude = 0.0;
  double frequency = 0.0;
  int crossings = 0;
};
[[nodiscard]] CycleStatistics cycle_statistics(const std::vector<double>& t,
                                               const std::vector<double>& x);

struct WorkPrecisionPoint {
  std::string integrator;  ///< as given ("cvode_bdf:2")
  vehicle::IntegratorSettings settings;
  std::string status;  ///< completed | solver_failure
  double t_reached = 0.0;
  long steps = 0, rhs_evaluations = 0;
  double cpu_seconds = 0.0;  ///< integration only (the model is built once, before)
  double error = 0.0;        ///< NaN when the run did not complete
  double cycle_error = 0.0;  ///< amplitude and frequency (see above); NaN likewise
};

struct WorkPrecisionReport {
  double t_end = 0.0;
  double setup_cpu_seconds = 0.0;  ///< model, tables and static equilibrium, once
  double settle = 0.0;             ///< compared interval [settle, settle + t_end]
  double settle_cpu_seconds = 0.0; ///< the reference's settling run
  std::string metric;              ///< which error chose `best`
  /// Per compared state, the reference's amplitude and frequency over the compared interval.
  std::vector<CycleStatistics> reference_cycles;
  WorkPrecisionPoint reference;
  std::vector<WorkPrecisionPoint> points;
  std::vector<std::string> compared_states;
  /// Index into points of the cheapest completed run with error <= target_error.
  std::optional<std::size_t> best;
};

/// The checks of the options run_work_precision makes before its first run, with the settled
/// interval [0, settle + t_end] staying on the designed track. Throws std::invalid_argument
/// naming the option.
void check_work_precision(const Scene& scene, const WorkPrecisionOptions& options);

/// Runs the study (check_work_precision first). Throws std::invalid_argument naming the option
/// for a bad integrator entry, tolerance or state name.
[[nodiscard]] WorkPrecisionReport run_work_precision(const Scene& scene,
                                                     const WorkPrecisionOptions& options);

/// Writes the table as CSV (one row per run, the reference first).
void write_work_precision_csv(const WorkPrecisionReport& report, const std::string& path);

/// The table as `ferrodyn bench work-precision` prints it (Markdown rows), with the reference's
/// cycles and the cheapest setting within options.target_error.
[[nodiscard]] std::string work_precision_report(const Scene& scene,
                                                const WorkPrecisionReport& report,
                                                const WorkPrecisionOptions& options);

}  // namespace ferro::scenarios
