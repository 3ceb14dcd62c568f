#pragma once
// Running a scene: time simulation to HDF5 (and CSV), and the eigenvalue speed sweep.
// Library code: no printing; progress and interruption go through callbacks.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ferro/scenarios/scene.hpp"
#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/stability.hpp"

namespace ferro::scenarios {

struct RunOptions {
  std::string output_file;                      ///< overrides scene.output.file when not empty
  std::optional<std::vector<std::string>> csv;  ///< overrides scene.output.csv when set
  std::function<void(double t)> progress;       ///< called at each output time
  std::function<bool()> should_stop;            ///< polled at each output time; true stops the run
  std::string stop_reason = "interrupted";      ///< status message prefix when should_stop fired
  /// Simulated seconds per wall-clock second (0 = as fast as possible). With pace 1 a run
  /// advances in real time, so it can be watched live.
  double pace = 0.0;
};

struct RunSummary {
  vehicle::IntegrationResult::Status status = vehicle::IntegrationResult::Status::kCompleted;
  std::string status_text;  ///< completed | interrupted | solver_failure
  std::string message;      ///< cause of a failure or interruption
  double t_reached = 0.0;   ///< [s]
  long samples = 0;
  double wall_seconds = 0.0;
  long steps = 0;
  long rhs_evaluations = 0;
  std::string output_file;
  std::string csv_file;                       ///< empty when no CSV was asked for
  std::vector<vehicle::SignalInfo> channels;  ///< states then derived signals
  std::size_t state_count = 0;                ///< the first state_count channels are states
  std::vector<double> peak_abs;               ///< max |value| per channel over the run
  std::vector<double> final_values;           ///< per channel at t_reached (last sample)
};

/// Integrates the scene, writing samples as they come. Never throws for a solver failure or an
/// interruption (the summary says which); throws for bad input or I/O failure after writing the
/// status into the file when it was already open.
RunSummary run_scene(const Scene& scene, const RunOptions& options = {});

struct EigenReport {
  std::vector<vehicle::SweepPoint> sweep;
  std::optional<double> critical_speed;              ///< [m/s], eigenvalue crossing
  std::optional<double> closed_form_critical_speed;  ///< eq. (151) when its assumptions hold
  std::string closed_form_note;                      ///< why eq. (151) does or does not apply
  std::vector<vehicle::Mode> modes_at_scene_speed;
};

/// Linear eigenvalue analysis over scene.eigen's speed range about the equilibrium
/// (equilibrium_state(): zero for suspended_wheelset, the static equilibrium for vehicles).
[[nodiscard]] EigenReport run_eigen(const Scene& scene);
/// Writes the report under /eigen of a new HDF5 file, with the scene metadata.
void write_eigen_report(const Scene& scene, const EigenReport& report, const std::string& path);

/// UTC time stamp "YYYY-MM-DDThh:mm:ssZ".
[[nodiscard]] std::string utc_timestamp();

}  // namespace ferro::scenarios
