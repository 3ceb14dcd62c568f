#pragma once
// Sweeps of independent constant-speed runs (speeds x reduction factors): the steady
// oscillation amplitude of each wheelset at each point, run over a pool of local threads; a
// journal records each finished point durably so that an interrupted sweep resumes without
// redoing it. run_sweep deals the points to the ranks of an executor (sweep_executor.hpp; rank 0
// gathers and writes) and to threads within each, with the same per-point function, so serial,
// threaded and MPI sweeps give the same numbers.

#include <atomic>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ferro/scenarios/analysis/limit_cycle.hpp"
#include "ferro/scenarios/analysis/scene_analysis.hpp"
#include "ferro/scenarios/analysis/studies.hpp"
#include "ferro/scenarios/analysis/sweep_executor.hpp"
#include "ferro/scenarios/claimed_output.hpp"
#include "ferro/scenarios/model_factory.hpp"

namespace ferro::scenarios::analysis {

struct SweepPoint {
  double speed = 0.0;  ///< [m/s]
  contact::ReductionFactors k;
};

struct SweepPointResult {
  std::size_t index = 0;
  SweepPoint point;
  Oscillation outcome = Oscillation::kDecayed;  ///< of the vehicle (every wheelset decides)
  std::size_t holder = 0;         ///< wheelset holding the outcome (index into amplitude)
  std::vector<double> amplitude;  ///< per wheelset lateral state [m]
  double period = NAN;            ///< of the holding wheelset [s]
  double time = 0.0;              ///< simulated [s]
  long rhs_evaluations = 0;
  double cpu_seconds = 0.0;       ///< thread CPU time of the point [s]
};

/// One line of text, exact in every number (17 significant digits), and back.
[[nodiscard]] std::string serialize(const SweepPointResult& r);
/// Throws std::invalid_argument naming `where` for a malformed line.
[[nodiscard]] SweepPointResult deserialize(const std::string& line, const std::string& where);

/// Runs point `index` of a sweep of `scene`: constant speed from the scene's initial state plus
/// `lateral_offset` on the leading wheelset, until settled (options.observed is filled with the
/// wheelset lateral states). `resources`: the scene's track and geometry, built once per sweep.
[[nodiscard]] SweepPointResult run_sweep_point(const Scene& scene, const ModelResources& resources,
                                               std::size_t index, const SweepPoint& point,
                                               double lateral_offset, SettleOptions options);

/// A folder of finished points, one file each, written to a temporary name, synced and renamed
/// into place: a point is either wholly recorded or absent, whatever the interruption.
class SweepJournal {
 public:
  /// Creates the folder when missing. `signature` identifies the sweep (scene text and
  /// options); opening a folder written for another sweep throws std::invalid_argument.
  SweepJournal(std::string folder, const std::string& signature);
  [[nodiscard]] std::map<std::size_t, SweepPointResult> load() const;
  void record(const SweepPointResult& r) const;
  [[nodiscard]] const std::string& folder() const { return folder_; }

 private:
  std::string folder_;
};

struct PoolOptions {
  int jobs = 1;                                            ///< worker threads
  std::function<void(const SweepPointResult&)> on_done;   ///< called (serialised) per point
  std::function<bool()> should_stop;                      ///< polled before each point
};

/// Calls body(i) for i in [0, n) over `jobs` threads (the calling thread is one of them); stops
/// handing out indices once should_stop() returns true. An exception in a body stops the
/// others and is rethrown.
void parallel_for(std::size_t n, const std::function<void(std::size_t)>& body, int jobs,
                  const std::function<bool()>& should_stop = {});

/// Runs `run(index)` for each index in `todo` over `jobs` threads; returns the results in the
/// order of `todo` (points not run because of a stop are absent). An exception in a point stops
/// the pool and is rethrown.
[[nodiscard]] std::vector<SweepPointResult> run_pool(
    const std::vector<std::size_t>& todo,
    const std::function<SweepPointResult(std::size_t)>& run, const PoolOptions& options);

/// Writes a sweep to a new HDF5 file (kind "sweep"): /sweep/speed, k11, k22, outcome (codes:
/// attribute `outcome_codes`), holder, period, amplitude (points x wheelsets), with the scene
/// text.
void write_sweep(const Scene& scene, const std::vector<std::string>& wheelset_names,
                 const std::vector<SweepPointResult>& results, const std::string& path);

/// A sweep as asked for: speeds x reduction factors, settled runs, threads, resumption.
struct SweepRequest {
  double speed_min = NAN;  ///< [m/s]
  double speed_max = NAN;  ///< [m/s]
  int points = 10;         ///< speeds from min to max, evenly spaced (1 when min = max)
  std::vector<double> k = {1.0};     ///< reduction factors, one set of speeds each
  std::string coefficient = "both";  ///< which factor k sets: both | k11 | k22
  SettleRequest settle;              ///< its k11, k22: the factors k does not set
  int jobs = 1;                      ///< worker threads per process
  int max_new_points = -1;           ///< at most this many new points per process (-1: all)
  bool restart = false;              ///< forget the journal's finished points
  std::string output;   ///< HDF5 file written once every point is finished ("": none)
  std::string journal;  ///< folder of finished points, removed when complete ("": none)
};

/// The request's values as parameters (see parameters.hpp): every field but output and journal.
[[nodiscard]] Parameters parameters(SweepRequest& request);

/// The points of a request, speeds fastest-varying, each factor validated. Throws
/// std::invalid_argument naming the bad value.
[[nodiscard]] std::vector<SweepPoint> sweep_points(const Scene& scene, const SweepRequest& request,
                                                   Spelling spelling = Spelling::key);

struct SweepCallbacks {
  /// Before the first point: points of the sweep, points already in the journal, this rank's
  /// points to compute now.
  std::function<void(std::size_t total, std::size_t finished, std::size_t todo)> on_start;
  /// After each point of this rank (serialised): the result and the count done so far.
  std::function<void(const SweepPointResult&, std::size_t done)> on_done;
  /// Polled before each point; true stops handing out points (finished ones stay recorded).
  std::function<bool()> should_stop;
  /// Progress text for a terminal (progress_text.hpp): sweep_start_line() on rank 0 before the
  /// first point, sweep_point_line() after each point of this rank unless `quiet`, and
  /// sweep_stopped_line() when rank 0 ends before every point is finished.
  std::function<void(const std::string& text)> progress;
  bool quiet = false;
};

struct SweepOutcome {
  bool root = true;        ///< rank 0: holds the merged results and wrote the output
  bool complete = false;   ///< every point finished and no stop asked (rank 0)
  std::size_t total = 0;   ///< points of the sweep
  std::size_t finished = 0;                 ///< finished points known to rank 0
  std::vector<SweepPointResult> results;    ///< rank 0, complete: every point by index
  std::vector<std::string> wheelset_names;  ///< rank 0, complete: the amplitude columns
  double wall_seconds = 0.0;  ///< this call [s]
  double cpu_seconds = 0.0;   ///< rank 0, complete: CPU time over all points [s]
};

/// Runs the points of `request` not yet in its journal over `executor`'s ranks and
/// `request.jobs` threads each; rank 0 merges, and once every point is finished writes
/// `request.output` and removes the journal. Throws std::invalid_argument for a bad request.
[[nodiscard]] SweepOutcome run_sweep(const Scene& scene, const SweepRequest& request,
                                     SweepExecutor& executor, const SweepCallbacks& callbacks = {},
                                     Spelling spelling = Spelling::key);

/// The files of a sweep: the output (`given`, else <output.file stem>_sweep.h5) and its journal
/// <output>.points. The writing rank claims the output before any point is computed (a path that
/// would be refused is refused at once; written as <output>.part until commit).
struct SweepFiles {
  std::string output, journal;
  std::optional<ClaimedOutput> claimed;  ///< the writing rank's
};
/// Claims the files (on the writing rank) and points `request`'s output and journal at them.
[[nodiscard]] SweepFiles claim_sweep_files(const Scene& scene, const std::string& given,
                                           bool overwrite, bool no_plots, bool writer,
                                           SweepRequest& request);

}  // namespace ferro::scenarios::analysis
