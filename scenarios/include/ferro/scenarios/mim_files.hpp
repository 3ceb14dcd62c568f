#pragma once
// The MIM verbs' work: `ferrodyn contact mim` (one solve, its report, its fields as HDF5) and
// `ferrodyn contact mim-table` (the tabulated-MIM HDF5 table of the "mim_table" model built and
// written, with an optional CSV map of its errors against direct MIM solves).

#include <functional>
#include <string>

#include "ferro/contact/tangential/mim_table.hpp"
#include "ferro/scenarios/mim_solve.hpp"

namespace ferro::scenarios {

/// One solve (solve_hertz_rolling) of a request: its report (mim_report, with the solve's wall
/// time) and whether it converged.
struct MimSolveOutcome {
  std::string report;
  bool converged = false;
};

/// Solves `request` (std::invalid_argument naming the option for bad input); with a
/// `fields_path`, claimed before the solve (an existing file only with `overwrite`), writes the
/// pressure, traction and slip fields there.
[[nodiscard]] MimSolveOutcome solve_mim_files(const MimRequest& request,
                                              const std::string& fields_path, bool overwrite);

/// MimTableSpec::default_spec() built on every hardware thread of the machine.
[[nodiscard]] contact::MimTableSpec machine_table_spec();

struct MimTableRequest {
  std::string out;       ///< HDF5 table to write (required)
  std::string map_path;  ///< CSV of table-versus-direct errors ("": none)
  contact::MimTableSpec spec = machine_table_spec();
  int map_points = 200;  ///< points of the error map, >= 1
  bool overwrite = false;
};

/// Checks the request (std::invalid_argument naming the option), claims the outputs before the
/// build, builds and writes the table, then the error map. `say` receives a line on the table
/// written (nodes, elements, Poisson ratio, build time) once it is, then the error map's report.
void write_mim_table_files(const MimTableRequest& request,
                           const std::function<void(const std::string&)>& say);

}  // namespace ferro::scenarios
