// References: Abramowitz & Stegun (1964) 17.6.
// Known deviations: none.
#include "ferro/contact/elliptic_integrals.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ferro::contact {

EllipticKE complete_elliptic_integrals(double modulus) {
  if (!(modulus >= 0.0 && modulus < 1.0)) {
    throw std::invalid_argument(
        fmt::format("complete_elliptic_integrals: modulus must lie in [0, 1), got {}", modulus));
  }
  // AGM: a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n), c_{n+1} = (a_n - b_n)/2,
  // K = pi / (2 a_inf), E = K (1 - sum_n 2^{n-1} c_n^2) with c_0 = k.
  double a = 1.0;
  double b = std::sqrt((1.0 - modulus) * (1.0 + modulus));
  double sum = 0.5 * modulus * modulus;
  double weight = 0.5;
  for (int iter = 0; iter < 40; ++iter) {
    const double c = 0.5 * (a - b);
    weight *= 2.0;
    sum += weight * c * c;
    const double a_next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = a_next;
    if (std::abs(c) <= 1e-17 * a) break;
  }
  EllipticKE out;
  out.first = std::numbers::pi / (2.0 * a);
  out.second = out.first * (1.0 - sum);
  return out;
}

}  // namespace ferro::contact
