#pragma once
// MIM (boundary-element) rolling contact as a user asks for it: one solve on a Hertz ellipse
// (`ferrodyn contact mim`: the request in SI, its check naming the request's keys, the report)
// and the tabulated-MIM table (`ferrodyn contact mim-table`: the build options as parameters,
// their check, the error map against direct MIM).

#include <limits>
#include <string>

#include "ferro/contact/mim/mim.hpp"
#include "ferro/contact/tangential/mim_table.hpp"
#include "ferro/scenarios/parameters.hpp"

namespace ferro::scenarios {

struct MimRequest {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double a = kNaN, b = kNaN;  ///< semi-axes along the rolling direction and lateral [m]
  double fn = kNaN;           ///< normal force [N]
  double xi_x = 0.0;          ///< longitudinal creepage [-]
  double xi_y = 0.0;          ///< lateral creepage [-]
  double spin = 0.0;          ///< spin creepage [1/m]
  double mu = 0.3;            ///< friction coefficient [-]
  double young = 210.0e9;     ///< Young's modulus of both bodies [Pa]
  double poisson = 0.28;      ///< Poisson's ratio of both bodies [-]
  int elements = 40;          ///< elements across the shorter axis [-]
};
[[nodiscard]] Parameters parameters(MimRequest& request);

/// The solver's input; throws std::invalid_argument naming the request's key.
[[nodiscard]] contact::mim::HertzRollingInput mim_input(const MimRequest& request,
                                                        Spelling spelling = Spelling::key);

/// Grid, stick and slip elements, forces (also over mu F_n), approach, convergence, the CPU
/// time given [ms], and a warning when the patch reaches the grid's edge.
[[nodiscard]] std::string mim_report(const MimRequest& request,
                                     const contact::mim::MimResult& result, double milliseconds);

/// The table's build options as parameters: elements, grid, threads, poisson, density.
[[nodiscard]] Parameters parameters(contact::MimTableSpec& spec);
/// spec.validate() with the messages naming the parameters' keys.
void check_mim_table_spec(const contact::MimTableSpec& spec, Spelling spelling = Spelling::key);

/// Writes the error map (ratio, xi_x, xi_y, phi, table and direct forces, error in mu F_n) as
/// CSV to `path` and returns its summary line: mean, 95th percentile and largest error, naming
/// the file `shown` (empty: `path`; e.g. the final name of a file written under a temporary one).
std::string write_mim_table_error_map(const std::vector<contact::MimTableErrorPoint>& map,
                                      const std::string& path, const std::string& shown = {});

}  // namespace ferro::scenarios
