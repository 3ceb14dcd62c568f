// Verbs on scenes and run outputs: run, eig, plot, validate.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <memory>

#include "cli.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "plotting.hpp"
#include "ferro/scenarios/run.hpp"
#include "ferro/scenarios/scene.hpp"
#include "terminal.hpp"

namespace ferro::cli {
namespace {

namespace fs = std::filesystem;
using scenarios::Scene;

struct RunArgs {
  std::string scene, output, plot_dir;
  std::vector<std::string> csv;
  scenarios::RunOverrides overrides;
  double pace = 0.0;
  bool no_plots = false, quiet = false;
};

struct EigArgs {
  std::string scene, output;
  scenarios::RunOverrides overrides;
  bool no_plots = false;
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
  return run_python_tool("ferroplot.py", args);
}

int do_run(const RunArgs& a) {
  Scene scene = scenarios::load_scene(a.scene);
  scenarios::apply_overrides(scene, a.overrides, scenarios::Spelling::option);
  scenarios::RunOptions opt;
  opt.output_file = a.output;
  if (!(a.pace >= 0.0))
    throw std::invalid_argument(fmt::format("--pace: must be >= 0, got {}", a.pace));
  opt.pace = a.pace;
  if (!a.csv.empty()) opt.csv = a.csv;
  Progress progress(scene.simulation.t_end, stderr);
  if (!a.quiet) opt.progress = [&](double t) { progress.update(t); };
  opt.should_stop = [] { return InterruptGuard::signal_received() != 0; };
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
  if (!a.no_plots && s.samples > 1) {
    const std::string dir = a.plot_dir.empty() ? default_plot_dir(s.output_file) : a.plot_dir;
    std::vector<std::string> signals = scene.output.plots;
    if (signals.empty()) {
      for (std::size_t i = 0; i < s.state_count; ++i) signals.push_back(s.channels[i].name);
    }
    const int rc = make_plots("timeseries", s.output_file, signals, dir, "png,svg");
    if (rc == 0) {
      fmt::print("  plots     {}/\n", dir);
    } else {
      fmt::print(stderr,
                 "ferrodyn: warning: plotting failed (python3 with matplotlib and h5py needed); "
                 "the results in {} are complete\n",
                 s.output_file);
    }
  }
  std::fflush(stdout);
  if (s.status == vehicle::IntegrationResult::Status::kInterrupted)
    return sig != 0 ? 128 + sig : kExitInterrupted;
  if (s.status == vehicle::IntegrationResult::Status::kSolverFailure) {
    fmt::print(stderr, "ferrodyn: solver failure: {}\n", s.message);
    return kExitRunFailure;
  }
  return kExitOk;
}

int do_eig(const EigArgs& a) {
  Scene scene = scenarios::load_scene(a.scene);
  scenarios::apply_overrides(scene, a.overrides, scenarios::Spelling::option);
  const auto r = scenarios::run_eigen(scene);
  fmt::print("ferrodyn eig: {} ({}), {} speeds in [{:g}, {:g}] m/s\n", scene.name, scene.path,
             scene.eigen.points, scene.eigen.speed_min, scene.eigen.speed_max);
  fmt::print("  {:>10} {:>10} {:>14} {:>12}\n", "V [m/s]", "V [km/h]", "damping ratio",
             "freq [Hz]");
  const std::size_t stride = std::max<std::size_t>(1, r.sweep.size() / 15);
  for (std::size_t i = 0; i < r.sweep.size(); i += stride) {
    const auto& p = r.sweep[i];
    fmt::print("  {:>10.3f} {:>10.2f} {:>+14.5f} {:>12.4f}\n", p.speed, p.speed * 3.6,
               p.least_damped.damping_ratio, p.least_damped.frequency_hz);
  }
  if (r.critical_speed) {
    fmt::print("  critical speed (least damped mode crosses zero): {:.6f} m/s = {:.3f} km/h\n",
               *r.critical_speed, *r.critical_speed * 3.6);
  } else {
    fmt::print("  no critical speed in [{:g}, {:g}] m/s\n", scene.eigen.speed_min,
               scene.eigen.speed_max);
  }
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
  const std::string out = a.output.empty()
                              ? (fs::path(scene.output.file).parent_path() /
                                 (fs::path(scene.output.file).stem().string() + "_eig.h5"))
                                    .string()
                              : a.output;
  scenarios::write_eigen_report(scene, r, out);
  fmt::print("  output    {}\n", out);
  if (!a.no_plots) {
    const std::string dir = default_plot_dir(out);
    if (make_plots("eigen", out, {}, dir, "png,svg") == 0) {
      fmt::print("  plots     {}/\n", dir);
    } else {
      fmt::print(stderr, "ferrodyn: warning: plotting failed; the results in {} are complete\n",
                 out);
    }
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
  const int rc = make_plots("auto", a.file, a.signals, dir, a.format);
  if (rc == 2) return kExitBadInput;
  if (rc != 0)
    throw std::runtime_error("plotting failed (python3 with matplotlib and h5py needed)");
  fmt::print("plots written to {}/\n", dir);
  return kExitOk;
}

int do_validate(const std::string& path) {
  const Scene s = scenarios::load_scene(path);
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
  run->add_option("--t-end", run_args->overrides.t_end, "Override simulation.t_end [s]");
  run->add_option("--speed", run_args->overrides.speed, "Override simulation.speed [m/s]");
  run->add_option("--integrator", run_args->overrides.integrator, "Override solver.integrator");
  run->add_option("--fixed-step", run_args->overrides.fixed_step,
                  "Override solver.fixed_step [s] (arkode_erk, arkode_dirk, odeint_bs3; 0: "
                  "adaptive steps)");
  run->add_option("--rtol", run_args->overrides.rtol, "Override solver.rtol [-]");
  run->add_option("--atol", run_args->overrides.atol, "Override solver.atol [state units, SI]");
  run->add_option("--tangential", run_args->overrides.tangential,
                  "Override the scene's tangential contact model (vehicle scenes)");
  run->add_option("--normal", run_args->overrides.normal,
                  "Override the scene's normal contact model: hertz, semi_hertz (vehicle scenes)");
  run->add_option("--pace", run_args->pace,
                  "Simulated seconds per wall-clock second (0: as fast as possible; 1: real time)");
  run->add_option("--plot-dir", run_args->plot_dir,
                  "Folder for the plots (default: <output>_plots)");
  add_no_plots_flag(run, run_args->no_plots);
  run->add_flag("-q,--quiet", run_args->quiet, "No progress display");
  run->callback([&handler, run_args] {
    InterruptGuard::claim();
    handler = [run_args] { return do_run(*run_args); };
  });

  auto eig_args = std::make_shared<EigArgs>();
  auto* eig =
      app.add_subcommand("eig", "Linear eigenvalue analysis over a speed range; critical speed");
  eig->add_option("scene", eig_args->scene, "Scene YAML file")->required();
  eig->add_option("-o,--output", eig_args->output,
                  "HDF5 output (default: <output.file stem>_eig.h5)");
  eig->add_option("--speed-min", eig_args->overrides.speed_min, "Lowest speed [m/s]");
  eig->add_option("--speed-max", eig_args->overrides.speed_max, "Highest speed [m/s]");
  eig->add_option("--points", eig_args->overrides.points, "Number of speeds in the sweep");
  eig->add_option("--tangential", eig_args->overrides.tangential,
                  "Override the scene's tangential contact model (vehicle scenes)");
  add_no_plots_flag(eig, eig_args->no_plots);
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
