#pragma once
// Normal-contact models behind one small interface, and their registry by (YAML) name.
//
// References: Toumi (2016) section 1.1 (Hertz eqs. 5-13, semi-Hertz eqs. 17-23).
// Known deviations: see hertz.hpp and semi_hertz.hpp.

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ferro/contact/material.hpp"
#include "ferro/contact/model_options.hpp"
#include "ferro/contact/normal/contact_patch.hpp"

namespace ferro::contact {

/// Undeformed gap of a contact and the load. Hertz needs curvature_x and curvature_y;
/// semi-Hertz needs curvature_x and the lateral gap samples (gap_y strictly increasing).
struct NormalProblem {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double curvature_x = kNaN;   ///< A: longitudinal relative curvature, gap = A x^2 + ... [1/m]
  double curvature_y = kNaN;   ///< B: lateral relative curvature (Hertz) [1/m]
  std::vector<double> gap_y;   ///< lateral sample positions [m] (semi-Hertz)
  std::vector<double> gap_z;   ///< undeformed gap z(y) at gap_y [m] (semi-Hertz)
  double normal_force = kNaN;  ///< F_n [N]
  Material body1;              ///< wheel
  Material body2;              ///< rail
};

/// Result: one or several patches (disconnected lobes become separate patches).
struct NormalSolution {
  std::vector<ContactPatch> patches;
  double approach = ContactPatch::kNaN;  ///< rigid approach delta [m] (NaN if not defined)
};

class NormalContactModel {
 public:
  virtual ~NormalContactModel() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  [[nodiscard]] virtual NormalSolution solve(const NormalProblem& problem) const = 0;
};

/// One entry of the normal-model registry: the name a scene, a case file or the command line
/// uses, and the factory that parses the model's own options and builds it.
struct NormalModelEntry {
  std::string_view name;
  std::unique_ptr<NormalContactModel> (*make)(const ModelOptions& options);
};

/// Every registered normal model: "hertz" (no options) and "semi_hertz" (options "strips",
/// default 200; "curvature" = fit | three_point, default fit).
[[nodiscard]] std::span<const NormalModelEntry> normal_models();
/// Their names, in registry order.
[[nodiscard]] std::vector<std::string> normal_model_names();
/// Creates a model by name. Throws std::invalid_argument for an unknown name or option, with
/// the allowed values in the message.
[[nodiscard]] std::unique_ptr<NormalContactModel> make_normal_model(
    std::string_view name, const ModelOptions& options = {});

}  // namespace ferro::contact
