#pragma once
// Private helper: a planar polyline as two natural cubic splines (numerics/interpolation.hpp)
// of its chord length.
//
// References: de Boor, "A Practical Guide to Splines" (natural end conditions, tridiagonal solve).
// Known deviations: none.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "ferro/numerics/interpolation.hpp"

namespace ferro::contact::detail {

/// Planar curve (y(s), z(s)) through the points, s = cumulative chord length.
struct ParamSpline {
  std::vector<double> s;
  numerics::NaturalCubicSpline y, z;
  ParamSpline(const std::vector<double>& py, const std::vector<double>& pz) {
    s.assign(py.size(), 0.0);
    for (std::size_t i = 1; i < py.size(); ++i) {
      s[i] = s[i - 1] + std::max(std::hypot(py[i] - py[i - 1], pz[i] - pz[i - 1]), 1e-12);
    }
    y = numerics::NaturalCubicSpline(s, py);
    z = numerics::NaturalCubicSpline(s, pz);
  }
  [[nodiscard]] double length() const { return s.back(); }
};

}  // namespace ferro::contact::detail
