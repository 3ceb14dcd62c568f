#pragma once
// Tangential (creep-force) models behind one interface, and their registry by (YAML) name.
//
// Sign convention (all models): creepages are the rigid slip of the WHEEL (body 1) relative to
// the RAIL (body 2) divided by the rolling speed, Toumi eqs. (24)-(27): xi_x, xi_y [-],
// phi [1/m]. Forces and moment are those exerted BY THE RAIL ON THE WHEEL, in the contact frame
// (x rolling direction, y lateral, z normal), moment about the patch centre (y_center for
// semi-Hertz patches): F_x = -G a b C11 xi_x etc. (eqs. 38-40), i.e. the force opposes the
// creepage. Units: N and N m.
//
// References: Toumi (2016) eqs. (38)-(52), (154)-(156); see each model's file.
// Known deviations: see each model's file.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ferro/contact/contact_patch.hpp"
#include "ferro/contact/kalker_coefficients.hpp"
#include "ferro/contact/material.hpp"
#include "ferro/contact/normal_model.hpp"
#include "ferro/contact/reduction_factors.hpp"

namespace ferro::contact {

struct Creepage {
  double longitudinal = 0.0;  ///< xi_x [-]
  double lateral = 0.0;       ///< xi_y [-]
  double spin = 0.0;          ///< phi [1/m]
};

/// Traction picture on a grid (filled by models that resolve the patch, e.g. FASTSIM). One
/// entry per element, strip after strip.
struct TractionMap {
  std::vector<double> x, y;                    ///< element centres [m] (patch frame)
  std::vector<double> dx, dy;                  ///< element sizes [m]
  std::vector<double> pressure;                ///< p_n [Pa]
  std::vector<double> traction_x, traction_y;  ///< on the wheel [Pa]
  std::vector<unsigned char> slip;             ///< 1 = slip, 0 = adhesion
  void clear();
};

struct TangentialProblem {
  const ContactPatch* patch = nullptr;  ///< required
  Creepage creepage;
  double friction = ContactPatch::kNaN;       ///< mu [-]
  Material body1;                             ///< wheel
  Material body2;                             ///< rail
  ReductionFactors reduction;                 ///< K_ij (all 1 = Kalker)
  double rolling_speed = ContactPatch::kNaN;  ///< V [m/s], for slip-speed-dependent friction
  /// Full undeformed gap, for models that solve the contact numerically (MIM); may be null.
  const NormalProblem* gap = nullptr;
  /// Optional output: the traction picture (models that have none leave it empty).
  TractionMap* map = nullptr;
  /// Throws std::invalid_argument naming the field.
  void validate() const;
};

struct TangentialSolution {
  double force_x = 0.0;                           ///< F_x on the wheel [N]
  double force_y = 0.0;                           ///< F_y on the wheel [N]
  double moment_z = 0.0;                          ///< M_z on the wheel [N m]
  double adhesion_fraction = ContactPatch::kNaN;  ///< adhesion area / patch area (NaN if n/a)
};

class TangentialModel {
 public:
  virtual ~TangentialModel() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  [[nodiscard]] virtual TangentialSolution solve(const TangentialProblem& problem) const = 0;
};

/// Registered names: kalker_linear, linear_saturated, vermeulen_johnson, shen_hedrick_elkins,
/// chopaya, polach, fastsim, fastrip (fastrip.hpp), mim (mim_tangential_model.hpp), mim_table
/// (mim_table.hpp).
[[nodiscard]] std::vector<std::string> tangential_model_names();

/// Creates a model. Common option: "coefficients" = kalker_table (default) | voco_fit.
/// linear_saturated, vermeulen_johnson, shen_hedrick_elkins, chopaya: "spin_moment" = true
/// (default) | false (no moment about the contact normal). polach: "k_a", "k_s" (default 1), "friction_ratio" (A, default 1), "friction_decay" (B [s/m],
/// default 0). fastsim: "mx", "my" (default 20, 20),
/// "flexibility" = three (default) | weighted | adaptive, "stiffening" (adaptive, default 0.05),
/// "bound" = parabolic (default) | elliptic. fastrip: "mx", "my" (default 12, 12),
/// "slip_flexibility" = longitudinal (default) | weighted | three.
/// mim: "elements" (default 30), "grid" = minor (default: N square elements across the shorter
/// axis, so N x 5N at a/b = 5) | patch (N x N rectangular elements over the ellipse).
/// mim_table: "table" (HDF5 path, default $FERRO_MIM_TABLE). Unknown names/options throw
/// std::invalid_argument listing the allowed values.
[[nodiscard]] std::unique_ptr<TangentialModel> make_tangential_model(
    std::string_view name, const ModelOptions& options = {});

/// Linear-theory quantities of a patch, with K_ij applied (C_ij,r = K_ij C_ij).
struct LinearCreepStiffness {
  KalkerCoefficients c;        ///< reduced coefficients
  double shear_modulus = 0.0;  ///< combined G [Pa]
  double poisson = 0.0;        ///< combined nu [-]
  double a = 0.0, b = 0.0;     ///< semi-axes used [m]
  /// F_x, F_y, M_z of Kalker's linear theory (eqs. 38-40) for the given creepages.
  [[nodiscard]] TangentialSolution forces(const Creepage& c) const;
};
[[nodiscard]] LinearCreepStiffness linear_creep_stiffness(const TangentialProblem& problem,
                                                          CoefficientSource source);

}  // namespace ferro::contact
