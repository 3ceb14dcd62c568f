#pragma once
// Running a scene: time simulation to HDF5 (and CSV), and the eigenvalue speed sweep.
// Library code: no printing; progress and interruption go through callbacks.

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ferro/scenarios/parameters.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/stability.hpp"

namespace ferro::scenarios {

struct RunOptions {
  std::string output_file;                      ///< overrides scene.output.file when not empty
  std::optional<std::vector<std::string>> csv;  ///< overrides scene.output.csv when set
  bool overwrite = false;                       ///< replace existing output files
  std::function<void(double t)> progress;       ///< called at each output time
  /// Polled before every right-hand side, after every integrator step and at each output time
  /// (cheap: e.g. an atomic load); true stops the run at once.
  std::function<bool()> should_stop;
  std::string stop_reason = "interrupted";      ///< status message prefix when should_stop fired
  /// Simulated seconds per wall-clock second, >= 0 (0 = as fast as possible). With pace 1 a run
  /// advances in real time, so it can be watched live.
  double pace = 0.0;
  /// Called with each sample: time [s] and the values of RunSummary::channels [SI].
  std::function<void(double t, std::span<const double> values)> on_sample;
  /// false: no HDF5 (nor CSV) file; the samples reach the caller through on_sample only.
  bool write_output = true;
};
/// The options a user sets as parameters (see parameters.hpp): pace.
[[nodiscard]] Parameters parameters(RunOptions& options);

struct RunSummary {
  vehicle::IntegrationResult::Status status = vehicle::IntegrationResult::Status::kCompleted;
  std::string status_text;  ///< completed | interrupted | solver_failure
  std::string message;      ///< cause of a failure or interruption
  double t_reached = 0.0;   ///< time of the last sample written [s]
  long samples = 0;
  double wall_seconds = 0.0;
  long steps = 0;
  long rhs_evaluations = 0;
  long jacobians = 0;          ///< bdf2's Jacobians; 0 for the other integrators
  long newton_iterations = 0;  ///< bdf2's Newton iterations; 0 for the other integrators
  long step_splits = 0;        ///< bdf2's split steps (Newton failures); 0 for the others
  std::string output_file;                    ///< empty when no file was written
  std::string csv_file;                       ///< empty when no CSV was asked for
  std::vector<vehicle::SignalInfo> channels;  ///< states then derived signals
  std::size_t state_count = 0;                ///< the first state_count channels are states
  std::vector<std::string> plots;  ///< signals to draw: output.plots, else every state
  std::vector<double> peak_abs;               ///< max |value| per channel over the run
  std::vector<double> final_values;           ///< per channel at t_reached (last sample)
};

/// Integrates the scene, writing samples as they come (output files: output_file.hpp; layout:
/// docs/OUTPUT.md). Never throws for a solver failure or an interruption (the summary says
/// which). Bad input (std::invalid_argument) is refused before any file is touched; a failure
/// after the output file exists (static equilibrium, I/O) is recorded in it as status `error`
/// before the exception leaves.
RunSummary run_scene(const Scene& scene, const RunOptions& options = {});

/// Every check run_scene makes before its first step, without writing anything: the model
/// built through the same factory, the initial-state and signal names, the integrator
/// settings, the output path against the scene's inputs. What `ferrodyn validate` runs.
void check_scene(const Scene& scene, const RunOptions& options = {});

struct EigenReport {
  std::vector<vehicle::SweepPoint> sweep;
  std::optional<double> critical_speed;              ///< [m/s], eigenvalue crossing
  std::optional<double> closed_form_critical_speed;  ///< eq. (151) when its assumptions hold
  std::string closed_form_note;                      ///< why eq. (151) does or does not apply
  std::vector<vehicle::Mode> modes_at_scene_speed;
};

/// Linear eigenvalue analysis over scene.eigen's speed range, each speed about its own
/// equilibrium (linearisation_family(): zero for suspended_wheelset, the static equilibrium at
/// that speed for vehicles); the Hopf speed by the scan on scene.eigen's points and bisection to
/// kHopfRelTol.
[[nodiscard]] EigenReport run_eigen(const Scene& scene);
/// Most speeds an eigenvalue sweep takes (analysis.eigen.points, --points).
inline constexpr int kMaxEigenPoints = 100000;
/// Relative width the Hopf speed is bisected to [-].
inline constexpr double kHopfRelTol = 1e-10;
/// The Hopf speed in [v_min, v_max] (vehicle::critical_speed on linearisation_family(scene):
/// each speed about its own equilibrium): what run_eigen and the bifurcation analysis report.
[[nodiscard]] std::optional<double> hopf_speed(const Scene& scene, double v_min, double v_max,
                                               int scan_points);
[[nodiscard]] std::optional<double> hopf_speed(const vehicle::LinearisationAtSpeed& family,
                                               double v_min, double v_max, int scan_points);
/// Writes the report under /eigen of a new HDF5 file, with the scene metadata.
void write_eigen_report(const Scene& scene, const EigenReport& report, const std::string& path);

/// Number of output samples of a run over [0, t_end] every `interval` seconds. Throws
/// std::invalid_argument ("<where>: ...") for an interval that is not a positive finite number or
/// that would give more than kMaxOutputSamples samples.
[[nodiscard]] std::uint64_t output_sample_count(double t_end, double interval,
                                                const std::string& where = "output.interval");
/// For a fixed-step integrator, the output interval must be a whole multiple of the step: a
/// sample between two steps would interpolate the states, and the contact forces derived from
/// interpolated states are not the model's (an error of a micrometre in a Hertz approach of
/// fifty is a tenth of the wheel load). Throws std::invalid_argument ("<where>: ...") otherwise.
void check_output_on_steps(double interval, const vehicle::IntegratorSettings& solver,
                           const std::string& where = "output.interval");
/// At most this many output samples per run (8 TB per signal): anything beyond is a typo.
inline constexpr double kMaxOutputSamples = 1e12;

/// UTC time stamp "YYYY-MM-DDThh:mm:ssZ".
[[nodiscard]] std::string utc_timestamp();

}  // namespace ferro::scenarios
