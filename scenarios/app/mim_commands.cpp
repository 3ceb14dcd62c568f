// `ferrodyn contact mim`: one MIM (boundary-element) rolling-contact solve on a Hertzian patch.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "cli.hpp"
#include "ferro/scenarios/mim_files.hpp"

namespace ferro::cli {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct MimArgs {
  scenarios::MimRequest request;
  double a_mm = kNaN, b_mm = kNaN, young_gpa = kNaN;  // former spellings [mm], [GPa]
  std::string out;
  bool overwrite = false;
};

int run_mim(MimArgs args) {
  auto& r = args.request;
  if (std::isnan(r.a) && !std::isnan(args.a_mm)) r.a = args.a_mm * 1.0e-3;
  if (std::isnan(r.b) && !std::isnan(args.b_mm)) r.b = args.b_mm * 1.0e-3;
  if (!std::isnan(args.young_gpa)) r.young = args.young_gpa * 1.0e9;
  const auto outcome = scenarios::solve_mim_files(r, args.out, args.overwrite);
  fmt::print("{}", outcome.report);
  if (!args.out.empty()) fmt::print("fields written to {}\n", args.out);
  return outcome.converged ? kExitOk : kExitRunFailure;
}

}  // namespace

void add_mim_commands(CLI::App& app, VerbHandler& handler) {
  auto args = std::make_shared<MimArgs>();
  const auto define = [&](CLI::App* cmd) {
    add_parameters(cmd, scenarios::parameters(args->request));
    add_output_option(cmd, args->out, "HDF5 file for the pressure, traction, slip fields",
                      {"--out"});
    add_overwrite_flag(cmd, args->overwrite);
    add_hidden_alias(cmd, "--a-mm", args->a_mm);
    add_hidden_alias(cmd, "--b-mm", args->b_mm);
    add_hidden_alias(cmd, "--young-gpa", args->young_gpa);
    on_parsed(cmd, handler, args, run_mim);
  };
  const char* help =
      "MIM boundary-element rolling contact on a Hertz ellipse (normal + steady rolling)";
  define(app.get_subcommand("contact")->add_subcommand("mim", help));
  // The former top-level spelling, hidden, for one release.
  define(app.add_subcommand("mim", help)->group(""));
}

}  // namespace ferro::cli
