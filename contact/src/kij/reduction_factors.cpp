// Reduction factors K_ij: their check (see the header).
//
// References: Toumi (2016) eq. (156). Known deviations: none.
#include "ferro/contact/kij/reduction_factors.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace ferro::contact {

void ReductionFactors::validate(const char* where) const {
  const std::pair<double, const char*> f[] = {
      {k11, "k11"}, {k22, "k22"}, {k23, "k23"}, {k33, "k33"}};
  for (const auto& [v, field] : f) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::invalid_argument(
          fmt::format("{}.{}: must be finite and > 0, got {}", where, field, v));
    }
  }
}

}  // namespace ferro::contact
