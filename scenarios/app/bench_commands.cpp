// `ferrodyn bench contact`: speed-versus-error table of every tangential model against
// fine-grid MIM, with a Pareto picture (time against error).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <string>

#include "cli.hpp"
#include "ferro/scenarios/contact_bench.hpp"
#include "ferro/scenarios/plotting.hpp"

namespace ferro::cli {

void add_bench_commands(CLI::App& app, VerbHandler& handler) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks that report speed against accuracy");
  bench->require_subcommand(1);
  auto opt = std::make_shared<scenarios::ContactBenchOptions>();
  auto out = std::make_shared<std::string>(".");
  auto no_png = std::make_shared<bool>(false);
  CLI::App* contact = bench->add_subcommand(
      "contact",
      "Every tangential model over 90 Hertzian cases (a/b 0.2-5; pure and combined creepage and "
      "spin; micro-slip to full slip) against fine-grid MIM: us per evaluation and mean / 95th "
      "percentile / max error in units of mu Fn; writes bench_contact.csv and bench_contact.png");
  add_output_option(contact, *out, "output folder", {"--out"})->capture_default_str();
  contact->add_option("--reference-elements", opt->reference_elements,
                      "reference MIM: elements across the shorter axis")
      ->capture_default_str();
  contact->add_option("--table", opt->table,
                      "mim_table HDF5 file (default: build the default table, ~10-20 s)");
  contact->add_option("--min-time", opt->min_time_s, "timing: minimum CPU seconds per model")
      ->capture_default_str();
  contact->add_flag("--quick", opt->quick, "15 cases, coarse reference and table (smoke test)");
  add_no_plots_flag(contact, *no_png, {"--no-png"});
  contact->callback([&handler, opt, out, no_png] {
    handler = [opt, out, no_png] {
      if (opt->reference_elements < 8) {
        throw std::invalid_argument(fmt::format("--reference-elements: must be >= 8, got {}",
                                                opt->reference_elements));
      }
      const scenarios::ContactBenchResult r = scenarios::run_contact_bench(*opt);
      fmt::print("{} Hertzian cases; error = |F_t - F_t,ref| / (mu F_n); CPU time per evaluation\n",
                 r.cases);
      fmt::print("| model | us / eval | mean error | 95th pct | max error |\n|---|---|---|---|---|\n");
      for (const auto& row : r.rows) {
        fmt::print("| {} | {:.3g} | {:.4f} | {:.4f} | {:.4f} |\n", row.label, row.us_per_eval,
                   row.mean_error, row.p95_error, row.max_error);
      }
      std::filesystem::create_directories(*out);
      const std::string csv = (std::filesystem::path(*out) / "bench_contact.csv").string();
      scenarios::write_contact_bench_csv(r, csv);
      fmt::print("wrote {}\n", csv);
      if (!*no_png) {
        const std::string png = (std::filesystem::path(*out) / "bench_contact.png").string();
        if (scenarios::run_python_tool("bench_contact_plot.py", {csv, png}) != 0) {
          throw std::runtime_error(fmt::format(
              "bench_contact_plot.py failed (python {} with matplotlib needed; --no-plots skips)",
              scenarios::python_program()));
        }
        fmt::print("wrote {}\n", png);
      }
      return kExitOk;
    };
  });
}

}  // namespace ferro::cli
