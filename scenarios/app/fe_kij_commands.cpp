// `ferrodyn fe-kij CONFIG.yaml`: K_ij reduction-factor table over wheel load, interfacial-layer
// parameters and the rail's yield stress (scenarios::FeKijStudy), with creep and derivative
// curves per configuration; resumes an interrupted run.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>
#include <string>

#include "cli.hpp"
#include "ferro/scenarios/fe_kij_output.hpp"
#include "ferro/scenarios/fe_kij_study.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "plotting.hpp"
#include "terminal.hpp"

namespace ferro::cli {
namespace {

struct FeKijArgs {
  std::string config;
  bool restart = false, overwrite = false;
};

int run_fe_kij(const FeKijArgs& a) {
  const std::string& config_path = a.config;
  scenarios::FeKijStudy study(config_path, a.restart);
  scenarios::OutputSet outputs({a.overwrite, {config_path}});
  scenarios::OutputFile* table_file = &scenarios::claim_fe_kij_table(study, outputs);
  fmt::print("fe-kij: {} configurations ({} already done in {})\n", study.points(),
             study.resumed(), study.work_dir());
  Progress progress(static_cast<double>(study.points()), stderr);
  scenarios::FeKijRunOptions options;
  options.should_stop = [] { return InterruptGuard::stop_now(); };
  options.table_path = table_file->write_path();
  options.progress = [&](std::size_t done, std::size_t) {
    progress.update(static_cast<double>(done));
  };
  const scenarios::FeKijReport r = study.run(options);
  progress.finish();
  if (r.interrupted) {
    fmt::print(stderr, "fe-kij: interrupted; {} finished points kept in {} (run again to resume)\n",
               r.finished, study.work_dir());
    return 128 + InterruptGuard::signal_received();
  }
  table_file->commit();
  fmt::print("fe-kij: wrote {} ({} configurations; this run {:.2f} s CPU, {:.1f} s wall)\n",
             study.output(), study.points(), r.cpu_seconds, r.wall_seconds);
  if (study.wants_curve_plots()) {
    const int rc = run_python_tool("plot_kij_curves.py", {study.work_dir()});
    if (rc != 0) {
      fmt::print(stderr, "fe-kij: plotting failed (exit {}); the table and curve CSVs are written\n", rc);
      return kExitRunFailure;
    }
    fmt::print("fe-kij: creep and derivative curves plotted in {}\n", study.work_dir());
  }
  return kExitOk;
}

}  // namespace

void add_fe_kij_commands(CLI::App& app, VerbHandler& handler) {
  auto a = std::make_shared<FeKijArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fe-kij",
      "K_ij reduction-factor table (layout docs/KIJ_TABLE.md v2) over wheel load, "
      "interfacial-layer and rail yield-stress axes, with creep and derivative curves; resumes "
      "an interrupted run");
  cmd->add_option("config", a->config, "CONFIG.yaml")->required();
  cmd->add_flag("--restart", a->restart, "discard the finished points of a previous run");
  add_overwrite_flag(cmd, a->overwrite);
  on_parsed(cmd, handler, a, run_fe_kij);
}

}  // namespace ferro::cli
