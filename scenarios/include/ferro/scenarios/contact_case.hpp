#pragma once
// A contact case file (YAML): geometry, load, materials, friction, K_ij, the models to compare
// and the creep-curve / patch-picture requests. Read by `ferrodyn contact curve|patch`.
// Layout: see scenarios/cases/contact/thesis_spheres.yaml (every key documented there).

#include <limits>
#include <string>
#include <vector>

#include "ferro/contact/kij/reduction_factors.hpp"
#include "ferro/contact/normal/normal_model.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"

namespace ferro::scenarios {

struct NamedModel {
  std::string name;
  contact::ModelOptions options;
  [[nodiscard]] std::string label() const;  ///< "fastsim(mx=40,my=40)"
};

struct CurveRequest {
  bool enabled = false;
  double max =
      std::numeric_limits<double>::quiet_NaN();  ///< largest |creepage| (xi [-], phi [1/m])
  int points = 101;
  double angle_deg = 45.0;  ///< combined curve: xi_x = s cos(angle), xi_y = s sin(angle)
};

struct ContactCase {
  static constexpr int kSchemaVersion = 1;
  std::string name;
  std::string normal_model = "hertz";
  contact::ModelOptions normal_options;
  contact::NormalProblem normal;  ///< curvatures / gap, load, materials (SI)
  double approach = std::numeric_limits<double>::quiet_NaN();  ///< if set, load from delta [m]
  double friction = std::numeric_limits<double>::quiet_NaN();
  contact::ReductionFactors reduction;
  std::vector<NamedModel> models;
  CurveRequest longitudinal, lateral, spin, combined;
  NamedModel patch_model{"fastsim", {{"mx", "60"}, {"my", "60"}}};
  contact::Creepage patch_creepage{2e-3, 0.0, 0.0};
};

/// Reads and validates a case file; std::invalid_argument names the file and key on bad input.
[[nodiscard]] ContactCase load_contact_case(const std::string& path);

/// Solves the normal problem of a case (converting an imposed approach into the load first).
[[nodiscard]] contact::NormalSolution solve_case_normal(ContactCase& c);

}  // namespace ferro::scenarios
