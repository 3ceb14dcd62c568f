#pragma once
// Complete elliptic integrals of the first and second kind, K(k) and E(k), computed together by
// the arithmetic-geometric mean.
//
// References: Abramowitz & Stegun (1964) 17.6 (AGM scheme for K and E).
// Known deviations: none; converges to double precision for modulus k in [0, 1).

namespace ferro::contact {

struct EllipticKE {
  double first = 0.0;   ///< K(k)
  double second = 0.0;  ///< E(k)
};

/// K(k) and E(k) for the modulus k in [0, 1) (same convention as std::comp_ellint_1/2).
/// Throws std::invalid_argument outside that range.
[[nodiscard]] EllipticKE complete_elliptic_integrals(double modulus);

}  // namespace ferro::contact
