#pragma once
// Creep curves and patch pictures of a contact case (`ferrodyn contact curve|patch`).
// Forces are on the wheel from the rail (see ferro/contact/tangential/tangential_model.hpp); SI units.

#include <string>
#include <vector>

#include "ferro/scenarios/contact_case.hpp"

namespace ferro::scenarios {

struct CurvePoint {
  std::string curve;      ///< longitudinal | lateral | spin | combined
  std::string model;      ///< model label
  double creepage = 0.0;  ///< swept creepage: xi_x, xi_y [-], phi [1/m], or |xi| (combined)
  double force_x = 0.0, force_y = 0.0, moment_z = 0.0;  ///< [N], [N m], summed over patches
};

/// Throws std::invalid_argument when a force or the moment of `s` is not finite: the input
/// was outside the range the model's arithmetic holds (overflow), and a NaN or infinite force
/// must never be printed or written as a result. `what` names the model and the input.
void require_finite_forces(const contact::TangentialSolution& s, const std::string& what);

/// Every enabled curve for every model of the case, on the patches of `normal`.
[[nodiscard]] std::vector<CurvePoint> compute_creep_curves(const ContactCase& c,
                                                           const contact::NormalSolution& normal);
void write_curves_csv(const std::string& path, const std::vector<CurvePoint>& points);
/// HDF5: /<curve>/<model label>/{creepage, force_x, force_y, moment_z}; root attributes
/// schema_version = 1, units = "SI: creepage [-] or [1/m] (spin), force [N], moment [N m]".
void write_curves_hdf5(const std::string& path, const std::vector<CurvePoint>& points);

/// One element of the patch picture (all patches, gap frame).
struct PatchCell {
  int patch = 0;
  double x = 0.0, y = 0.0, dx = 0.0, dy = 0.0;  ///< [m]
  double pressure = 0.0;                        ///< normal model's pressure [Pa]
  double traction_x = 0.0, traction_y = 0.0;    ///< [Pa] on the wheel
  int slip = 0;
};
struct PatchPicture {
  std::vector<PatchCell> cells;
  std::vector<contact::TangentialSolution> forces;  ///< per patch
};
/// Runs the case's patch model (it must fill a traction map, e.g. fastsim) on every patch.
[[nodiscard]] PatchPicture compute_patch_picture(const ContactCase& c,
                                                 const contact::NormalSolution& normal);
void write_patch_csv(const std::string& path, const PatchPicture& picture);

}  // namespace ferro::scenarios
