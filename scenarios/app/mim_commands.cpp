// `ferrodyn contact mim`: one MIM (boundary-element) rolling-contact solve on a Hertzian patch.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "cli.hpp"
#include "ferro/scenarios/mim_files.hpp"

namespace ferro::cli {
namespace {

struct MimArgs {
  scenarios::MimRequest request;
  std::string out;
  bool overwrite = false;
};

int run_mim(const MimArgs& args) {
  const auto outcome = scenarios::solve_mim_files(args.request, args.out, args.overwrite);
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
    on_parsed(cmd, handler, args, run_mim);
  };
  const char* help =
      "MIM boundary-element rolling contact on a Hertz ellipse (normal + steady rolling)";
  define(app.get_subcommand("contact")->add_subcommand("mim", help));
  // The former top-level spelling, hidden, for one release.
  define(app.add_subcommand("mim", help)->group(""));
}

}  // namespace ferro::cli
