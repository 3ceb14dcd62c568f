#pragma once
// Private helper: natural cubic spline of a planar polyline, parameterised by chord length.
//
// References: de Boor, "A Practical Guide to Splines" (natural end conditions, tridiagonal solve).
// Known deviations: none.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ferro::contact::detail {

/// One coordinate of a natural cubic spline over knots t (strictly increasing).
class CubicSpline1 {
 public:
  CubicSpline1() = default;
  CubicSpline1(const std::vector<double>& t, const std::vector<double>& v) : t_(t), v_(v) {
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

/// Planar curve (y(s), z(s)) through the points, s = cumulative chord length.
struct ParamSpline {
  std::vector<double> s;
  CubicSpline1 y, z;
  ParamSpline(const std::vector<double>& py, const std::vector<double>& pz) {
    s.assign(py.size(), 0.0);
    for (std::size_t i = 1; i < py.size(); ++i) {
      s[i] = s[i - 1] + std::max(std::hypot(py[i] - py[i - 1], pz[i] - pz[i - 1]), 1e-12);
    }
    y = CubicSpline1(s, py);
    z = CubicSpline1(s, pz);
  }
  [[nodiscard]] double length() const { return s.back(); }
};

}  // namespace ferro::contact::detail
