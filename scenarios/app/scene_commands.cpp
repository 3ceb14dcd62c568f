// Verbs on scenes and run outputs: run, plot, validate.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "cli.hpp"
#include "ferro/scenarios/claimed_output.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/parameters.hpp"
#include "ferro/scenarios/report.hpp"
#include "plotting.hpp"
#include "ferro/scenarios/run.hpp"
#include "ferro/scenarios/scene.hpp"
#include "terminal.hpp"

namespace ferro::cli {
namespace {

using scenarios::Scene;

struct RunArgs {
  std::string scene, plot_dir;
  std::vector<std::string> csv;
  scenarios::RunOverrides overrides;
  scenarios::RunOptions options;  ///< output_file, overwrite, pace
  bool no_plots = false, quiet = false;
};

struct PlotArgs {
  std::string file, out_dir, format = "png,svg";
  std::vector<std::string> signals;
};

int do_run(const RunArgs& a) {
  Scene scene = scenarios::load_scene(a.scene);
  scenarios::apply_overrides(scene, a.overrides, scenarios::Spelling::option);
  scenarios::RunOptions opt = a.options;
  if (!a.csv.empty()) opt.csv = a.csv;
  const std::string output = opt.output_file.empty() ? scene.output.file : opt.output_file;
  const std::string plot_dir = a.plot_dir.empty() ? scenarios::sibling(output, "_plots") : a.plot_dir;
  if (!a.no_plots) scenarios::check_plot_folder(plot_dir, a.plot_dir.empty() ? "plots" : "--plot-dir");
  for (const auto& w : scenarios::scene_warnings(scene))
    fmt::print(stderr, "ferrodyn: warning: {}\n", w);
  auto progress = stderr_meter(scene.simulation.t_end);
  if (!a.quiet) opt.progress = [&](double t) { show_progress(progress.update(t)); };
  opt.should_stop = [] { return InterruptGuard::stop_now(); };
  opt.stop_reason = "interrupted by signal";
  const auto s = scenarios::run_scene(scene, opt);
  show_progress(progress.finish());
  const int sig = InterruptGuard::signal_received();

  fmt::print("{}", scenarios::run_report(scene, s));
  fmt::print("  output    {}{}\n", s.output_file, s.csv_file.empty() ? "" : " and " + s.csv_file);
  if (s.status == vehicle::IntegrationResult::Status::kInterrupted || sig != 0) {
    std::fflush(stdout);
    return sig != 0 ? 128 + sig : kExitInterrupted;
  }
  if (!a.no_plots && s.samples > 1) {
    const int rc = plot_after_report("timeseries", s.output_file, s.plots, plot_dir);
    if (rc != kExitOk) return rc;
  }
  std::fflush(stdout);
  if (s.status == vehicle::IntegrationResult::Status::kSolverFailure) {
    fmt::print(stderr, "ferrodyn: solver failure: {}\n", s.message);
    return kExitRunFailure;
  }
  return kExitOk;
}

int do_plot(const PlotArgs& a) {
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
  fmt::print("{}", scenarios::valid_scene_line(path, s));
  return kExitOk;
}

}  // namespace

void add_scene_commands(CLI::App& app, VerbHandler& handler) {
  auto [run, run_args] = add_verb<RunArgs>(
      &app, handler, do_run, "run", "Time simulation of a scene: HDF5 output, summary, plots");
  run->add_option("scene", run_args->scene, "Scene YAML file")->required();
  run->add_option("-o,--output", run_args->options.output_file,
                  "HDF5 output file (default: the scene's output.file)");
  run->add_option("--csv", run_args->csv,
                  "Also write these signals to CSV ('all' for every signal)");
  add_parameters(run, scenarios::select_parameters(
                          scenarios::parameters(run_args->overrides),
                          {"t_end", "speed", "integrator", "fixed_step", "rtol", "atol",
                           "tangential", "normal"}));
  add_parameters(run, scenarios::parameters(run_args->options));
  run->add_option("--plot-dir", run_args->plot_dir,
                  "Folder for the plots (default: <output>_plots)");
  add_no_plots_flag(run, run_args->no_plots);
  run->add_flag("-q,--quiet", run_args->quiet, "No progress display");
  add_overwrite_flag(run, run_args->options.overwrite);

  auto [plot, plot_args] = add_verb<PlotArgs>(
      &app, handler, do_plot, "plot", "Plot signals of a ferrodyn HDF5 file to PNG and SVG");
  plot->add_option("file", plot_args->file, "HDF5 file written by ferrodyn")
      ->required()
      ->check(CLI::ExistingFile);
  plot->add_option("signals", plot_args->signals, "Signals to plot (default: all)");
  add_output_option(plot, plot_args->out_dir, "Output folder (default: <file>_plots)", {"--out"});
  plot->add_option("--format", plot_args->format, "png, svg or png,svg")
      ->check(CLI::IsMember({"png", "svg", "png,svg", "svg,png"}));

  auto [validate, scene_path] = add_verb<std::string>(
      &app, handler, do_validate, "validate", "Check a scene file and report the first error");
  validate->add_option("scene", *scene_path, "Scene YAML file")->required();
}

}  // namespace ferro::cli
