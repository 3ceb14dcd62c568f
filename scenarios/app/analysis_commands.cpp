// Verbs of the analyses: derailment assessment of a run, critical speed (ramp, bifurcation,
// eigen), reduction-factor studies and parallel sweeps (threads and, when built with it, MPI).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>

#include "cli.hpp"
#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/derailment.hpp"
#include "ferro/scenarios/analysis/output.hpp"
#include "ferro/scenarios/analysis/report.hpp"
#include "ferro/scenarios/analysis/studies.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/run.hpp"
#include "plotting.hpp"
#include "terminal.hpp"


namespace ferro::cli {
namespace {

namespace fs = std::filesystem;
namespace an = scenarios::analysis;
using scenarios::Scene;
constexpr scenarios::Spelling kOption = scenarios::Spelling::option;

void plot(const std::string& h5, bool no_plots) {
  if (!no_plots) plot_after_report("auto", h5);
}

// ---------------------------------------------------------------- derailment
struct DerailArgs {
  std::string file, output;
  an::DerailmentRequest request;
  bool no_plots = false;
};

int do_derailment(const DerailArgs& a) {
  if (!fs::exists(a.file))
    throw std::invalid_argument(fmt::format("derailment: no such file '{}'", a.file));
  const an::DerailmentOptions o = an::derailment_options(a.request, kOption);
  const auto r = an::assess_derailment_file(a.file, o);
  fmt::print("{}", an::derailment_report(a.file, o, r));
  const std::string out = a.output.empty() ? sibling(a.file, "_derailment.h5") : a.output;
  an::write_derailment_report(r, a.file, out);
  fmt::print("  output    {}\n", out);
  plot(out, a.no_plots);
  return kExitOk;  // the verdict is a result, not a failure of the assessment
}

// ---------------------------------------------------------------- settle options
void add_settle_options(CLI::App* c, an::SettleRequest& s) {
  c->add_option("--disturbance", s.disturbance,
                "Lateral offset added to the leading wheelset at the start [m]")->capture_default_str();
  c->add_option("--segment", s.segment, "Simulated time per convergence check [s]")->capture_default_str();
  c->add_option("--t-max", s.t_max, "Simulated time limit per speed [s]")->capture_default_str();
  c->add_option("--output-interval", s.output_interval, "Sampling of the lateral states [s]")->capture_default_str();
  c->add_option("--zero-amplitude", s.zero_amplitude, "Below: oscillation decayed [m]")->capture_default_str();
  c->add_option("--max-amplitude", s.max_amplitude, "Above: diverged [m]")->capture_default_str();
  c->add_option("--periods", s.periods, "Periods the steady amplitude is measured over")->capture_default_str();
  c->add_option("--rel-tol", s.rel_tol, "Relative amplitude change that counts as settled")->capture_default_str();
  c->add_option("--k11", s.k11, "Reduction factor on C11")->capture_default_str();
  c->add_option("--k22", s.k22, "Reduction factor on C22")->capture_default_str();
}

// ---------------------------------------------------------------- ramp
struct RampArgs {
  std::string scene, output;
  an::RampRequest request;
  bool no_plots = false;
};

int do_ramp(const RampArgs& a) {
  const auto study = an::run_ramp(scenarios::load_scene(a.scene), a.request, kOption);
  const Scene& scene = study.scene;
  const auto& o = study.options;
  const auto& r = study.result;
  fmt::print("{}", an::ramp_report(study, a.request));
  const std::string out = a.output.empty() ? sibling(scene.output.file, "_ramp.h5") : a.output;
  an::write_ramp(scene, r, o, study.observed, out);
  fmt::print("  output    {}\n", out);
  plot(out, a.no_plots);
  return r.completed ? kExitOk : kExitRunFailure;
}

// ---------------------------------------------------------------- bifurcation
struct BranchArgs {
  std::string scene, output;
  an::BranchRequest request;
  bool no_plots = false;
};

// Progress of the branch of factors k, on stderr.
std::function<void(const an::BranchPoint&)> branch_progress(const an::Reduction& k) {
  return [k](const an::BranchPoint& p) {
    const auto& fit = p.run.fit;
    const std::string growth =
        fit.valid() ? fmt::format(" (sigma = {:.3g} +- {:.2g} /s, beta = {:.3g} /(s mm^2))",
                                  fit.sigma, fit.sigma_error, fit.beta * 1e-6)
                    : std::string();
    fmt::print(stderr, "progress: K = ({}, {}) V = {:.4f} m/s{}: {} {:.4f} mm after {:.1f} s{}\n",
               k.k11, k.k22, p.speed, p.bisection ? " (bisection)" : "",
               an::to_string(p.run.outcome), p.run.amplitude.front() * 1e3, p.run.time, growth);
  };
}

int do_branch(const BranchArgs& a) {
  const Scene scene = scenarios::load_scene(a.scene);
  const an::SettleRequest& settle = a.request.settle;
  fmt::print("ferrodyn critical-speed bifurcation: {} ({}), K11 = {}, K22 = {}\n", scene.name,
             scene.path, settle.k11, settle.k22);
  std::vector<std::string> names;
  const an::Reduction k{settle.k11, settle.k22};
  const auto row = an::run_bifurcation(scene, a.request, k, &names, branch_progress(k), kOption);
  fmt::print("{}", an::branch_report(row, names));
  const Scene reduced = an::with_reduction(scene, row.k);
  const std::string out =
      a.output.empty() ? sibling(scene.output.file, "_bifurcation.h5") : a.output;
  an::write_branch(reduced, row.branch, names, row.hopf_speed, out);
  fmt::print("  output    {}\n", out);
  plot(out, a.no_plots);
  return kExitOk;
}

// ---------------------------------------------------------------- eigen
// The verb's own range, whatever the scene's analysis.eigen says.
scenarios::RunOverrides eigen_range_defaults() {
  scenarios::RunOverrides r;
  r.speed_min = 1.0;
  r.speed_max = 150.0;
  r.points = 150;
  return r;
}

struct EigenArgs {
  std::string scene, output;
  double k11 = 1.0, k22 = 1.0;
  scenarios::RunOverrides range = eigen_range_defaults();
  bool no_plots = false;
};

int do_eigen(const EigenArgs& a) {
  Scene scene = an::with_reduction(scenarios::load_scene(a.scene), {a.k11, a.k22});
  scenarios::apply_overrides(scene, a.range, kOption);
  const auto r = scenarios::run_eigen(scene);
  fmt::print("ferrodyn critical-speed eigen: {} ({}), K11 = {}, K22 = {}\n", scene.name,
             scene.path, a.k11, a.k22);
  if (r.critical_speed) {
    fmt::print("  Hopf speed (least damped mode crosses zero): {:.4f} m/s = {:.2f} km/h\n",
               *r.critical_speed, *r.critical_speed * 3.6);
  } else {
    fmt::print("  no eigenvalue crossing in [{}, {}] m/s\n", scene.eigen.speed_min,
               scene.eigen.speed_max);
  }
  const std::string out = a.output.empty() ? sibling(scene.output.file, "_eig.h5") : a.output;
  scenarios::write_eigen_report(scene, r, out);
  fmt::print("  output    {}\n", out);
  plot(out, a.no_plots);
  return kExitOk;
}

// ---------------------------------------------------------------- K_ij study
struct KijArgs {
  std::string scene, output;
  an::KijStudyRequest request;
  bool no_plots = false;
};

int do_kij(const KijArgs& a) {
  const Scene scene = scenarios::load_scene(a.scene);
  InterruptGuard guard;
  const auto study = an::run_kij_study(
      scene, a.request, [] { return InterruptGuard::signal_received() != 0; },
      [](const an::KijRow& row, std::size_t done, std::size_t total) {
        fmt::print(stderr, "progress: K11 = {}, K22 = {} done ({}/{})\n", row.k.k11, row.k.k22,
                   done, total);
      },
      kOption);
  if (InterruptGuard::signal_received() != 0) return 128 + InterruptGuard::signal_received();
  const auto& rows = study.rows;
  fmt::print("{}", an::kij_study_report(scene, a.request, study));
  const std::string out = a.output.empty() ? sibling(scene.output.file, "_kij.h5") : a.output;
  an::write_kij_study(scene, rows, out);
  fmt::print("  output    {}\n", out);
  plot(out, a.no_plots);
  return kExitOk;
}

// ---------------------------------------------------------------- sweep
struct SweepArgs {
  std::string scene;
  an::SweepRequest request;
  bool quiet = false, no_plots = false;
};

// mpirun (OpenMPI) and PMI launchers set these: a plain run stays a plain process.
bool launched_by_mpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr;
}

int report_sweep(const Scene& scene, const an::SweepRequest& a, const an::SweepOutcome& r,
                 int ranks, bool no_plots) {
  fmt::print("{}", an::sweep_report(scene, a, r, ranks));
  fmt::print("  output    {}\n", a.output);
  plot(a.output, no_plots);
  return kExitOk;
}

int do_sweep_ranked(const SweepArgs& args, an::SweepExecutor& ex) {
  const Scene scene = scenarios::load_scene(args.scene);
  an::SweepRequest a = args.request;
  if (a.output.empty()) a.output = sibling(scene.output.file, "_sweep.h5");
  a.journal = a.output + ".points";
  InterruptGuard guard;
  an::SweepCallbacks cb;
  cb.should_stop = [] { return InterruptGuard::signal_received() != 0; };
  std::size_t todo = 0;
  cb.on_start = [&](std::size_t total, std::size_t finished, std::size_t mine) {
    todo = mine;
    if (ex.rank() != 0) return;
    fmt::print(stderr, "ferrodyn sweep: {} points ({} already finished in {}), {} rank(s) x {} "
               "thread(s)\n",
               total, finished, a.journal, ex.size(), a.jobs);
  };
  const auto wall0 = std::chrono::steady_clock::now();
  if (!args.quiet) {
    cb.on_done = [&](const an::SweepPointResult& r, std::size_t done) {
      const double el =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      fmt::print(stderr, "[rank {} {:>4}/{:<4} {:6.1f} s] V = {:8.4f} m/s K = ({:.3f}, {:.3f}): {} "
                 "{:.4f} mm\n",
                 ex.rank(), done, todo, el, r.point.speed, r.point.k.k11, r.point.k.k22,
                 an::to_string(r.outcome), r.amplitude.empty() ? NAN : r.amplitude.front() * 1e3);
    };
  }
  const auto r = an::run_sweep(scene, a, ex, cb, kOption);
  const int sig = InterruptGuard::signal_received();
  if (!r.root) return sig != 0 ? 128 + sig : kExitOk;
  if (!r.complete) {
    fmt::print(stderr,
               "ferrodyn sweep: stopped with {} of {} points finished (recorded in {}); run the "
               "same command again to resume\n",
               r.finished, r.total, a.journal);
    return sig != 0 ? 128 + sig : kExitRunFailure;
  }
  return report_sweep(scene, a, r, ex.size(), args.no_plots);
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

// --no-hopf clears `hopf`.
void add_no_hopf_flag(CLI::App* c, bool& hopf) {
  c->add_flag_function(
      "--no-hopf", [&hopf](std::int64_t) { hopf = false; }, "Skip the eigenvalue (Hopf) speed");
}

void add_k_options(CLI::App* c, std::vector<double>& k, std::string& coefficient) {
  c->add_option("--k", k, "Reduction factors (one run per value)")->delimiter(',');
  c->add_option("--coefficient", coefficient, "Which factor --k sets: both (K11 = K22 = K23 = K33), k11, k22")->capture_default_str();
}

}  // namespace

void add_analysis_commands(CLI::App& app, VerbHandler& handler) {
  auto d = std::make_shared<DerailArgs>();
  auto* der = app.add_subcommand(
      "derailment", "Derailment assessment of a run: Y/Q (2 m mean), Nadal, sum Y, dQ/Q0, plot");
  der->add_option("run", d->file, "HDF5 output of `ferrodyn run`")->required();
  der->add_option("--mu", d->request.mu, "Friction coefficient in Nadal's formula")->capture_default_str();
  der->add_option("--flange-angle-deg", d->request.flange_angle_deg,
                  "Flange angle [deg] (default: largest contact angle of each wheel)");
  der->add_option("--q0", d->request.q0, "Static wheel load Q0 [N] (default: first sample)");
  der->add_option("--window", d->request.window, "Sliding-mean window [m]")->capture_default_str();
  der->add_option("--step", d->request.step, "Sliding-mean sampling step [m]")->capture_default_str();
  der->add_option("-o,--output", d->output, "Report file (default: <run>_derailment.h5)");
  der->add_flag("--no-plots", d->no_plots, "Do not draw plots");
  der->callback([&handler, d] { handler = [d] { return do_derailment(*d); }; });

  auto* cs = app.add_subcommand("critical-speed", "Critical speed: ramp, bifurcation, eigen");
  cs->require_subcommand(1);

  auto r = std::make_shared<RampArgs>();
  auto* ramp = cs->add_subcommand("ramp", "Decelerating run after a lateral disturbance");
  ramp->add_option("scene", r->scene, "Scene YAML file")->required();
  ramp->add_option("--speed-initial", r->request.speed_initial, "Start speed [m/s]")->capture_default_str();
  ramp->add_option("--deceleration", r->request.deceleration, "[m/s^2]")->capture_default_str();
  ramp->add_option("--speed-final", r->request.speed_final, "End speed [m/s] (default: 0.1 x start)");
  ramp->add_option("--hold", r->request.hold, "Constant-speed piece duration [s]")->capture_default_str();
  ramp->add_option("--threshold", r->request.threshold, "Envelope below which the oscillation died [m]")
      ->capture_default_str();
  ramp->add_option("--max-amplitude", r->request.max_amplitude, "Stop as diverged above this [m]")
      ->capture_default_str();
  ramp->add_option("--envelope-window", r->request.envelope_window, "Envelope trailing window [s]")->capture_default_str();
  ramp->add_option("--output-interval", r->request.output_interval, "Sampling [s]")->capture_default_str();
  ramp->add_option("--disturbance", r->request.disturbance, "Initial lateral offset [m]")->capture_default_str();
  ramp->add_option("--k11", r->request.k11, "Reduction factor on C11")->capture_default_str();
  ramp->add_option("--k22", r->request.k22, "Reduction factor on C22")->capture_default_str();
  ramp->add_option("-o,--output", r->output, "HDF5 output (default: <output.file stem>_ramp.h5)");
  ramp->add_flag("--no-plots", r->no_plots, "Do not draw plots");
  ramp->callback([&handler, r] { handler = [r] { return do_ramp(*r); }; });

  auto b = std::make_shared<BranchArgs>();
  auto* bif = cs->add_subcommand(
      "bifurcation", "Limit-cycle amplitudes followed down the periodic branch to the fold");
  bif->add_option("scene", b->scene, "Scene YAML file")->required();
  bif->add_option("--speed-max", b->request.speed_max, "First (highest) speed [m/s]")->required();
  bif->add_option("--speed-min", b->request.speed_min, "Lowest speed followed [m/s]")->required();
  bif->add_option("--step", b->request.step, "Downward speed step [m/s]")->capture_default_str();
  bif->add_option("--bracket", b->request.bracket, "Fold bracket width [m/s]")->capture_default_str();
  add_settle_options(bif, b->request.settle);
  bif->add_option("-o,--output", b->output,
                  "HDF5 output (default: <output.file stem>_bifurcation.h5)");
  add_no_hopf_flag(bif, b->request.hopf);
  bif->add_flag("--no-plots", b->no_plots, "Do not draw plots");
  bif->callback([&handler, b] { handler = [b] { return do_branch(*b); }; });

  auto e = std::make_shared<EigenArgs>();
  auto* eig = cs->add_subcommand("eigen", "Linear eigenvalues against speed: the Hopf speed");
  eig->add_option("scene", e->scene, "Scene YAML file")->required();
  eig->add_option("--speed-min", e->range.speed_min, "[m/s]")->capture_default_str();
  eig->add_option("--speed-max", e->range.speed_max, "[m/s]")->capture_default_str();
  eig->add_option("--points", e->range.points, "Speeds in the sweep")->capture_default_str();
  eig->add_option("--k11", e->k11, "Reduction factor on C11")->capture_default_str();
  eig->add_option("--k22", e->k22, "Reduction factor on C22")->capture_default_str();
  eig->add_option("-o,--output", e->output, "HDF5 output (default: <output.file stem>_eig.h5)");
  eig->add_flag("--no-plots", e->no_plots, "Do not draw plots");
  eig->callback([&handler, e] { handler = [e] { return do_eigen(*e); }; });

  auto k = std::make_shared<KijArgs>();
  auto* kij = app.add_subcommand(
      "kij-study", "Nonlinear critical speed against Kalker reduction factors (Table 4.1 layout)");
  kij->add_option("scene", k->scene, "Scene YAML file")->required();
  add_k_options(kij, k->request.k, k->request.coefficient);
  kij->add_option("--speed-max", k->request.branch.speed_max, "First (highest) speed [m/s]")->required();
  kij->add_option("--speed-min", k->request.branch.speed_min, "Lowest speed followed [m/s]")->required();
  kij->add_option("--step", k->request.branch.step, "Downward speed step [m/s]")->capture_default_str();
  kij->add_option("--bracket", k->request.branch.bracket, "Fold bracket width [m/s]")->capture_default_str();
  add_settle_options(kij, k->request.branch.settle);
  kij->add_option("-j,--jobs", k->request.jobs, "Worker threads (one K per thread)")->capture_default_str();
  kij->add_option("-o,--output", k->output, "HDF5 output (default: <stem>_kij.h5)");
  add_no_hopf_flag(kij, k->request.branch.hopf);
  kij->add_flag("--no-plots", k->no_plots, "Do not draw plots");
  kij->callback([&handler, k] { handler = [k] { return do_kij(*k); }; });

  auto s = std::make_shared<SweepArgs>();
  auto* sw = app.add_subcommand(
      "sweep", "Independent constant-speed runs over speeds x reduction factors, on threads and "
               "MPI ranks, resumable");
  sw->add_option("scene", s->scene, "Scene YAML file")->required();
  sw->add_option("--speed-min", s->request.speed_min, "[m/s]")->required();
  sw->add_option("--speed-max", s->request.speed_max, "[m/s]")->required();
  sw->add_option("--points", s->request.points, "Speeds between min and max")->capture_default_str();
  add_k_options(sw, s->request.k, s->request.coefficient);
  add_settle_options(sw, s->request.settle);
  sw->add_option("-j,--jobs", s->request.jobs, "Worker threads per process")->capture_default_str();
  sw->add_option("-o,--output", s->request.output,
                 "HDF5 output (default: <output.file stem>_sweep.h5); finished points are kept "
                 "in <output>.points/ until the sweep completes");
  sw->add_option("--max-new-points", s->request.max_new_points,
                 "Compute at most this many new points per process, then stop (resumable; for "
                 "batch-queue time limits)");
  sw->add_flag("--restart", s->request.restart, "Forget finished points and start over");
  sw->add_flag("-q,--quiet", s->quiet, "No progress display");
  sw->add_flag("--no-plots", s->no_plots, "Do not draw plots");
  sw->callback([&handler, s] { handler = [s] { return do_sweep(*s); }; });
}

}  // namespace ferro::cli
