#pragma once
// Work-precision study of a scene: every integrator setting of a list runs the same scene from
// the same initial state; each run's error is measured against a tight-tolerance reference run
// and set beside its CPU time, steps and right-hand-side calls.
//
// Error of a run: the largest, over the compared states, of max_t |x(t) - x_ref(t)| divided by
// max_t |x_ref(t)| (each state relative to its own peak), on the scene's output grid. The
// compared states default to every wheelset's lateral displacement and yaw angle.

#include <optional>
#include <string>
#include <vector>

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
};

struct WorkPrecisionPoint {
  std::string integrator;  ///< as given ("cvode_bdf:2")
  vehicle::IntegratorSettings settings;
  std::string status;  ///< completed | solver_failure
  double t_reached = 0.0;
  long steps = 0, rhs_evaluations = 0;
  double cpu_seconds = 0.0;  ///< integration only (the model is built once, before)
  double error = 0.0;        ///< NaN when the run did not complete
};

struct WorkPrecisionReport {
  double t_end = 0.0;
  double setup_cpu_seconds = 0.0;  ///< model, tables and static equilibrium, once
  WorkPrecisionPoint reference;
  std::vector<WorkPrecisionPoint> points;
  std::vector<std::string> compared_states;
  /// Index into points of the cheapest completed run with error <= target_error.
  std::optional<std::size_t> best;
};

/// Runs the study. Throws std::invalid_argument naming the option for a bad integrator entry,
/// tolerance or state name.
[[nodiscard]] WorkPrecisionReport run_work_precision(const Scene& scene,
                                                     const WorkPrecisionOptions& options);

/// Writes the table as CSV (one row per run, the reference first).
void write_work_precision_csv(const WorkPrecisionReport& report, const std::string& path);

}  // namespace ferro::scenarios
