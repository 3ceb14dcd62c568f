// Verbs on scenes and run outputs: run, eig, plot, validate.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <memory>

#include "cli.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/plotting.hpp"
#include "ferro/scenarios/run.hpp"
#include "ferro/scenarios/scene.hpp"
#include "terminal.hpp"

namespace ferro::cli {
namespace {

namespace fs = std::filesystem;
using scenarios::Scene;

struct RunArgs {
  std::string scene, output, plot_dir, integrator, tangential, normal;
  std::vector<std::string> csv;
  double t_end = NAN, speed = NAN, pace = 0.0, rtol = NAN, atol = NAN, fixed_step = NAN;
  bool no_plots = false, quiet = false, overwrite = false;
};

struct EigArgs {
  std::string scene, output, tangential;
  double speed_min = NAN, speed_max = NAN;
  int points = 0;  // 0: the scene's
  bool no_plots = false, overwrite = false;
};

struct PlotArgs {
  std::string file, out_dir, format = "png,svg";
  std::vector<std::string> signals;
};

std::string default_plot_dir(const std::string& h5) {
  fs::path p(h5);
  return (p.parent_path() / (p.stem().string() + "_plots")).string();
}

int make_plots(const std::string& mode, const std::string& h5,
               const std::vector<std::string>& signals, const std::string& out_dir,
               const std::string& format) {
  std::vector<std::string> args = {mode, h5, "--out", out_dir, "--format", format};
  if (!signals.empty()) {
    args.emplace_back("--signals");
    args.insert(args.end(), signals.begin(), signals.end());
  }
  return scenarios::run_python_tool("ferroplot.py", args, [] { return InterruptGuard::stop_now(); });
}

// After make_plots() of a verb's results: prints where the plots are, or why there are none.
// Returns the verb's exit code: an interruption ends the verb, a plotting failure does not (the
// results are complete).
int report_plots(int rc, const std::string& dir, const std::string& results) {
  if (rc == scenarios::kProgramStopped) return 128 + InterruptGuard::signal_received();
  if (rc == 0) {
    fmt::print("  plots     {}/\n", dir);
  } else if (rc == kPlotsNeedPython) {
    fmt::print(stderr,
               "ferrodyn: warning: no plots: python3 with matplotlib and h5py needed; the "
               "results in {} are complete\n",
               results);
  } else {
    fmt::print(stderr,
               "ferrodyn: warning: plotting failed (exit status {}, see above); the results in {} "
               "are complete\n",
               rc, results);
  }
  return kExitOk;
}

}  // namespace

void apply_run_overrides(Scene& scene, double t_end, double speed, const std::string& tangential) {
  if (!std::isnan(t_end)) {
    if (!(t_end > 0.0) || !std::isfinite(t_end))
      throw std::invalid_argument(fmt::format("--t-end: must be a finite number > 0 s, got {}", t_end));
    scene.simulation.t_end = t_end;
    (void)scenarios::output_sample_count(t_end, scene.output.interval, "--t-end");
  }
  if (!std::isnan(speed)) {
    // A vehicle may stand still (the creep forces then vanish); the linear wheelset's
    // equations divide by the speed.
    const bool vehicle = scene.model.type == "vehicle";
    if (!std::isfinite(speed) || (vehicle ? !(speed >= 0.0) : !(speed > 0.0))) {
      throw std::invalid_argument(fmt::format("--speed: must be a finite number {} m/s for {} "
                                              "scenes, got {}",
                                              vehicle ? ">= 0" : "> 0", scene.model.type, speed));
    }
    scene.simulation.speed = speed;
  }
  if (!tangential.empty()) {
    scenarios::override_tangential(scene, tangential, "--tangential",
                                   with_environment_options(tangential));
  }
  if (!std::isnan(t_end) || !std::isnan(speed)) {
    const std::string problem = scenarios::track_extent_problem(scene, scene.simulation.t_end);
    if (!problem.empty()) {
      throw std::invalid_argument(
          fmt::format("{}: {}", !std::isnan(t_end) ? "--t-end" : "--speed", problem));
    }
  }
}

namespace {

int do_run(const RunArgs& a) {
  Scene scene = scenarios::load_scene(a.scene);
  apply_run_overrides(scene, a.t_end, a.speed, a.tangential);
  if (!a.normal.empty()) scenarios::override_normal(scene, a.normal, "--normal");
  if (!a.integrator.empty()) {
    scene.solver.method = a.integrator;
    // A scene's fixed step belongs to its explicit or implicit Runge-Kutta method: another
    // method given here runs with its error control (--fixed-step sets a step explicitly).
    if (std::isnan(a.fixed_step) && !vehicle::takes_fixed_step(a.integrator))
      scene.solver.fixed_step = 0.0;
  }
  if (!std::isnan(a.fixed_step)) {
    if (!(a.fixed_step >= 0.0) || !std::isfinite(a.fixed_step))
      throw std::invalid_argument(fmt::format(
          "--fixed-step: must be >= 0 s (0: adaptive steps), got {}", a.fixed_step));
    if (a.fixed_step > 0.0 && !vehicle::takes_fixed_step(scene.solver.method))
      throw std::invalid_argument(fmt::format(
          "--fixed-step: only arkode_erk, arkode_dirk, odeint_bs3 and bdf2 take a fixed step; {} "
          "needs 0, got {}",
          scene.solver.method, a.fixed_step));
    scene.solver.fixed_step = a.fixed_step;
  }
  if (!a.integrator.empty() || !std::isnan(a.fixed_step)) {
    scene.solver.validate(!a.integrator.empty() ? "--integrator" : "--fixed-step");
  }
  if (!std::isnan(a.rtol)) {
    if (!(a.rtol > 0.0 && a.rtol < 1.0))
      throw std::invalid_argument(fmt::format("--rtol: must lie in (0, 1), got {}", a.rtol));
    scene.solver.rtol = a.rtol;
  }
  if (!std::isnan(a.atol)) {
    if (!(a.atol > 0.0) || !std::isfinite(a.atol))
      throw std::invalid_argument(fmt::format("--atol: must be finite and > 0, got {}", a.atol));
    scene.solver.atol = a.atol;
  }
  scenarios::RunOptions opt;
  opt.output_file = a.output;
  opt.overwrite = a.overwrite;
  if (!(a.pace >= 0.0))
    throw std::invalid_argument(fmt::format("--pace: must be >= 0, got {}", a.pace));
  opt.pace = a.pace;
  if (!a.csv.empty()) opt.csv = a.csv;
  const std::string output = a.output.empty() ? scene.output.file : a.output;
  const std::string plot_dir = a.plot_dir.empty() ? default_plot_dir(output) : a.plot_dir;
  if (!a.no_plots) check_plot_folder(plot_dir, a.plot_dir.empty() ? "plots" : "--plot-dir");
  for (const auto& w : scenarios::scene_warnings(scene)) fmt::print(stderr, "ferrodyn: warning: {}\n", w);
  Progress progress(scene.simulation.t_end, stderr);
  if (!a.quiet) opt.progress = [&](double t) { progress.update(t); };
  opt.should_stop = [] { return InterruptGuard::stop_now(); };
  opt.stop_reason = "interrupted by signal";
  const auto s = scenarios::run_scene(scene, opt);
  progress.finish();
  const int sig = InterruptGuard::signal_received();

  const double v = scene.simulation.speed;
  fmt::print("ferrodyn run: {} ({})\n", scene.name, scene.path);
  fmt::print("  model     {}, V = {:.3f} m/s ({:.1f} km/h)\n", scene.model.type, v, v * 3.6);
  if (scene.model.type == "vehicle") {
    fmt::print("  vehicle   {} (scope {}), contact {} geometry, {} creep forces\n",
               scene.model.vehicle.name, scene.model.selection.scope,
               scene.model.vehicle.wheel_rail.geometry, scene.model.vehicle.wheel_rail.tangential_model);
  } else {
    const auto sys = scenarios::build_system(scene, v);
    const auto modes = vehicle::linear_modes(*sys, 0.0, scenarios::equilibrium_state(scene, *sys));
    if (!modes.empty()) {
      fmt::print("  linear    least damped mode at V: damping ratio {:+.4f}, {:.3f} Hz ({})\n",
                 modes.front().damping_ratio, modes.front().frequency_hz,
                 modes.front().damping_ratio > 0.0 ? "stable" : "unstable");
    }
  }
  if (scene.solver.fixed_step > 0.0) {
    fmt::print("  solver    {} (fixed step {:g} s, no error control): {} steps, {} rhs evaluations\n",
               scene.solver.method, scene.solver.fixed_step, s.steps, s.rhs_evaluations);
  } else {
    fmt::print("  solver    {} (rtol {:g}, atol {:g}): {} steps, {} rhs evaluations\n",
               scene.solver.method, scene.solver.rtol, scene.solver.atol, s.steps,
               s.rhs_evaluations);
  }
  fmt::print("  status    {} at t = {:.6g} s: {} samples in {:.3f} s wall ({:.1f}x real time)\n",
             s.status_text, s.t_reached, s.samples, s.wall_seconds,
             s.wall_seconds > 0 ? s.t_reached / s.wall_seconds : 0.0);
  if (!s.message.empty()) fmt::print("  cause     {}\n", s.message);
  fmt::print("  {:<30} {:<6} {:>12} {:>12}\n", "signal", "unit", "peak |x|", "final");
  // A vehicle has many channels: the summary shows wheel forces, wheelset displacements and
  // car-body acceleration (the HDF5 file has them all).
  const auto shown = [&](const std::string& name) {
    if (scene.model.type != "vehicle") return true;
    for (const char* end : {".Y", ".Q", ".points", "ay"}) {
      const std::string e(end);
      if (name.size() >= e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0)
        return true;
    }
    return name.rfind("wheelset_", 0) == 0 &&
           (name.size() > 2 && (name.substr(name.size() - 2) == ".y" ||
                                (name.size() > 4 && name.substr(name.size() - 4) == ".yaw")));
  };
  for (std::size_t i = 0; i < s.channels.size(); ++i) {
    if (!shown(s.channels[i].name)) continue;
    fmt::print("  {:<30} {:<6} {:>12.5g} {:>12.5g}\n", s.channels[i].name, s.channels[i].unit,
               s.peak_abs[i], s.final_values[i]);
  }
  fmt::print("  output    {}{}\n", s.output_file, s.csv_file.empty() ? "" : " and " + s.csv_file);
  if (s.status == vehicle::IntegrationResult::Status::kInterrupted || sig != 0) {
    std::fflush(stdout);
    return sig != 0 ? 128 + sig : kExitInterrupted;
  }
  if (!a.no_plots && s.samples > 1) {
    std::vector<std::string> signals = scene.output.plots;
    if (signals.empty()) {
      for (std::size_t i = 0; i < s.state_count; ++i) signals.push_back(s.channels[i].name);
    }
    std::fflush(stdout);
    const int rc = report_plots(make_plots("timeseries", s.output_file, signals, plot_dir, "png,svg"),
                                plot_dir, s.output_file);
    if (rc != kExitOk) return rc;
  }
  std::fflush(stdout);
  if (s.status == vehicle::IntegrationResult::Status::kSolverFailure) {
    fmt::print(stderr, "ferrodyn: solver failure: {}\n", s.message);
    return kExitRunFailure;
  }
  return kExitOk;
}

int do_eig(const EigArgs& a) {
  Scene scene = scenarios::load_scene(a.scene);
  if (!a.tangential.empty()) {
    scenarios::override_tangential(scene, a.tangential, "--tangential",
                                   with_environment_options(a.tangential));
  }
  if (!std::isnan(a.speed_min)) scene.eigen.speed_min = a.speed_min;
  if (!std::isnan(a.speed_max)) scene.eigen.speed_max = a.speed_max;
  if (a.points > 0) scene.eigen.points = a.points;
  if (!(scene.eigen.speed_min > 0.0 && scene.eigen.speed_max > scene.eigen.speed_min)) {
    throw std::invalid_argument(
        fmt::format("--speed-min/--speed-max: need 0 < min < max, got {} and {}",
                    scene.eigen.speed_min, scene.eigen.speed_max));
  }
  if (scene.eigen.points < 2) throw std::invalid_argument("--points: must be >= 2");
  // The output is claimed before the sweep: a path that would be refused is refused now.
  const std::string out = a.output.empty()
                              ? (fs::path(scene.output.file).parent_path() /
                                 (fs::path(scene.output.file).stem().string() + "_eig.h5"))
                                    .string()
                              : a.output;
  scenarios::OutputSet outputs({a.overwrite, scenarios::scene_inputs(scene)});
  scenarios::OutputFile& file = outputs.claim(out, a.output.empty() ? "output" : "-o");
  const std::string plot_dir = default_plot_dir(out);
  if (!a.no_plots) check_plot_folder(plot_dir, "plots");
  const auto r = scenarios::run_eigen(scene);
  fmt::print("ferrodyn eig: {} ({}), {} speeds in [{:g}, {:g}] m/s\n", scene.name, scene.path,
             scene.eigen.points, scene.eigen.speed_min, scene.eigen.speed_max);
  print_eigen_report(scene, r, 16);
  if (r.closed_form_critical_speed) {
    fmt::print("  closed form eq. (151): {:.6f} m/s", *r.closed_form_critical_speed);
    if (r.critical_speed) {
      fmt::print(" (relative difference {:.2e})",
                 *r.critical_speed / *r.closed_form_critical_speed - 1.0);
    }
    fmt::print("\n");
  } else if (!r.closed_form_note.empty()) {
    fmt::print("  {}\n", r.closed_form_note);
  }
  scenarios::write_eigen_report(scene, r, file.write_path());
  file.commit();
  fmt::print("  output    {}\n", out);
  if (!a.no_plots) {
    std::fflush(stdout);
    return report_plots(make_plots("eigen", out, {}, plot_dir, "png,svg"), plot_dir, out);
  }
  return kExitOk;
}

int do_plot(const PlotArgs& a) {
  if (!fs::exists(a.file))
    throw std::invalid_argument(fmt::format("plot: no such file '{}'", a.file));
  if (a.format != "png" && a.format != "svg" && a.format != "png,svg" && a.format != "svg,png") {
    throw std::invalid_argument(
        fmt::format("--format: unknown '{}'; allowed: png, svg, png,svg", a.format));
  }
  const std::string dir = a.out_dir.empty() ? default_plot_dir(a.file) : a.out_dir;
  check_plot_folder(dir, a.out_dir.empty() ? "plots" : "-o");
  const int rc = make_plots("auto", a.file, a.signals, dir, a.format);
  if (rc == scenarios::kProgramStopped) return 128 + InterruptGuard::signal_received();
  if (rc == 2) return kExitBadInput;
  if (rc == kPlotsNeedPython)
    throw std::runtime_error("plotting needs python3 with matplotlib and h5py");
  if (rc != 0) throw std::runtime_error(fmt::format("plotting failed (exit status {})", rc));
  fmt::print("plots written to {}/\n", dir);
  return kExitOk;
}

int do_validate(const std::string& path) {
  const Scene s = scenarios::load_scene(path);
  // Every check of `run` before its first step (the model built as `run` builds it).
  scenarios::check_scene(s);
  for (const auto& w : scenarios::scene_warnings(s)) fmt::print(stderr, "{}: warning: {}\n", path, w);
  fmt::print(
      "{}: valid scene '{}' (schema {}): model {}, track {}, integrator {}, t_end {} s, V = {} "
      "m/s\n",
      path, s.name, s.schema_version, s.model.type, s.track.type, s.solver.method,
      s.simulation.t_end, s.simulation.speed);
  return kExitOk;
}

}  // namespace

void add_scene_commands(CLI::App& app, VerbHandler& handler) {
  auto run_args = std::make_shared<RunArgs>();
  auto* run = app.add_subcommand("run", "Time simulation of a scene: HDF5 output, summary, plots");
  run->add_option("scene", run_args->scene, "Scene YAML file")->required();
  run->add_option("-o,--output", run_args->output,
                  "HDF5 output file (default: the scene's output.file)");
  run->add_option("--csv", run_args->csv,
                  "Also write these signals to CSV ('all' for every signal)");
  run->add_option("--t-end", run_args->t_end, "Override simulation.t_end [s]")
      ->check(number_in(0.0, INFINITY, true, true, "s"));
  run->add_option("--speed", run_args->speed,
                  "Override simulation.speed [m/s] (>= 0 for vehicle scenes, > 0 for the linear "
                  "wheelset)")
      ->check(number_in(0.0, INFINITY, false, true, "m/s"));
  run->add_option("--integrator", run_args->integrator, "Override solver.integrator");
  run->add_option("--fixed-step", run_args->fixed_step,
                  "Override solver.fixed_step [s] (arkode_erk, arkode_dirk, odeint_bs3, bdf2; 0: "
                  "adaptive steps)")
      ->check(number_in(0.0, INFINITY, false, true, "s"));
  run->add_option("--rtol", run_args->rtol, "Override solver.rtol [-]")
      ->check(number_in(0.0, 1.0, true, true, ""));
  run->add_option("--atol", run_args->atol, "Override solver.atol [state units, SI]")
      ->check(number_in(0.0, INFINITY, true, true, ""));
  run->add_option("--tangential", run_args->tangential,
                  "Override the scene's tangential contact model (vehicle scenes)");
  run->add_option("--normal", run_args->normal,
                  "Override the scene's normal contact model: hertz, semi_hertz (vehicle scenes)");
  run->add_option("--pace", run_args->pace,
                  "Simulated seconds per wall-clock second (0: as fast as possible; 1: real time)")
      ->check(number_in(0.0, INFINITY, false, true, ""));
  run->add_option("--plot-dir", run_args->plot_dir,
                  "Folder for the plots (default: <output>_plots)");
  add_no_plots_flag(run, run_args->no_plots);
  run->add_flag("-q,--quiet", run_args->quiet, "No progress display");
  add_overwrite_flag(run, run_args->overwrite);
  run->callback([&handler, run_args] {
    handler = [run_args] { return do_run(*run_args); };
  });

  auto eig_args = std::make_shared<EigArgs>();
  auto* eig =
      app.add_subcommand("eig", "Linear eigenvalue analysis over a speed range; critical speed");
  eig->add_option("scene", eig_args->scene, "Scene YAML file")->required();
  eig->add_option("-o,--output", eig_args->output,
                  "HDF5 output (default: <output.file stem>_eig.h5)");
  eig->add_option("--speed-min", eig_args->speed_min, "Lowest speed [m/s]")
      ->check(number_in(0.0, INFINITY, true, true, "m/s"));
  eig->add_option("--speed-max", eig_args->speed_max, "Highest speed [m/s]")
      ->check(number_in(0.0, INFINITY, true, true, "m/s"));
  eig->add_option("--points", eig_args->points, "Number of speeds in the sweep")
      ->check(count_in(2, scenarios::kMaxEigenPoints));
  eig->add_option("--tangential", eig_args->tangential,
                  "Override the scene's tangential contact model (vehicle scenes)");
  add_no_plots_flag(eig, eig_args->no_plots);
  add_overwrite_flag(eig, eig_args->overwrite);
  eig->callback([&handler, eig_args] { handler = [eig_args] { return do_eig(*eig_args); }; });

  auto plot_args = std::make_shared<PlotArgs>();
  auto* plot = app.add_subcommand("plot", "Plot signals of a ferrodyn HDF5 file to PNG and SVG");
  plot->add_option("file", plot_args->file, "HDF5 file written by ferrodyn")->required();
  plot->add_option("signals", plot_args->signals, "Signals to plot (default: all)");
  add_output_option(plot, plot_args->out_dir, "Output folder (default: <file>_plots)", {"--out"});
  plot->add_option("--format", plot_args->format, "png, svg or png,svg");
  plot->callback([&handler, plot_args] { handler = [plot_args] { return do_plot(*plot_args); }; });

  auto scene_path = std::make_shared<std::string>();
  auto* validate = app.add_subcommand("validate", "Check a scene file and report the first error");
  validate->add_option("scene", *scene_path, "Scene YAML file")->required();
  validate->callback(
      [&handler, scene_path] { handler = [scene_path] { return do_validate(*scene_path); }; });
}

}  // namespace ferro::cli
