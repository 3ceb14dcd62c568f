// `ferrodyn fe-kij CONFIG.yaml`: K_ij reduction-factor table over wheel load, interfacial-layer
// parameters and the rail's yield stress (scenarios::FeKijStudy), with creep and derivative
// curves per configuration; resumes an interrupted run.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
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
  scenarios::FeKijStudy study(a.config, a.restart);
  scenarios::OutputSet outputs({a.overwrite, {a.config}});
  scenarios::OutputFile* table_file = &scenarios::claim_fe_kij_table(study, outputs);
  fmt::print("{}", scenarios::fe_kij_start_text(study));
  auto progress = stderr_meter(static_cast<double>(study.points()));
  scenarios::FeKijRunOptions options;
  options.should_stop = [] { return InterruptGuard::stop_now(); };
  options.table_path = table_file->write_path();
  options.progress = [&](std::size_t done, std::size_t) {
    show_progress(progress.update(static_cast<double>(done)));
  };
  const scenarios::FeKijReport r = study.run(options);
  show_progress(progress.finish());
  if (r.interrupted) {
    fmt::print(stderr, "{}", scenarios::fe_kij_end_text(study, r));
    return 128 + InterruptGuard::signal_received();
  }
  table_file->commit();
  fmt::print("{}", scenarios::fe_kij_end_text(study, r));
  if (study.wants_curve_plots()) {
    draw("plot_kij_curves.py", {study.work_dir()}, "the table and curve CSVs are written");
    fmt::print("fe-kij: creep and derivative curves plotted in {}\n", study.work_dir());
  }
  return kExitOk;
}

}  // namespace

void add_fe_kij_commands(CLI::App& app, VerbHandler& handler) {
  auto [cmd, a] = add_verb<FeKijArgs>(
      &app, handler, run_fe_kij, "fe-kij",
      "K_ij reduction-factor table (layout docs/KIJ_TABLE.md v2) over wheel load, "
      "interfacial-layer and rail yield-stress axes, with creep and derivative curves; resumes "
      "an interrupted run");
  cmd->add_option("config", a->config, "CONFIG.yaml")->required();
  cmd->add_flag("--restart", a->restart, "discard the finished points of a previous run");
  add_overwrite_flag(cmd, a->overwrite);
}

}  // namespace ferro::cli
