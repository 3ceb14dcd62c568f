// A whole sweep over an executor's ranks and threads, resumable from its journal (see
// sweep.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>

#include "ferro/scenarios/analysis/progress_text.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"
#include "ferro/scenarios/run.hpp"

namespace ferro::scenarios::analysis {
namespace {

namespace fs = std::filesystem;

// Everything that changes the numbers identifies the sweep.
std::string sweep_signature(const Scene& scene, const std::vector<SweepPoint>& points,
                            const SweepRequest& a, const SettleOptions& settle) {
  std::string signature = scene.text + " records-with-holder";
  for (const auto& p : points)
    signature += fmt::format(" {:.17g}/{:.17g}/{:.17g}", p.speed, p.k.k11, p.k.k22);
  signature +=
      fmt::format(" {} {} {} {} {} {} {} {}", a.settle.disturbance, settle.segment, settle.max_time,
                  settle.output_interval, settle.zero_amplitude, settle.max_amplitude,
                  settle.amplitude.periods, settle.amplitude.rel_tol);
  return signature;
}

// This rank's points still to compute: dealt by index, fastest first. Above the critical speed
// a run hunts into flange contact and costs several times a decaying one, so starting those
// first keeps the threads busy to the end instead of leaving the dearest points for last
// (results are stored by index, whatever the order).
std::vector<std::size_t> points_to_run(const std::vector<SweepPoint>& points,
                                       const std::map<std::size_t, SweepPointResult>& finished,
                                       const SweepExecutor& ex, int max_new_points) {
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (finished.count(i) == 0 &&
        static_cast<int>(i % static_cast<std::size_t>(ex.size())) == ex.rank())
      todo.push_back(i);
  }
  std::stable_sort(todo.begin(), todo.end(), [&points](std::size_t l, std::size_t r) {
    return points[l].speed > points[r].speed;
  });
  if (max_new_points >= 0 && todo.size() > static_cast<std::size_t>(max_new_points))
    todo.resize(static_cast<std::size_t>(max_new_points));
  return todo;
}

// Rank 0: the journal (earlier runs) merged with what every rank computed now.
std::map<std::size_t, SweepPointResult> merge(std::map<std::size_t, SweepPointResult> all,
                                              const std::vector<std::string>& gathered,
                                              const SweepJournal* journal) {
  for (const auto& chunk : gathered) {
    std::size_t pos = 0;
    while (pos < chunk.size()) {
      const auto end = chunk.find('\n', pos);
      const auto line = chunk.substr(pos, end - pos);
      if (!line.empty()) {
        auto r = deserialize(line, "sweep gather");
        all[r.index] = r;
      }
      pos = end == std::string::npos ? chunk.size() : end + 1;
    }
  }
  if (journal != nullptr) {
    for (const auto& [i, r] : journal->load()) all.emplace(i, r);  // other ranks' records
  }
  return all;
}

}  // namespace

Parameters parameters(SweepRequest& r) {
  Parameters p = {
      {"speed_min", "m/s", "lowest speed", &r.speed_min, false},
      {"speed_max", "m/s", "highest speed", &r.speed_max, false},
      Parameter{"points", "", "speeds between min and max", &r.points}.counting(
          {1, kMaxEigenPoints}),
      {"k", "-", "reduction factors, one set of speeds each", &r.k},
      {"coefficient", "",
       "which factor k sets: both (K11 = K22 = K23 = K33), k11, k22", &r.coefficient},
  };
  for (auto& s : parameters(r.settle)) p.push_back(std::move(s));
  Parameters run = {
      Parameter{"jobs", "", "worker threads per process", &r.jobs}.counting({1, kMaxJobs}),
      Parameter{"max_new_points", "",
                "compute at most this many new points per process, then stop (resumable; for "
                "batch-queue time limits)",
                &r.max_new_points, false}
          .counting({0, std::numeric_limits<int>::max()}),
      {"restart", "", "forget finished points and start over", &r.restart},
  };
  for (auto& q : run) p.push_back(std::move(q));
  return p;
}

std::vector<SweepPoint> sweep_points(const Scene& scene, const SweepRequest& a, Spelling sp) {
  const std::string min = spelled("speed_min", sp), max = spelled("speed_max", sp);
  if (std::isnan(a.speed_min) || std::isnan(a.speed_max) ||
      !(a.speed_max >= a.speed_min && a.speed_min > 0.0))
    throw std::invalid_argument(fmt::format("{}/{}: required, 0 < min <= max", min, max));
  if (a.points < 1 || (a.points == 1) != (a.speed_min == a.speed_max))
    throw std::invalid_argument(
        fmt::format("{}: >= 1 (1 only when min = max)", spelled("points", sp)));
  if (a.jobs < 1) throw std::invalid_argument(fmt::format("{}: must be >= 1", spelled("jobs", sp)));
  const auto factors = study_reductions(a.k, a.coefficient, a.settle.reduction(), sp);
  std::vector<SweepPoint> points;
  for (const contact::ReductionFactors& r : factors) {
    (void)with_reduction(scene, r);  // validates the factors
    for (int i = 0; i < a.points; ++i) {
      const double v = a.points == 1 ? a.speed_min
                                     : a.speed_min + (a.speed_max - a.speed_min) * i /
                                                         static_cast<double>(a.points - 1);
      points.push_back({v, r});
    }
  }
  return points;
}

SweepOutcome run_sweep(const Scene& scene, const SweepRequest& a, SweepExecutor& ex,
                       const SweepCallbacks& callbacks, Spelling sp) {
  const auto points = sweep_points(scene, a, sp);
  const auto settle = settle_options(scene, a.settle, sp);
  const std::string signature = sweep_signature(scene, points, a, settle);
  std::unique_ptr<SweepJournal> journal;
  if (!a.journal.empty()) {
    // Rank 0 creates (or clears) the folder before the others open it.
    if (ex.rank() == 0 && a.restart && fs::exists(a.journal)) fs::remove_all(a.journal);
    ex.barrier();
    if (ex.rank() == 0) journal = std::make_unique<SweepJournal>(a.journal, signature);
    ex.barrier();
    if (ex.rank() != 0) journal = std::make_unique<SweepJournal>(a.journal, signature);
  }
  const auto finished = journal ? journal->load() : std::map<std::size_t, SweepPointResult>{};
  const auto todo = points_to_run(points, finished, ex, a.max_new_points);
  if (callbacks.on_start) callbacks.on_start(points.size(), finished.size(), todo.size());
  if (callbacks.progress && ex.rank() == 0) {
    callbacks.progress(sweep_start_line(points.size(), finished.size(), a.journal, ex.size(), a.jobs));
  }
  const auto wall0 = std::chrono::steady_clock::now();
  std::size_t done = 0;
  PoolOptions pool;
  pool.jobs = a.jobs;
  pool.should_stop = callbacks.should_stop;
  pool.on_done = [&](const SweepPointResult& r) {
    if (journal) journal->record(r);
    ++done;
    if (callbacks.on_done) callbacks.on_done(r, done);
    if (callbacks.progress && !callbacks.quiet) {
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      callbacks.progress(sweep_point_line(ex.rank(), done, todo.size(), elapsed, r));
    }
  };
  const auto resources = build_resources(scene);
  const auto mine = run_pool(
      todo,
      [&](std::size_t i) {
        return run_sweep_point(scene, resources, i, points[i], a.settle.disturbance, settle);
      },
      pool);
  SweepOutcome out;
  out.total = points.size();
  out.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::string text;
  for (const auto& r : mine) text += serialize(r) + "\n";
  const bool stopped = callbacks.should_stop && callbacks.should_stop();
  const auto gathered = ex.gather(text);
  out.root = ex.rank() == 0;
  if (!out.root) return out;
  const auto all = merge(finished, gathered, journal.get());
  out.finished = all.size();
  out.complete = !stopped && all.size() == points.size();
  if (!out.complete) {
    if (callbacks.progress) callbacks.progress(sweep_stopped_line(out, a.journal));
    return out;
  }
  for (const auto& [i, r] : all) {
    out.cpu_seconds += r.cpu_seconds;
    out.results.push_back(r);
  }
  const auto probe = build_system(scene, points.front().speed);
  out.wheelset_names = lateral_states(*probe).name;
  if (!a.output.empty()) write_sweep(scene, out.wheelset_names, out.results, a.output);
  if (journal) fs::remove_all(a.journal);  // complete: the results hold every point
  return out;
}

SweepFiles claim_sweep_files(const Scene& scene, const std::string& given, bool overwrite,
                             bool no_plots, bool writer, SweepRequest& request) {
  SweepFiles files;
  files.output = given.empty() ? sibling(scene.output.file, "_sweep.h5") : given;
  files.journal = files.output + ".points";
  if (writer) {
    files.claimed.emplace(ClaimedOutput::given_or(given, files.output, overwrite,
                                                  scene_inputs(scene), no_plots));
  }
  request.output = files.claimed ? files.claimed->write_path() : files.output;
  request.journal = files.journal;
  return files;
}

}  // namespace ferro::scenarios::analysis
