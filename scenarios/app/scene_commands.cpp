// Verbs on scenes and run outputs: run, eig, plot, validate.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <memory>

#include "cli.hpp"
#include "ferro/scenarios/claimed_output.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/output_file.hpp"
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
  bool no_plots = false, quiet = false, overwrite = false;
};

struct EigArgs {
  std::string scene, output;
  scenarios::RunOverrides overrides;
  bool no_plots = false, overwrite = false;
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
  opt.overwrite = a.overwrite;
  if (!(a.pace >= 0.0))
    throw std::invalid_argument(fmt::format("--pace: must be >= 0, got {}", a.pace));
  opt.pace = a.pace;
  if (!a.csv.empty()) opt.csv = a.csv;
  const std::string output = a.output.empty() ? scene.output.file : a.output;
  const std::string plot_dir = a.plot_dir.empty() ? scenarios::sibling(output, "_plots") : a.plot_dir;
  if (!a.no_plots) scenarios::check_plot_folder(plot_dir, a.plot_dir.empty() ? "plots" : "--plot-dir");
  for (const auto& w : scenarios::scene_warnings(scene))
    fmt::print(stderr, "ferrodyn: warning: {}\n", w);
  Progress progress(scene.simulation.t_end, stderr);
  if (!a.quiet) opt.progress = [&](double t) { progress.update(t); };
  opt.should_stop = [] { return InterruptGuard::stop_now(); };
  opt.stop_reason = "interrupted by signal";
  const auto s = scenarios::run_scene(scene, opt);
  progress.finish();
  const int sig = InterruptGuard::signal_received();

  fmt::print("{}", scenarios::run_report(scene, s));
  fmt::print("  output    {}{}\n", s.output_file, s.csv_file.empty() ? "" : " and " + s.csv_file);
  if (s.status == vehicle::IntegrationResult::Status::kInterrupted || sig != 0) {
    std::fflush(stdout);
    return sig != 0 ? 128 + sig : kExitInterrupted;
  }
  if (!a.no_plots && s.samples > 1) {
    std::vector<std::string> signals = scene.output.plots;  // default: every state
    if (signals.empty())
      for (std::size_t i = 0; i < s.state_count; ++i) signals.push_back(s.channels[i].name);
    const int rc = plot_after_report("timeseries", s.output_file, signals, plot_dir);
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
  scenarios::apply_overrides(scene, a.overrides, scenarios::Spelling::option);
  // The output is claimed before the sweep: a path that would be refused is refused now.
  const std::string out =
      a.output.empty() ? scenarios::sibling(scene.output.file, "_eig.h5") : a.output;
  scenarios::ClaimedOutput file(out, a.output.empty() ? "output" : "-o", a.overwrite,
                                scenarios::scene_inputs(scene), a.no_plots);
  const auto r = scenarios::run_eigen(scene);
  fmt::print("{}", scenarios::eigen_sweep_report(scene, r));
  scenarios::write_eigen_report(scene, r, file.write_path());
  file.file->commit();
  fmt::print("  output    {}\n", out);
  if (!a.no_plots) return plot_after_report("eigen", out);
  return kExitOk;
}

int do_plot(const PlotArgs& a) {
  if (!fs::exists(a.file))
    throw std::invalid_argument(fmt::format("plot: no such file '{}'", a.file));
  if (a.format != "png" && a.format != "svg" && a.format != "png,svg" && a.format != "svg,png") {
    throw std::invalid_argument(
        fmt::format("--format: unknown '{}'; allowed: png, svg, png,svg", a.format));
  }
  const std::string dir = a.out_dir.empty() ? scenarios::sibling(a.file, "_plots") : a.out_dir;
  scenarios::check_plot_folder(dir, a.out_dir.empty() ? "plots" : "-o");
  const int rc = plot_file("auto", a.file, a.signals, dir, a.format);
  if (rc == kProgramStopped) return 128 + InterruptGuard::signal_received();
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
  for (const auto& w : scenarios::scene_warnings(s))
    fmt::print(stderr, "{}: warning: {}\n", path, w);
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
  run->get_option("--t-end")->check(number_in(0.0, INFINITY, true, true, "s"));
  run->get_option("--speed")->check(number_in(0.0, INFINITY, false, true, "m/s"));
  run->get_option("--fixed-step")->check(number_in(0.0, INFINITY, false, true, "s"));
  run->get_option("--rtol")->check(number_in(0.0, 1.0, true, true, ""));
  run->get_option("--atol")->check(number_in(0.0, INFINITY, true, true, ""));
  run->add_option("--pace", run_args->pace,
                  "Simulated seconds per wall-clock second (0: as fast as possible; 1: real time)")
      ->check(number_in(0.0, INFINITY, false, true, ""));
  run->add_option("--plot-dir", run_args->plot_dir,
                  "Folder for the plots (default: <output>_plots)");
  add_no_plots_flag(run, run_args->no_plots);
  run->add_flag("-q,--quiet", run_args->quiet, "No progress display");
  add_overwrite_flag(run, run_args->overwrite);
  on_parsed(run, handler, run_args, do_run);

  auto eig_args = std::make_shared<EigArgs>();
  auto* eig =
      app.add_subcommand("eig", "Linear eigenvalue analysis over a speed range; critical speed");
  eig->add_option("scene", eig_args->scene, "Scene YAML file")->required();
  eig->add_option("-o,--output", eig_args->output,
                  "HDF5 output (default: <output.file stem>_eig.h5)");
  add_parameters(eig, scenarios::select_parameters(scenarios::parameters(eig_args->overrides),
                                                   {"speed_min", "speed_max", "points",
                                                    "tangential"}));
  eig->get_option("--speed-min")->check(number_in(0.0, INFINITY, true, true, "m/s"));
  eig->get_option("--speed-max")->check(number_in(0.0, INFINITY, true, true, "m/s"));
  eig->get_option("--points")->check(count_in(2, scenarios::kMaxEigenPoints));
  add_no_plots_flag(eig, eig_args->no_plots);
  add_overwrite_flag(eig, eig_args->overwrite);
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
