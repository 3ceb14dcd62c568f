// Verbs of the analyses: assessment of a run (EN 14363 / UIC 518 / EN 12299), critical speed (ramp, bifurcation,
// eigen), reduction-factor studies and parallel sweeps (threads and, when built with it, MPI).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>

#include "cli.hpp"
#include "ferro/scenarios/claimed_output.hpp"
#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/assessment.hpp"
#include "ferro/scenarios/analysis/output.hpp"
#include "ferro/scenarios/analysis/progress_text.hpp"
#include "ferro/scenarios/analysis/report.hpp"
#include "ferro/scenarios/analysis/studies.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/report.hpp"
#include "ferro/scenarios/run.hpp"
#include "plotting.hpp"
#include "terminal.hpp"

namespace ferro::cli {
namespace {

namespace fs = std::filesystem;
namespace an = scenarios::analysis;
namespace fc = ferro::contact;
using scenarios::Scene;
constexpr scenarios::Spelling kOption = scenarios::Spelling::option;

// The input (scene or run file), output, plot and overwrite switches of an analysis verb, and
// its request.
struct VerbArgs {
  std::string input, output;
  bool no_plots = false, overwrite = false;
  /// Claims -o, else <stem of `beside`><suffix>, against `inputs`.
  [[nodiscard]] scenarios::ClaimedOutput claim(const std::string& beside, const char* suffix,
                                     std::vector<std::string> inputs) const {
    return scenarios::ClaimedOutput(output.empty() ? scenarios::sibling(beside, suffix) : output,
                          output.empty() ? "output" : "-o", overwrite, std::move(inputs),
                          no_plots);
  }
  /// After the report: the output file's name and its plots; returns the verb's exit code
  /// (`code` unless a stop request ended the plotting).
  [[nodiscard]] int finish(const std::string& out, int code = kExitOk) const {
    fmt::print("  output    {}\n", out);
    return no_plots ? code : plot_after_report("auto", out, {}, {}, code);
  }
};
template <class Request>
struct Analysis : VerbArgs {
  Request request;
};
// ---------------------------------------------------------------- assess
struct AssessArgs : Analysis<an::AssessmentRequest> {
  bool all_rows = false;
};

int do_assess(const AssessArgs& a) {
  if (!fs::exists(a.input))
    throw std::invalid_argument(fmt::format("assess: no such file '{}'", a.input));
  const an::AssessmentOptions o = an::assessment_options(a.request, kOption);
  auto out = a.claim(a.input, "_assessment.h5", {a.input});
  const auto r = an::assess_run(a.input, o);
  fmt::print("{}", an::assessment_report(a.input, r, a.all_rows));
  an::write_assessment(r, a.input, out.write_path());
  out.file->commit();
  return a.finish(out.path());  // the verdict is a result, not a failure of the assessment
}

using RampArgs = Analysis<an::RampRequest>;

int do_ramp(const RampArgs& a) {
  const Scene scene = scenarios::load_scene(a.input);
  auto out = a.claim(scene.output.file, "_ramp.h5", scenarios::scene_inputs(scene));
  const auto study = an::run_ramp(scene, a.request, kOption);
  fmt::print("{}", an::ramp_report(study, a.request));
  an::write_ramp(study.scene, study.result, study.options, study.observed, out.write_path());
  out.file->commit();
  const int code = a.finish(out.path(), study.result.completed ? kExitOk : kExitRunFailure);
  if (!study.result.completed) {
    std::fflush(stdout);
    fmt::print(stderr, "ferrodyn: failure: the ramp stopped before its end: {}\n",
               study.result.message);
  }
  return code;
}

using BranchArgs = Analysis<an::BranchRequest>;

// Progress of the branch of factors k, on stderr.
std::function<void(const an::BranchPoint&)> branch_progress(
    const fc::ReductionFactors& k, const std::vector<std::string>& names) {
  return [k, &names](const an::BranchPoint& p) {
    fmt::print(stderr, "{}", an::branch_progress_line(k, names, p));
  };
}

int do_branch(const BranchArgs& a) {
  const Scene scene = scenarios::load_scene(a.input);
  const an::SettleRequest& settle = a.request.settle;
  fmt::print("ferrodyn critical-speed bifurcation: {} ({}), K11 = {}, K22 = {}\n", scene.name,
             scene.path, settle.k11, settle.k22);
  std::vector<std::string> names;
  const auto k = fc::ReductionFactors::following_k22(settle.k11, settle.k22);
  auto out =
      a.claim(scene.output.file, "_bifurcation.h5", scenarios::scene_inputs(scene));
  const auto row =
      an::run_bifurcation(scene, a.request, k, &names, branch_progress(k, names), kOption);
  fmt::print("{}", an::branch_report(row, names));
  an::write_branch(an::with_reduction(scene, row.k), row.branch, names, row.hopf_speed,
                   out.write_path());
  out.file->commit();
  return a.finish(out.path());
}

// The verb's own range, whatever the scene's analysis.eigen says.
scenarios::RunOverrides eigen_range_defaults() {
  scenarios::RunOverrides r;
  r.speed_min = 1.0;
  r.speed_max = 150.0;
  r.points = 150;
  return r;
}

struct EigenArgs : VerbArgs {
  double k11 = 1.0, k22 = 1.0;
  scenarios::RunOverrides range = eigen_range_defaults();
};

int do_eigen(const EigenArgs& a) {
  Scene scene = an::with_reduction(scenarios::load_scene(a.input),
                                   fc::ReductionFactors::following_k22(a.k11, a.k22));
  scenarios::apply_overrides(scene, a.range, kOption);
  auto out = a.claim(scene.output.file, "_eig.h5", scenarios::scene_inputs(scene));
  const auto r = scenarios::run_eigen(scene);
  fmt::print("ferrodyn critical-speed eigen: {} ({}), K11 = {}, K22 = {}\n", scene.name,
             scene.path, a.k11, a.k22);
  fmt::print("{}", scenarios::eigen_modes_report(scene, r, 16));
  scenarios::write_eigen_report(scene, r, out.write_path());
  out.file->commit();
  return a.finish(out.path());
}

using KijArgs = Analysis<an::KijStudyRequest>;

int do_kij(const KijArgs& a) {
  const Scene scene = scenarios::load_scene(a.input);
  auto out = a.claim(scene.output.file, "_kij.h5", scenarios::scene_inputs(scene));
  const auto study = an::run_kij_study(
      scene, a.request, [] { return InterruptGuard::stop_now(); },
      [](const an::KijRow& row, std::size_t done, std::size_t total) {
        fmt::print(stderr, "{}", an::kij_progress_line(row, done, total));
      },
      kOption);
  if (InterruptGuard::signal_received() != 0) return 128 + InterruptGuard::signal_received();
  fmt::print("{}", an::kij_study_report(scene, a.request, study));
  an::write_kij_study(scene, study.rows, out.write_path());
  out.file->commit();
  return a.finish(out.path());
}

struct SweepArgs : Analysis<an::SweepRequest> {
  bool quiet = false;
};

// mpirun (OpenMPI) and PMI launchers set these: a plain run stays a plain process.
bool launched_by_mpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr;
}

int do_sweep_ranked(const SweepArgs& args, an::SweepExecutor& ex) {
  const Scene scene = scenarios::load_scene(args.input);
  an::SweepRequest a = args.request;
  // Rank 0 writes the output: claimed before any point is computed, written as <file>.part.
  const std::string final_output =
      args.output.empty() ? scenarios::sibling(scene.output.file, "_sweep.h5") : args.output;
  std::optional<scenarios::ClaimedOutput> output;
  if (ex.rank() == 0) {
    output.emplace(final_output, args.output.empty() ? "output" : "-o", args.overwrite,
                   scenarios::scene_inputs(scene), args.no_plots);
  }
  a.output = output ? output->write_path() : final_output;
  a.journal = final_output + ".points";
  an::SweepCallbacks cb;
  cb.should_stop = [] { return InterruptGuard::stop_now(); };
  std::size_t todo = 0;
  cb.on_start = [&](std::size_t total, std::size_t finished, std::size_t mine) {
    todo = mine;
    if (ex.rank() == 0)
      fmt::print(stderr, "{}", an::sweep_start_line(total, finished, a.journal, ex.size(), a.jobs));
  };
  const auto wall0 = std::chrono::steady_clock::now();
  if (!args.quiet) {
    cb.on_done = [&](const an::SweepPointResult& r, std::size_t done) {
      const double el =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      fmt::print(stderr, "{}", an::sweep_point_line(ex.rank(), done, todo, el, r));
    };
  }
  const auto r = an::run_sweep(scene, a, ex, cb, kOption);
  const int sig = InterruptGuard::signal_received();
  if (!r.root) return sig != 0 ? 128 + sig : kExitOk;
  if (!r.complete) {
    fmt::print(stderr, "{}", an::sweep_stopped_line(r, a.journal));
    return sig != 0 ? 128 + sig : kExitRunFailure;
  }
  output->file->commit();
  a.output = final_output;
  fmt::print("{}", an::sweep_report(scene, a, r, ex.size()));
  return args.finish(final_output);
}

int do_sweep(const SweepArgs& a) {
  const auto ex = an::make_sweep_executor(launched_by_mpi());
  try {
    return do_sweep_ranked(a, *ex);
  } catch (const std::exception& e) {
    if (ex->size() > 1) {
      // Another rank may wait in a collective: take the job down with this rank's error.
      fmt::print(stderr, "ferrodyn: rank {}: {}\n", ex->rank(), e.what());
      ex->abort(kExitRunFailure);
    }
    throw;
  }
}

// The scene (or run file) argument, -o and --no-plots of an analysis verb.
template <class Args>
void add_common(CLI::App* c, Args& a, const char* input, const char* input_help,
                const char* output_default) {
  c->add_option(input, a.input, input_help)->required();
  add_output_option(c, a.output, std::string("HDF5 output (default: ") + output_default + ")");
  add_no_plots_flag(c, a.no_plots);
  add_overwrite_flag(c, a.overwrite);
}

}  // namespace

void add_analysis_commands(CLI::App& app, VerbHandler& handler) {
  const char* scene = "Scene YAML file";
  auto d = std::make_shared<AssessArgs>();
  auto* as = app.add_subcommand(
      "assess",
      "Assessment of a run as EN 14363 / UIC 518 / EN 12299 define it: running safety, track "
      "loading, stability, ride; table, HDF5 and plots along the track");
  add_common(as, *d, "run", "HDF5 output of `ferrodyn run` (vehicle scene)",
             "<run>_assessment.h5");
  add_parameters(as, an::parameters(d->request));
  as->get_option("--mu")->check(number_in(0.0, 2.0, false, true, ""));
  as->get_option("--flange-angle-deg")->check(number_in(0.0, 90.0, true, true, "deg"));
  as->get_option("--section-length")->check(number_in(0.0, INFINITY, true, true, "m"));
  as->get_option("--f0")->check(number_in(0.0, INFINITY, true, true, "Hz"));
  as->get_option("--floor-offset")->check(number_in(0.0, INFINITY, false, true, "m"));
  as->get_option("--y-over-q-limit")->check(number_in(0.0, INFINITY, true, true, ""));
  as->add_flag("--all", d->all_rows, "Print every section's row (default: the worst per item)");
  on_parsed(as, handler, d, do_assess);

  auto* cs = app.add_subcommand("critical-speed", "Critical speed: ramp, bifurcation, eigen");
  cs->require_subcommand(1);
  auto r = std::make_shared<RampArgs>();
  auto* ramp = cs->add_subcommand("ramp", "Decelerating run after a lateral disturbance");
  add_common(ramp, *r, "scene", scene, "<output.file stem>_ramp.h5");
  add_parameters(ramp, an::parameters(r->request));
  on_parsed(ramp, handler, r, do_ramp);

  auto b = std::make_shared<BranchArgs>();
  auto* bif = cs->add_subcommand(
      "bifurcation", "Limit-cycle amplitudes followed down the periodic branch to the fold");
  add_common(bif, *b, "scene", scene, "<output.file stem>_bifurcation.h5");
  add_parameters(bif, an::parameters(b->request));
  on_parsed(bif, handler, b, do_branch);

  auto e = std::make_shared<EigenArgs>();
  auto* eig = cs->add_subcommand("eigen", "Linear eigenvalues against speed: the Hopf speed");
  add_common(eig, *e, "scene", scene, "<output.file stem>_eig.h5");
  add_parameters(eig, scenarios::select_parameters(scenarios::parameters(e->range),
                                                   {"speed_min", "speed_max", "points"}));
  eig->get_option("--points")->check(count_in(2, scenarios::kMaxEigenPoints));
  eig->add_option("--k11", e->k11, "Reduction factor on C11")->capture_default_str();
  eig->add_option("--k22", e->k22, "Reduction factor on C22")->capture_default_str();
  on_parsed(eig, handler, e, do_eigen);

  auto k = std::make_shared<KijArgs>();
  auto* kij = app.add_subcommand(
      "kij-study", "Nonlinear critical speed against Kalker reduction factors (Table 4.1 layout)");
  add_common(kij, *k, "scene", scene, "<output.file stem>_kij.h5");
  add_parameters(kij, an::parameters(k->request));
  kij->get_option("--jobs")->check(count_in(1, kMaxJobs));
  on_parsed(kij, handler, k, do_kij);

  auto s = std::make_shared<SweepArgs>();
  auto* sw = app.add_subcommand(
      "sweep", "Independent constant-speed runs over speeds x reduction factors, on threads and "
               "MPI ranks, resumable");
  add_common(sw, *s, "scene", scene,
             "<output.file stem>_sweep.h5; finished points are kept in <output>.points/ until "
             "the sweep completes");
  add_parameters(sw, an::parameters(s->request));
  sw->get_option("--points")->check(count_in(1, scenarios::kMaxEigenPoints));
  sw->get_option("--jobs")->check(count_in(1, kMaxJobs));
  sw->get_option("--max-new-points")->check(count_in(0, std::numeric_limits<int>::max()));
  sw->add_flag("-q,--quiet", s->quiet, "No progress display");
  on_parsed(sw, handler, s, do_sweep);
}

}  // namespace ferro::cli
