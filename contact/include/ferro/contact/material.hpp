#pragma once
// Elastic constants of the two bodies in contact and their combination.
//
// References: Toumi (2016) eqs. (58)-(59); Kalker, "Three-dimensional elastic bodies in rolling
// contact" (1990) for the quasi-identity assumption.
// Known deviations: none; the combination is exact for the half-space model.

#include <cmath>
#include <limits>
#include <string>

namespace ferro::contact {

/// Isotropic linear-elastic material. SI units.
struct Material {
  double shear_modulus = std::numeric_limits<double>::quiet_NaN();  ///< G [Pa]
  double poisson = std::numeric_limits<double>::quiet_NaN();        ///< nu [-]

  /// Young's modulus E = 2 G (1 + nu) [Pa].
  [[nodiscard]] double young() const { return 2.0 * shear_modulus * (1.0 + poisson); }
  /// Throws std::invalid_argument naming `where` when G <= 0 or nu outside [0, 0.5).
  void validate(const std::string& where = "material") const;

  static Material from_young(double young_modulus, double poisson_ratio) {
    return Material{young_modulus / (2.0 * (1.0 + poisson_ratio)), poisson_ratio};
  }
  static Material steel() { return Material{82.0e9, 0.28}; }
};

/// Combined constants of two bodies: 1/G = (1/G1 + 1/G2)/2, nu/G = (nu1/G1 + nu2/G2)/2
/// (Toumi eqs. 58-59), and the Hertz contact modulus E* with 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
struct CombinedMaterial {
  double shear_modulus = 0.0;    ///< G [Pa]
  double poisson = 0.0;          ///< nu [-]
  double contact_modulus = 0.0;  ///< E* [Pa]
};

[[nodiscard]] CombinedMaterial combine(const Material& body1, const Material& body2);

}  // namespace ferro::contact
