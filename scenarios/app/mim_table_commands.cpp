// `ferrodyn contact mim-table`: builds the tabulated-MIM HDF5 table of the "mim_table" model.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <string>

#include "cli.hpp"
#include "ferro/scenarios/mim_solve.hpp"
#include "ferro/scenarios/mim_files.hpp"

namespace ferro::cli {

void add_mim_table_commands(CLI::App& app, VerbHandler& handler) {
  const auto write = [](const scenarios::MimTableRequest& r) {
    scenarios::write_mim_table_files(r, [](const std::string& text) { fmt::print("{}", text); });
    return kExitOk;
  };
  auto [cmd, a] = add_verb<scenarios::MimTableRequest>(
      app.get_subcommand("contact"), handler, write, "mim-table",
      "Precompute MIM creep forces over normalised creepages, spin and a/b into an HDF5 table "
      "(model mim_table; layout in docs/OUTPUT.md)");
  add_output_option(cmd, a->out, "HDF5 file to write (required)", {"--out"});
  add_parameters(cmd, scenarios::parameters(a->spec));
  cmd->add_option("--error-map", a->map_path,
                  "CSV of table-versus-direct MIM errors at random points (empty: none)");
  cmd->add_option("--error-map-points", a->map_points, "points of the error map")
      ->capture_default_str();
  add_overwrite_flag(cmd, a->overwrite);
}

}  // namespace ferro::cli
