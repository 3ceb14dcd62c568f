// `ferrodyn bench contact`: speed-versus-error table of every tangential model against
// fine-grid MIM, with a Pareto picture (time against error).
// `ferrodyn bench work-precision`: integrator x tolerance against a tight-tolerance reference
// run of a scene (error, CPU time, steps), naming the cheapest setting for a stated error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>
#include <filesystem>
#include <memory>
#include <string>

#include "cli.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/contact_bench.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/parameters.hpp"
#include "plotting.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/scenarios/work_precision.hpp"

namespace ferro::cli {

void add_bench_commands(CLI::App& app, VerbHandler& handler) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks that report speed against accuracy");
  bench->require_subcommand(1);
  auto opt = std::make_shared<scenarios::ContactBenchOptions>();
  auto out = std::make_shared<std::string>(".");
  auto no_png = std::make_shared<bool>(false);
  CLI::App* contact = bench->add_subcommand(
      "contact",
      "Every tangential model over 855 Hertzian cases (a/b 0.2-5; normalised spin 0-2; seven "
      "creepage directions; micro-slip to full slip) against converged MIM (N x N and 2N x 2N "
      "grids over the patch, Richardson): us per evaluation, mean / 95th percentile / max force "
      "error in mu Fn with and without spin, M_z error; writes bench_contact.csv and "
      "bench_contact.png");
  add_output_option(contact, *out, "output folder", {"--out"})->capture_default_str();
  add_parameters(contact, scenarios::parameters(*opt));
  add_no_plots_flag(contact, *no_png, {"--no-png"});
  contact->callback([&handler, opt, out, no_png] {
    handler = [opt, out, no_png] {
      const scenarios::ContactBenchResult r = scenarios::run_contact_bench(*opt);
      fmt::print("{}", scenarios::contact_bench_report(r, opt->threads));
      std::filesystem::create_directories(*out);
      const std::string csv = (std::filesystem::path(*out) / "bench_contact.csv").string();
      scenarios::write_contact_bench_csv(r, csv);
      fmt::print("wrote {}\n", csv);
      if (!*no_png) {
        const std::string png = (std::filesystem::path(*out) / "bench_contact.png").string();
        if (run_python_tool("bench_contact_plot.py", {csv, png}) != 0) {
          throw std::runtime_error(fmt::format(
              "bench_contact_plot.py failed (python {} with matplotlib needed; --no-plots skips)",
              python_program()));
        }
        fmt::print("wrote {}\n", png);
      }
      return kExitOk;
    };
  });

  struct WpArgs {
    std::string scene, output;
    scenarios::RunOverrides overrides;
    scenarios::WorkPrecisionOptions options;
    bool overwrite = false;
  };
  auto wp = std::make_shared<WpArgs>();
  CLI::App* work = bench->add_subcommand(
      "work-precision",
      "Integrator x tolerance on one scene against a cvode_bdf reference at a tight tolerance: "
      "error (largest deviation of the compared states, each relative to its peak), CPU seconds "
      "of the integration, steps; names the cheapest setting within --target-error");
  work->add_option("scene", wp->scene, "Scene YAML file")->required();
  add_output_option(work, wp->output, "CSV file of the table (default: none)");
  add_overwrite_flag(work, wp->overwrite);
  add_parameters(work, scenarios::select_parameters(scenarios::parameters(wp->overrides),
                                                    {"t_end", "speed", "tangential"}));
  add_parameters(work, scenarios::parameters(wp->options));
  work->callback([&handler, wp] {
    handler = [wp] {
      scenarios::Scene scene = scenarios::load_scene(wp->scene);
      scenarios::apply_overrides(scene, wp->overrides, scenarios::Spelling::option);
      if (wp->options.settle > 0.0) {
        const std::string problem = scenarios::track_extent_problem(
            scene, wp->options.settle + scene.simulation.t_end);
        if (!problem.empty()) throw std::invalid_argument(fmt::format("--settle: {}", problem));
      }
      scenarios::OutputSet outputs({wp->overwrite, scenarios::scene_inputs(scene)});
      scenarios::OutputFile* table =
          wp->output.empty() ? nullptr : &outputs.claim(wp->output, "-o");
      const scenarios::WorkPrecisionReport r = scenarios::run_work_precision(scene, wp->options);
      fmt::print("{}", scenarios::work_precision_report(scene, r, wp->options));
      if (table != nullptr) {
        scenarios::write_work_precision_csv(r, table->write_path());
        table->commit();
        fmt::print("wrote {}\n", wp->output);
      }
      return kExitOk;
    };
  });
}

}  // namespace ferro::cli
