#pragma once
// Normal-contact models behind one small interface, and their registry by (YAML) name.
//
// References: Toumi (2016) section 1.1 (Hertz eqs. 5-13, semi-Hertz eqs. 17-23).
// Known deviations: see hertz.hpp and semi_hertz.hpp.

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ferro/contact/contact_patch.hpp"
#include "ferro/contact/material.hpp"

namespace ferro::contact {

/// String options of a model, as read from YAML or the command line ("strips" -> "200").
using ModelOptions = std::map<std::string, std::string>;

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

/// Names accepted by make_normal_model: "hertz", "semi_hertz".
[[nodiscard]] std::vector<std::string> normal_model_names();
/// Creates a model by name. Throws std::invalid_argument for an unknown name or option, with
/// the allowed values in the message. Options: semi_hertz: "strips" (default 200), "curvature"
/// (fit | three_point, default fit).
[[nodiscard]] std::unique_ptr<NormalContactModel> make_normal_model(
    std::string_view name, const ModelOptions& options = {});

/// Option helpers shared by the registries (throw std::invalid_argument naming the key).
[[nodiscard]] double option_double(const ModelOptions& options, const std::string& key,
                                   double fallback);
[[nodiscard]] int option_int(const ModelOptions& options, const std::string& key, int fallback);
[[nodiscard]] std::string option_string(const ModelOptions& options, const std::string& key,
                                        const std::string& fallback);
/// Throws std::invalid_argument if options hold a key not in `allowed`.
void check_option_keys(std::string_view model, const ModelOptions& options,
                       const std::vector<std::string>& allowed);

}  // namespace ferro::contact
