#pragma once
// The interpolation family of ferrodyn, one scheme per need, shared by every room:
// - locate(): the cell of a sorted axis and the position in it (clamped at the ends), for
//   piecewise-linear tables and multilinear grids;
// - lerp(): linear interpolation, a + t (b - a) (multilinear grids nest it);
// - HermiteBasis: the cubic Hermite basis on a cell, for tables that carry values and slopes
//   (profiles, irregularities, the MIM table);
// - NaturalCubicSpline: the natural cubic spline through knots, for smooth curves through
//   measured points (profile resampling, imported contact tables).
//
// References: de Boor, "A Practical Guide to Splines" (2001) ch. IV (natural end conditions,
// tridiagonal solve), ch. II (cubic Hermite); Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980)
// (piecewise cubic Hermite interpolation).
// Known deviations: none.

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace ferro::numerics {

/// A position on a sorted axis: the cell between nodes [index] and [index + 1] and the fraction
/// t in [0, 1] across it.
struct AxisCell {
  std::size_t index = 0;
  double t = 0.0;
};

/// The cell of `x` on the strictly increasing `nodes` (at least 2): t = (x - x_i) / (x_i+1 - x_i);
/// x at or beyond an end is clamped to it (index 0 with t = 0, or the last cell with t = 1).
[[nodiscard]] inline AxisCell locate(std::span<const double> nodes, double x) {
  const std::size_t n = nodes.size();
  if (!(x > nodes.front())) return {0, 0.0};
  if (!(x < nodes.back())) return {n - 2, 1.0};
  const auto i =
      static_cast<std::size_t>(std::upper_bound(nodes.begin(), nodes.end(), x) - nodes.begin()) - 1;
  return {i, (x - nodes[i]) / (nodes[i + 1] - nodes[i])};
}

/// a + t (b - a): a at t = 0 (exactly), b at t = 1 (to rounding).
[[nodiscard]] inline double lerp(double a, double b, double t) {
  return a + t * (b - a);
}

/// The piecewise-linear interpolant of (x, y) at `xq`; at or beyond an end, that end's value.
[[nodiscard]] inline double interpolate_linear(std::span<const double> x, std::span<const double> y,
                                               double xq) {
  if (!(xq > x.front())) return y.front();
  if (!(xq < x.back())) return y.back();
  const AxisCell c = locate(x, xq);
  return lerp(y[c.index], y[c.index + 1], c.t);
}

/// Cubic Hermite basis at t in [0, 1] of a cell of length h: the value is
/// h00 y0 + h10 h m0 + h01 y1 + h11 h m1 (y the end values, m the end slopes), its derivative
/// (g00 y0 + g01 y1) / h + g10 m0 + g11 m1.
struct HermiteBasis {
  double h00, h10, h01, h11;  ///< value weights
  double g00, g10, g01, g11;  ///< d/dt of the value weights
  explicit HermiteBasis(double t) {
    const double t2 = t * t, t3 = t2 * t;
    h00 = 2 * t3 - 3 * t2 + 1;
    h10 = t3 - 2 * t2 + t;
    h01 = -2 * t3 + 3 * t2;
    h11 = t3 - t2;
    g00 = 6 * t2 - 6 * t;
    g10 = 3 * t2 - 4 * t + 1;
    g01 = -g00;
    g11 = 3 * t2 - 2 * t;
  }
};

/// Natural cubic spline of values v over strictly increasing knots t (second derivative zero at
/// both ends).
class NaturalCubicSpline {
 public:
  NaturalCubicSpline() = default;
  NaturalCubicSpline(const std::vector<double>& t, const std::vector<double>& v) : t_(t), v_(v) {
    const std::size_t n = t.size();
    m_.assign(n, 0.0);  // second derivatives
    if (n < 3) return;
    std::vector<double> c(n, 0.0), d(n, 0.0);
    // Thomas algorithm for the interior second derivatives.
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double h0 = t[i] - t[i - 1];
      const double h1 = t[i + 1] - t[i];
      const double a = h0 / 6.0;
      const double b = (h0 + h1) / 3.0;
      const double cc = h1 / 6.0;
      const double rhs = (v[i + 1] - v[i]) / h1 - (v[i] - v[i - 1]) / h0;
      const double denom = b - a * c[i - 1];
      c[i] = cc / denom;
      d[i] = (rhs - a * d[i - 1]) / denom;
    }
    for (std::size_t i = n - 2; i >= 1; --i) {
      m_[i] = d[i] - c[i] * m_[i + 1];
      if (i == 1) break;
    }
  }
  /// Segment index containing t (clamped).
  [[nodiscard]] std::size_t segment(double t) const {
    auto it = std::upper_bound(t_.begin(), t_.end(), t);
    std::size_t i = it == t_.begin() ? 0 : static_cast<std::size_t>(it - t_.begin()) - 1;
    return std::min(i, t_.size() - 2);
  }
  /// Value, first and second derivative at t within segment i.
  void eval(std::size_t i, double t, double& f, double& df, double& ddf) const {
    const double h = t_[i + 1] - t_[i];
    const double a = (t_[i + 1] - t) / h;
    const double b = (t - t_[i]) / h;
    f = a * v_[i] + b * v_[i + 1] +
        ((a * a * a - a) * m_[i] + (b * b * b - b) * m_[i + 1]) * h * h / 6.0;
    df = (v_[i + 1] - v_[i]) / h - (3.0 * a * a - 1.0) / 6.0 * h * m_[i] +
         (3.0 * b * b - 1.0) / 6.0 * h * m_[i + 1];
    ddf = a * m_[i] + b * m_[i + 1];
  }
  [[nodiscard]] const std::vector<double>& knots() const { return t_; }

 private:
  std::vector<double> t_, v_, m_;
};

}  // namespace ferro::numerics
