// Verbs of the analyses: assessment of a run (EN 14363 / UIC 518 / EN 12299), eigenvalues
// against speed (eig), critical speed (ramp, bifurcation, eigen), reduction-factor studies and
// parallel sweeps (threads and, when built with it, MPI).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <memory>

#include "cli.hpp"
#include "ferro/scenarios/claimed_output.hpp"
#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/assessment.hpp"
#include "ferro/scenarios/analysis/output.hpp"
#include "ferro/scenarios/analysis/progress_text.hpp"
#include "ferro/scenarios/analysis/report.hpp"
#include "ferro/scenarios/analysis/studies.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/report.hpp"
#include "ferro/scenarios/run.hpp"
#include "plotting.hpp"
#include "terminal.hpp"

namespace ferro::cli {
namespace {

namespace an = scenarios::analysis;
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
    return scenarios::ClaimedOutput::given_or(output, scenarios::sibling(beside, suffix),
                                              overwrite, std::move(inputs), no_plots);
  }
  /// After the report: the output file's name and its plots (ferroplot.py `mode`); returns the
  /// verb's exit code (`code` unless a stop request ended the plotting).
  [[nodiscard]] int finish(const std::string& out, int code = kExitOk,
                           const char* mode = "auto") const {
    fmt::print("  output    {}\n", out);
    return no_plots ? code : plot_after_report(mode, out, {}, {}, code);
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
  const an::AssessmentOptions o = an::assessment_options(a.request, kOption);
  auto out = a.claim(a.input, "_assessment.h5", {a.input});
  const auto r = an::assess_run(a.input, o);
  fmt::print("{}", an::assessment_report(a.input, r, a.all_rows));
  an::write_assessment(r, a.input, out.write_path());
  return a.finish(out.commit());  // the verdict is a result, not a failure of the assessment
}

using RampArgs = Analysis<an::RampRequest>;

int do_ramp(const RampArgs& a) {
  const Scene scene = scenarios::load_scene(a.input);
  auto out = a.claim(scene.output.file, "_ramp.h5", scenarios::scene_inputs(scene));
  const auto study = an::run_ramp(scene, a.request, kOption);
  fmt::print("{}", an::ramp_report(study, a.request));
  an::write_ramp(study.scene, study.result, study.options, study.observed, out.write_path());
  const int code = a.finish(out.commit(), study.result.completed ? kExitOk : kExitRunFailure);
  if (!study.result.completed) {
    std::fflush(stdout);
    fmt::print(stderr, "ferrodyn: failure: the ramp stopped before its end: {}\n",
               study.result.message);
  }
  return code;
}

using BranchArgs = Analysis<an::BranchRequest>;

int do_branch(const BranchArgs& a) {
  const Scene scene = scenarios::load_scene(a.input);
  fmt::print("{}", an::branch_heading(scene, a.request));
  std::vector<std::string> names;
  const auto k = a.request.settle.reduction();
  auto out =
      a.claim(scene.output.file, "_bifurcation.h5", scenarios::scene_inputs(scene));
  const auto row = an::run_bifurcation(
      scene, a.request, k, &names,
      [&](const an::BranchPoint& p) { fmt::print(stderr, "{}", an::branch_progress_line(k, names, p)); },
      kOption);
  fmt::print("{}", an::branch_report(row, names));
  an::write_branch(an::with_reduction(scene, row.k), row.branch, names, row.hopf_speed,
                   out.write_path());
  return a.finish(out.commit());
}

using EigenArgs = Analysis<an::EigenRequest>;

int do_eigen(const EigenArgs& a) {
  const Scene scene = an::eigen_study_scene(scenarios::load_scene(a.input), a.request, kOption);
  auto out = a.claim(scene.output.file, "_eig.h5", scenarios::scene_inputs(scene));
  const auto r = scenarios::run_eigen(scene);
  fmt::print("{}", an::eigen_study_report(scene, a.request, r));
  scenarios::write_eigen_report(scene, r, out.write_path());
  return a.finish(out.commit());
}

// `ferrodyn eig`: the scene's own eigenvalue sweep, with run-time overrides.
using EigArgs = Analysis<scenarios::RunOverrides>;

int do_eig(const EigArgs& a) {
  Scene scene = scenarios::load_scene(a.input);
  scenarios::apply_overrides(scene, a.request, kOption);
  // The output is claimed before the sweep: a path that would be refused is refused now.
  auto out = a.claim(scene.output.file, "_eig.h5", scenarios::scene_inputs(scene));
  const auto r = scenarios::run_eigen(scene);
  fmt::print("{}", scenarios::eigen_sweep_report(scene, r));
  scenarios::write_eigen_report(scene, r, out.write_path());
  return a.finish(out.commit(), kExitOk, "eigen");
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
  return a.finish(out.commit());
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
  an::SweepFiles files = an::claim_sweep_files(scene, args.output, args.overwrite,
                                               args.no_plots, ex.rank() == 0, a);
  an::SweepCallbacks cb;
  cb.should_stop = [] { return InterruptGuard::stop_now(); };
  cb.progress = [](const std::string& text) { fmt::print(stderr, "{}", text); };
  cb.quiet = args.quiet;
  const auto r = an::run_sweep(scene, a, ex, cb, kOption);
  const int sig = InterruptGuard::signal_received();
  if (!r.root) return sig != 0 ? 128 + sig : kExitOk;
  if (!r.complete) return kExitRunFailure;  // run_main: 128 + signal when a stop ended it
  a.output = files.claimed->commit();
  fmt::print("{}", an::sweep_report(scene, a, r, ex.size()));
  return args.finish(a.output);
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
  add_output_option(c, a.output, std::string("HDF5 output (default: ") + output_default + ")");
  add_no_plots_flag(c, a.no_plots);
  add_overwrite_flag(c, a.overwrite);
  c->add_option(input, a.input, input_help)->required();  // its checks after the options'
}

}  // namespace

void add_analysis_commands(CLI::App& app, VerbHandler& handler) {
  const char* scene = "Scene YAML file";
  auto [as, d] = add_verb<AssessArgs>(
      &app, handler, do_assess, "assess",
      "Assessment of a run as EN 14363 / UIC 518 / EN 12299 define it: running safety, track "
      "loading, stability, ride; table, HDF5 and plots along the track");
  add_parameters(as, an::parameters(d->request));  // checked before the run file's existence
  add_common(as, *d, "run", "HDF5 output of `ferrodyn run` (vehicle scene)",
             "<run>_assessment.h5");
  as->get_option("run")->check(CLI::ExistingFile);
  as->add_flag("--all", d->all_rows, "Print every section's row (default: the worst per item)");

  auto* cs = app.add_subcommand("critical-speed", "Critical speed: ramp, bifurcation, eigen");
  cs->require_subcommand(1);
  auto [ramp, r] = add_verb<RampArgs>(cs, handler, do_ramp, "ramp",
                                      "Decelerating run after a lateral disturbance");
  add_common(ramp, *r, "scene", scene, "<output.file stem>_ramp.h5");
  add_parameters(ramp, an::parameters(r->request));

  auto [bif, b] = add_verb<BranchArgs>(
      cs, handler, do_branch, "bifurcation",
      "Limit-cycle amplitudes followed down the periodic branch to the fold");
  add_common(bif, *b, "scene", scene, "<output.file stem>_bifurcation.h5");
  add_parameters(bif, an::parameters(b->request));

  auto [eig, e] = add_verb<EigenArgs>(cs, handler, do_eigen, "eigen",
                                      "Linear eigenvalues against speed: the Hopf speed");
  add_common(eig, *e, "scene", scene, "<output.file stem>_eig.h5");
  add_parameters(eig, an::parameters(e->request));

  auto [scene_eig, g] = add_verb<EigArgs>(
      &app, handler, do_eig, "eig", "Linear eigenvalue analysis over a speed range; critical speed");
  add_common(scene_eig, *g, "scene", scene, "<output.file stem>_eig.h5");
  add_parameters(scene_eig,
                 scenarios::select_parameters(scenarios::parameters(g->request),
                                              {"speed_min", "speed_max", "points", "tangential"}));

  auto [kij, k] = add_verb<KijArgs>(
      &app, handler, do_kij, "kij-study",
      "Nonlinear critical speed against Kalker reduction factors (Table 4.1 layout)");
  add_common(kij, *k, "scene", scene, "<output.file stem>_kij.h5");
  add_parameters(kij, an::parameters(k->request));

  auto [sw, s] = add_verb<SweepArgs>(
      &app, handler, do_sweep, "sweep",
      "Independent constant-speed runs over speeds x reduction factors, on threads and MPI "
      "ranks, resumable");
  add_common(sw, *s, "scene", scene,
             "<output.file stem>_sweep.h5; finished points are kept in <output>.points/ until "
             "the sweep completes");
  add_parameters(sw, an::parameters(s->request));
  sw->add_flag("-q,--quiet", s->quiet, "No progress display");
}

}  // namespace ferro::cli
