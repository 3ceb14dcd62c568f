// `ferrodyn contact mim-table`: builds the tabulated-MIM HDF5 table of the "mim_table" model.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "cli.hpp"
#include "ferro/contact/tangential/mim_table.hpp"
#include "ferro/io/text_writer.hpp"
#include "ferro/scenarios/mim_solve.hpp"
#include "ferro/scenarios/output_file.hpp"

namespace ferro::cli {
namespace {

struct TableArgs {
  std::string out, map_path;
  contact::MimTableSpec spec = contact::MimTableSpec::default_spec();
  int map_points = 200;
  bool overwrite = false;
};

int run_mim_table(const TableArgs& a) {
  scenarios::check_mim_table_spec(a.spec, scenarios::Spelling::option);
  if (a.map_points < 1) {
    throw std::invalid_argument(
        fmt::format("--error-map-points: must be >= 1, got {}", a.map_points));
  }
  if (a.out.empty()) throw std::invalid_argument("contact mim-table: -o/--output is required");
  // Claimed before the (long) build: a path that would be refused is refused now.
  scenarios::OutputSet outputs({a.overwrite, {}});
  scenarios::OutputFile& file = outputs.claim(a.out, "-o");
  scenarios::OutputFile* map_file =
      a.map_path.empty() ? nullptr : &outputs.claim(a.map_path, "--error-map");
  const auto t0 = std::chrono::steady_clock::now();
  const contact::MimTable table = contact::MimTable::build(a.spec);
  table.write_hdf5(file.write_path());
  file.commit();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto& t = table.spec();
  fmt::print("wrote {} ({} x {} x {} x {} nodes, {} elements, nu {}) in {:.1f} s\n", a.out,
             t.ratio.size(), t.xi_x.size(), t.xi_y.size(), t.spin.size(), a.spec.elements,
             a.spec.poisson, s);
  if (!a.map_path.empty()) {
    const auto map = contact::mim_table_error_map(table, a.map_points, 1, a.spec.threads);
    const std::string report =
        scenarios::write_mim_table_error_map(map, map_file->write_path(), a.map_path);
    map_file->commit();
    fmt::print("{}", report);
  }
  return kExitOk;
}

}  // namespace

void add_mim_table_commands(CLI::App& app, VerbHandler& handler) {
  auto a = std::make_shared<TableArgs>();
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
  on_parsed(cmd, handler, a, run_mim_table);
}

}  // namespace ferro::cli
