// `ferrodyn contact mim-table`: builds the tabulated-MIM HDF5 table of the "mim_table" model.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>
#include <string>
#include <thread>

#include "cli.hpp"
#include "ferro/scenarios/mim_solve.hpp"
#include "ferro/scenarios/mim_files.hpp"

namespace ferro::cli {

void add_mim_table_commands(CLI::App& app, VerbHandler& handler) {
  auto a = std::make_shared<scenarios::MimTableRequest>();
  a->spec.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  CLI::App* cmd = app.get_subcommand("contact")->add_subcommand(
      "mim-table",
      "Precompute MIM creep forces over normalised creepages, spin and a/b into an HDF5 table "
      "(model mim_table; layout in docs/OUTPUT.md)");
  add_output_option(cmd, a->out, "HDF5 file to write (required)", {"--out"});
  add_parameters(cmd, scenarios::parameters(a->spec));
  cmd->add_option("--error-map", a->map_path,
                  "CSV of table-versus-direct MIM errors at random points (empty: none)");
  cmd->add_option("--error-map-points", a->map_points, "points of the error map")
      ->capture_default_str();
  add_overwrite_flag(cmd, a->overwrite);
  on_parsed(cmd, handler, a, [](const scenarios::MimTableRequest& r) {
    scenarios::write_mim_table_files(r, [](const std::string& text) { fmt::print("{}", text); });
    return kExitOk;
  });
}

}  // namespace ferro::cli
