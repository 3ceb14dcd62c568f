// Complete elliptic integrals of the first and second kind, K(k) and E(k), modulus convention
// (the same as std::comp_ellint_1/2), by the arithmetic-geometric mean.
//
// References: Abramowitz & Stegun (1964) 17.6.1-17.6.4: with a0 = 1, b0 = sqrt(1 - k^2),
// c0 = k and a(n+1) = (a(n) + b(n))/2, b(n+1) = sqrt(a(n) b(n)), c(n+1) = (a(n) - b(n))/2,
// K = pi / (2 a(N)) and E = K (1 - sum_{n=0..N} 2^(n-1) c(n)^2).
// Known deviations: none; the iteration converges quadratically and stops when c(n) falls
// below 1e-16 a(n) (5-7 iterations for k <= 1 - 1e-12), so both integrals carry the full
// double precision of the libstdc++ Carlson forms at a fraction of their cost (the Hertz
// solve calls them at every contact point of every right-hand side).
#pragma once

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ferro::contact {

struct CompleteEllipticIntegrals {
  double first = 0.0;   ///< K(k)
  double second = 0.0;  ///< E(k)
};

/// K(k) and E(k) for the modulus 0 <= k < 1 (std::invalid_argument otherwise).
[[nodiscard]] inline CompleteEllipticIntegrals complete_elliptic_integrals(double modulus) {
  if (!(modulus >= 0.0 && modulus < 1.0)) {
    throw std::invalid_argument("complete_elliptic_integrals: the modulus must lie in [0, 1)");
  }
  double a = 1.0;
  double b = std::sqrt((1.0 - modulus) * (1.0 + modulus));
  double c = modulus;
  double power = 0.5;  // 2^(n-1)
  double sum = power * c * c;
  for (int n = 0; n < 40 && std::abs(c) > 1e-16 * a; ++n) {
    const double a_next = 0.5 * (a + b);
    c = 0.5 * (a - b);
    b = std::sqrt(a * b);
    a = a_next;
    power *= 2.0;
    sum += power * c * c;
  }
  const double k = std::numbers::pi / (2.0 * a);
  return {k, k * (1.0 - sum)};
}

}  // namespace ferro::contact
