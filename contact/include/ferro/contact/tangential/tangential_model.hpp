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
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ferro/contact/kij/reduction_factors.hpp"
#include "ferro/contact/material.hpp"
#include "ferro/contact/model_options.hpp"
#include "ferro/contact/normal/contact_patch.hpp"
#include "ferro/contact/normal/normal_model.hpp"
#include "ferro/contact/tangential/creepage.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"

namespace ferro::contact {

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

/// One entry of the tangential-model registry: the name a scene, a case file or the command line
/// uses, and the factory that parses the model's own options (each model's header lists them)
/// and builds it. Unknown options throw std::invalid_argument naming the model, the option and
/// the allowed values.
struct TangentialModelEntry {
  std::string_view name;
  std::unique_ptr<TangentialModel> (*make)(const ModelOptions& options);
};

/// Every registered tangential model: kalker_linear (below), linear_saturated,
/// vermeulen_johnson, shen_hedrick_elkins, chopaya (saturation_laws.hpp), polach (polach.hpp),
/// fastsim (fastsim.hpp), fastrip (fastrip.hpp), mim (mim_model.hpp), mim_table (mim_table.hpp).
[[nodiscard]] std::span<const TangentialModelEntry> tangential_models();
/// Their names, in registry order.
[[nodiscard]] std::vector<std::string> tangential_model_names();
/// Creates a model by name through its registry entry. Unknown names throw
/// std::invalid_argument listing the allowed values.
[[nodiscard]] std::unique_ptr<TangentialModel> make_tangential_model(
    std::string_view name, const ModelOptions& options = {});

/// The option "coefficients" that the Kalker-based models share: kalker_table (default) |
/// voco_fit.
[[nodiscard]] CoefficientSource coefficients_option(const ModelOptions& options);

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

/// Kalker's linear theory with K_ij, "kalker_linear": F_x = -G a b C11 xi_x etc. (eqs. 38-40).
/// Option: "coefficients".
class KalkerLinearModel final : public TangentialModel {
 public:
  static std::unique_ptr<TangentialModel> from_options(const ModelOptions& options);
  explicit KalkerLinearModel(CoefficientSource source) : source_(source) {}
  [[nodiscard]] std::string_view name() const override { return "kalker_linear"; }
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;

 private:
  CoefficientSource source_;
};

}  // namespace ferro::contact
