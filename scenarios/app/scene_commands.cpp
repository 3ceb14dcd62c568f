// Verbs on scenes and run outputs: run, eig, plot, validate.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <memory>

#include "cli.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/parameters.hpp"
#include "ferro/scenarios/report.hpp"
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

  fmt::print("{}", scenarios::run_report(scene, s));
  fmt::print("  output    {}{}\n", s.output_file, s.csv_file.empty() ? "" : " and " + s.csv_file);
  if (!a.no_plots && s.samples > 1) {
    std::vector<std::string> signals = scene.output.plots;  // default: every state
    if (signals.empty())
      for (std::size_t i = 0; i < s.state_count; ++i) signals.push_back(s.channels[i].name);
    plot_after_report("timeseries", s.output_file, signals, a.plot_dir);
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
  fmt::print("{}", scenarios::eigen_sweep_report(scene, r));
  const std::string out = a.output.empty() ? sibling(scene.output.file, "_eig.h5") : a.output;
  scenarios::write_eigen_report(scene, r, out);
  fmt::print("  output    {}\n", out);
  if (!a.no_plots) plot_after_report("eigen", out);
  return kExitOk;
}

int do_plot(const PlotArgs& a) {
  if (!fs::exists(a.file))
    throw std::invalid_argument(fmt::format("plot: no such file '{}'", a.file));
  if (a.format != "png" && a.format != "svg" && a.format != "png,svg" && a.format != "svg,png") {
    throw std::invalid_argument(
        fmt::format("--format: unknown '{}'; allowed: png, svg, png,svg", a.format));
  }
  const std::string dir = a.out_dir.empty() ? sibling(a.file, "_plots") : a.out_dir;
  const int rc = plot_file("auto", a.file, a.signals, dir, a.format);
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
  add_parameters(run, scenarios::select_parameters(
                          scenarios::parameters(run_args->overrides),
                          {"t_end", "speed", "integrator", "fixed_step", "rtol", "atol",
                           "tangential", "normal"}));
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
  add_parameters(eig, scenarios::select_parameters(scenarios::parameters(eig_args->overrides),
                                                   {"speed_min", "speed_max", "points",
                                                    "tangential"}));
  add_no_plots_flag(eig, eig_args->no_plots);
  on_parsed(eig, handler, eig_args, do_eig);

  auto plot_args = std::make_shared<PlotArgs>();
  auto* plot = app.add_subcommand("plot", "Plot signals of a ferrodyn HDF5 file to PNG and SVG");
  plot->add_option("file", plot_args->file, "HDF5 file written by ferrodyn")->required();
  plot->add_option("signals", plot_args->signals, "Signals to plot (default: all)");
  add_output_option(plot, plot_args->out_dir, "Output folder (default: <file>_plots)", {"--out"});
  plot->add_option("--format", plot_args->format, "png, svg or png,svg");
  on_parsed(plot, handler, plot_args, do_plot);

  auto scene_path = std::make_shared<std::string>();
  auto* validate = app.add_subcommand("validate", "Check a scene file and report the first error");
  validate->add_option("scene", *scene_path, "Scene YAML file")->required();
  validate->callback(
      [&handler, scene_path] { handler = [scene_path] { return do_validate(*scene_path); }; });
}

}  // namespace ferro::cli
