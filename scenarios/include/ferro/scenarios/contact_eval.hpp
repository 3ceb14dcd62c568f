#pragma once
// One Hertzian evaluation of a tangential contact model, alone or as a CSV batch of cases
// (`ferrodyn contact eval [--batch]`). Forces and moment are those of the rail on the wheel
// (F_x = -G a b C11 xi_x in the linear range); SI units throughout.

#include <istream>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <span>
#include <string>

#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/scenarios/parameters.hpp"

namespace ferro::scenarios {

/// One case. The patch is given either by its semi-axes (a, b) or by the relative curvatures
/// (A, B), never both.
struct EvalInput {
  static constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
  double a = kUnset, b = kUnset;                      ///< semi-axes [m]
  double curvature_x = kUnset, curvature_y = kUnset;  ///< A, B [1/m]
  double fn = kUnset;                                 ///< normal load [N]
  double g1 = 82e9, nu1 = 0.28, g2 = 82e9, nu2 = 0.28;  ///< [Pa], [-] (steel by default)
  double mu = kUnset;                                   ///< friction coefficient [-]
  double xi_x = 0.0, xi_y = 0.0, phi = 0.0;  ///< creepages [-], [-], spin [1/m]
  std::string model = "fastsim";             ///< tangential model name (make_tangential_model)
  /// K_ij; K23 NaN (unset): K23 = K22 (Toumi 4.2.4).
  contact::ReductionFactors reduction{1.0, 1.0, kUnset, 1.0};
  /// K_ij table (overrides k11..k33): looked up at table_point, the normal_force and
  /// peak_pressure axes filled from the patch when not given.
  std::shared_ptr<const contact::KijTable> table;
  std::map<std::string, double> table_point;
};

/// A case's values as parameters (see parameters.hpp): the table and its point are not among
/// them.
[[nodiscard]] Parameters parameters(EvalInput& input);

struct EvalOutput {
  contact::ContactPatch patch;
  contact::NormalProblem gap;  ///< the quadratic gap A x^2 + B y^2, for models that need it (MIM)
  contact::TangentialSolution forces;
  contact::KalkerCoefficients c;  ///< C_ij used (K_ij applied), table or fit per `source`
};

/// Solves one case with `model`. Throws std::invalid_argument naming the option (--a, --fn, ...)
/// for bad input, or when the model's result is not finite.
[[nodiscard]] EvalOutput evaluate_contact(const EvalInput& in,
                                          const contact::TangentialModel& model,
                                          contact::CoefficientSource source);

/// Caller-owned output columns of evaluate_contact_columns, each empty (not wanted) or one value
/// per case: patch [m, Pa], forces on the wheel [N, N m], adhesion fraction [-], C_ij used [-].
struct EvalOutputColumns {
  std::span<double> semi_axis_x, semi_axis_y, peak_pressure;
  std::span<double> force_x, force_y, moment_z, adhesion_fraction;
  std::span<double> c11, c22, c23, c33;
};

/// Solves n cases with `model`: each input column, named by a key of parameters(EvalInput)
/// (a, b, curvature_x, curvature_y, fn, g1, nu1, g2, nu2, mu, xi_x, xi_y, spin, k11, k22, k23,
/// k33), holds n values or one for every case; the other fields are those of `defaults`. The
/// same arithmetic as evaluate_contact, case after case. Throws std::invalid_argument naming an
/// unknown key, a column of the wrong length, or the case and the bad value.
void evaluate_contact_columns(const EvalInput& defaults,
                              const std::map<std::string, std::span<const double>>& inputs,
                              std::size_t n, const contact::TangentialModel& model,
                              contact::CoefficientSource source, const EvalOutputColumns& out);

/// n normal-contact cases with `model` on `base` (materials, gap samples): the normal force and
/// the curvatures A, B from columns (n values or one; empty: the base's). Per case the rigid
/// approach [m]; per patch (several per case for a split semi-Hertz contact) its case index and
/// the patch itself.
struct NormalCases {
  std::vector<double> approach;
  std::vector<std::size_t> patch_case;
  std::vector<contact::ContactPatch> patches;
};
[[nodiscard]] NormalCases solve_normal_cases(const contact::NormalContactModel& model,
                                             const contact::NormalProblem& base, std::size_t n,
                                             std::span<const double> normal_force,
                                             std::span<const double> curvature_x,
                                             std::span<const double> curvature_y);

/// CSV batch: a header naming EvalInput's fields (a, b, curvature_x, curvature_y, fn, g1, nu1,
/// g2, nu2, mu, xi_x, xi_y, phi or spin, k11, k22, k23, k33, model), then one case per row; an
/// empty cell keeps the value of `defaults`. Writes a header and one CSV row per case to `out`
/// as each is solved, every number in the shortest text that reads back as the same double. Throws std::invalid_argument located as "<input_name>:<line>: ...".
void evaluate_contact_batch(std::istream& in, const std::string& input_name,
                            const EvalInput& defaults, const contact::ModelOptions& options,
                            contact::CoefficientSource source, std::ostream& out);

}  // namespace ferro::scenarios
