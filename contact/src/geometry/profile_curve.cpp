// Tabulation of a profile on a uniform y grid for O(1) evaluation.
//
// References: Fritsch & Carlson (1980) for the slope limiter.
// Known deviations: see profile_curve.hpp (slopes clamped at kMaxSlope).

#include "ferro/contact/geometry/profile_curve.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "param_spline.hpp"

namespace ferro::contact {

ProfileCurve::ProfileCurve(const Profile& p, double step) {
  if (!(step > 0.0) || p.size() < 4) {
    throw std::invalid_argument(
        fmt::format("{}: ProfileCurve needs step > 0 and at least 4 points", p.source));
  }
  const detail::ParamSpline sp(p.y, p.z);
  const double ya = p.y.front(), yb = p.y.back();
  n_ = static_cast<std::size_t>(std::floor((yb - ya) / step)) + 1;
  if (n_ < 2) throw std::invalid_argument(fmt::format("{}: profile too narrow", p.source));
  y0_ = ya;
  h_ = step;
  inv_h_ = 1.0 / step;
  z_.resize(n_);
  dz_.resize(n_);
  ddz_.resize(n_);
  std::size_t seg = 0;
  for (std::size_t k = 0; k < n_; ++k) {
    const double yk = std::min(ya + step * static_cast<double>(k), yb);
    while (seg + 2 < p.size() && p.y[seg + 1] < yk) ++seg;
    // Solve y(s) = yk on [s_seg, s_seg+1] by safeguarded Newton (bisection fallback).
    double lo = sp.s[seg], hi = sp.s[seg + 1];
    double s = lo + (hi - lo) * (yk - p.y[seg]) / (p.y[seg + 1] - p.y[seg]);
    double y = 0, dy = 1, ddy = 0;
    for (int it = 0; it < 60; ++it) {
      sp.y.eval(seg, s, y, dy, ddy);
      const double f = y - yk;
      if (std::abs(f) < 1e-13) break;
      if (f > 0)
        hi = s;
      else
        lo = s;
      double sn = dy > 0 ? s - f / dy : 0.5 * (lo + hi);
      if (!(sn > lo && sn < hi)) sn = 0.5 * (lo + hi);
      s = sn;
    }
    double z, dzs, ddzs;
    sp.y.eval(seg, s, y, dy, ddy);
    sp.z.eval(seg, s, z, dzs, ddzs);
    z_[k] = z;
    double slope = dy > 1e-12 ? dzs / dy : (dzs > 0 ? kMaxSlope : -kMaxSlope);
    double curv = dy > 1e-12 ? (ddzs * dy - dzs * ddy) / (dy * dy * dy) : 0.0;
    if (std::abs(slope) > kMaxSlope) {
      slope = std::copysign(kMaxSlope, slope);
      curv = 0.0;
    }
    dz_[k] = slope;
    ddz_[k] = curv;
  }
  // Limit node slopes so the Hermite pieces cannot overshoot (Fritsch-Carlson, factor 3).
  for (std::size_t k = 0; k < n_; ++k) {
    const double dl = k > 0 ? (z_[k] - z_[k - 1]) * inv_h_ : (z_[1] - z_[0]) * inv_h_;
    const double dr = k + 1 < n_ ? (z_[k + 1] - z_[k]) * inv_h_ : dl;
    const double lim = 3.0 * std::min(std::abs(dl), std::abs(dr));
    if (dl * dr <= 0.0) continue;  // local extremum: keep the exact slope (small there)
    if (std::abs(dz_[k]) > lim) dz_[k] = std::copysign(lim, dz_[k]);
  }
}

}  // namespace ferro::contact
