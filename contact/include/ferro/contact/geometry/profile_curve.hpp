#pragma once
// Fast evaluation of a profile z(y): the profile is resampled once onto a uniform y grid along a
// chord-length cubic spline through its points (so corners between points are not cut), then
// evaluated in O(1) by cubic Hermite interpolation of z and dz/dy; d2z/dy2 is interpolated
// linearly. Units: metres.
//
// References: Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980) (slope limiting that keeps the
// Hermite interpolant free of overshoot near near-vertical faces).
// Known deviations: parts of a profile steeper than |dz/dy| = kMaxSlope (about 89.4 deg: rail
// gauge face far below the corner, wheel flange back) are represented with the slope clamped;
// no contact occurs there on the profiles handled here.

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "ferro/contact/geometry/profile.hpp"
#include "ferro/numerics/interpolation.hpp"

namespace ferro::contact {

class ProfileCurve {
 public:
  static constexpr double kMaxSlope = 100.0;

  ProfileCurve() = default;
  /// Tabulates `profile` every `step` [m] over its y range.
  ProfileCurve(const Profile& profile, double step);

  [[nodiscard]] double y_min() const { return y0_; }
  [[nodiscard]] double y_max() const { return y0_ + h_ * static_cast<double>(n_ - 1); }
  [[nodiscard]] bool contains(double y) const { return y >= y_min() && y <= y_max(); }

  /// z and dz/dy at y (clamped to the range; check `contains` first).
  void eval(double y, double& z, double& dz) const {
    const auto [i, t] = cell(y);
    const double z0 = z_[i], z1 = z_[i + 1], d0 = dz_[i] * h_, d1 = dz_[i + 1] * h_;
    const numerics::HermiteBasis b(t);
    z = b.h00 * z0 + b.h10 * d0 + b.h01 * z1 + b.h11 * d1;
    dz = (b.g00 * z0 + b.g10 * d0 + b.g01 * z1 + b.g11 * d1) * inv_h_;
  }
  /// z, dz/dy and d2z/dy2 at y.
  void eval2(double y, double& z, double& dz, double& ddz) const {
    eval(y, z, dz);
    const auto [i, t] = cell(y);
    ddz = (1.0 - t) * ddz_[i] + t * ddz_[i + 1];
  }
  [[nodiscard]] double z(double y) const {
    double v, d;
    eval(y, v, d);
    return v;
  }
  /// Curvature of the profile seen from the side of smaller z (positive when convex towards
  /// negative z, i.e. when z has a minimum): z'' / (1 + z'^2)^(3/2) [1/m].
  [[nodiscard]] double curvature(double y) const {
    double v, d, dd;
    eval2(y, v, d, dd);
    return dd / std::pow(1.0 + d * d, 1.5);
  }
  [[nodiscard]] double step() const { return h_; }
  [[nodiscard]] std::size_t size() const { return n_; }

 private:
  // Sample interval i and local coordinate t in [0, 1) of y, clamped to the range.
  [[nodiscard]] std::pair<std::size_t, double> cell(double y) const {
    double u = (y - y0_) * inv_h_;
    if (u < 0.0) u = 0.0;
    const double umax = static_cast<double>(n_ - 1) - 1e-9;
    if (u > umax) u = umax;
    const auto i = static_cast<std::size_t>(u);
    return {i, u - static_cast<double>(i)};
  }

  double y0_ = 0.0, h_ = 1.0, inv_h_ = 1.0;
  std::size_t n_ = 0;
  std::vector<double> z_, dz_, ddz_;
};

}  // namespace ferro::contact
