// `ferrodyn bench contact`: speed-versus-error table of every tangential model against
// fine-grid MIM, with a Pareto picture (time against error).
// `ferrodyn bench work-precision`: integrator x tolerance against a tight-tolerance reference
// run of a scene (error, CPU time, steps), naming the cheapest setting for a stated error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <vector>
#include <memory>
#include <string>

#include "cli.hpp"
#include "ferro/scenarios/claimed_output.hpp"
#include "ferro/scenarios/contact_bench.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/parameters.hpp"
#include "plotting.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/scenarios/work_precision.hpp"

namespace ferro::cli {
namespace {

struct ContactArgs {
  scenarios::ContactBenchOptions options;
  std::string out = ".";
  bool no_png = false;
};

int do_contact(const ContactArgs& a) {
  const scenarios::ContactBenchResult r = scenarios::run_contact_bench(a.options);
  fmt::print("{}", scenarios::contact_bench_report(r, a.options.threads));
  const std::string csv = scenarios::write_contact_bench_csv_in(r, a.out);
  fmt::print("wrote {}\n", csv);
  if (a.no_png) return kExitOk;
  const std::string png = scenarios::sibling(csv, ".png");
  draw("bench_contact_plot.py", {csv, png}, "the CSV is written; --no-plots skips the picture");
  fmt::print("wrote {}\n", png);
  return kExitOk;
}

struct WorkPrecisionArgs {
  std::string scene, output;
  scenarios::RunOverrides overrides;
  scenarios::WorkPrecisionOptions options;
  bool overwrite = false;
};

int do_work_precision(const WorkPrecisionArgs& a) {
  scenarios::Scene scene = scenarios::load_scene(a.scene);
  scenarios::apply_overrides(scene, a.overrides, scenarios::Spelling::option);
  scenarios::check_work_precision(scene, a.options);
  scenarios::OutputSet outputs({a.overwrite, scenarios::scene_inputs(scene)});
  scenarios::OutputFile* table = a.output.empty() ? nullptr : &outputs.claim(a.output, "-o");
  const scenarios::WorkPrecisionReport r = scenarios::run_work_precision(scene, a.options);
  fmt::print("{}", scenarios::work_precision_report(scene, r, a.options));
  if (table != nullptr) {
    scenarios::write_work_precision_csv(r, table->write_path());
    table->commit();
    fmt::print("wrote {}\n", a.output);
  }
  return kExitOk;
}

}  // namespace

void add_bench_commands(CLI::App& app, VerbHandler& handler) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks that report speed against accuracy");
  bench->require_subcommand(1);
  auto [contact, c] = add_verb<ContactArgs>(
      bench, handler, do_contact, "contact",
      "Every tangential model over 855 Hertzian cases (a/b 0.2-5; normalised spin 0-2; seven "
      "creepage directions; micro-slip to full slip) against converged MIM (N x N and 2N x 2N "
      "grids over the patch, Richardson): us per evaluation, mean / 95th percentile / max force "
      "error in mu Fn with and without spin, M_z error; writes bench_contact.csv and "
      "bench_contact.png");
  add_output_option(contact, c->out, "output folder", {"--out"})->capture_default_str();
  add_parameters(contact, scenarios::parameters(c->options));
  add_no_plots_flag(contact, c->no_png, {"--no-png"});

  auto [work, wp] = add_verb<WorkPrecisionArgs>(
      bench, handler, do_work_precision, "work-precision",
      "Integrator x tolerance on one scene against a cvode_bdf reference at a tight tolerance: "
      "error (largest deviation of the compared states, each relative to its peak), CPU seconds "
      "of the integration, steps; names the cheapest setting within --target-error");
  work->add_option("scene", wp->scene, "Scene YAML file")->required();
  add_output_option(work, wp->output, "CSV file of the table (default: none)");
  add_overwrite_flag(work, wp->overwrite);
  add_parameters(work, scenarios::select_parameters(scenarios::parameters(wp->overrides),
                                                    {"t_end", "speed", "tangential"}));
  add_parameters(work, scenarios::parameters(wp->options));
}

}  // namespace ferro::cli
