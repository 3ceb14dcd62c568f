// Profile operations: rail inclination, top of rail and gauge point, resampling, smoothing,
// conical treads.
//
// References: EN 13848-1 (gauge 14 mm below the top of rail); EN 13715 (taping line);
// Toumi (2016) ch. 3-4 (1/10 conical-tread variant of S1002).
// Known deviations: smoothing is a plain Gaussian kernel along the arc length (not a
// least-squares smoothing spline).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/geometry/profile.hpp"
#include "param_spline.hpp"

namespace ferro::contact {

Profile incline_rail(const Profile& rail, double inclination) {
  if (!std::isfinite(inclination)) {
    throw std::invalid_argument("incline_rail: inclination must be finite [rad]");
  }
  const double c = std::cos(inclination), s = std::sin(inclination);
  std::vector<double> ry(rail.size()), rz(rail.size());
  for (std::size_t i = 0; i < rail.size(); ++i) {
    ry[i] = c * rail.y[i] + s * rail.z[i];
    rz[i] = -s * rail.y[i] + c * rail.z[i];
  }
  // Keep the part visible from above: walk from the top point outwards on both sides and stop
  // where the rotated flank turns back under the head (an undercut cannot be touched by a
  // wheel and would make the profile multi-valued in y).
  const auto itop = static_cast<std::size_t>(std::min_element(rz.begin(), rz.end()) - rz.begin());
  std::size_t first = itop, last = itop;
  while (first > 0 && ry[first - 1] < ry[first]) --first;
  while (last + 1 < rail.size() && ry[last + 1] > ry[last]) ++last;
  Profile out;
  out.kind = rail.kind;
  for (std::size_t i = first; i <= last; ++i) {
    out.y.push_back(ry[i]);
    out.z.push_back(rz[i]);
    out.line.push_back(i < rail.line.size() ? rail.line[i] : 0);
  }
  out.source = fmt::format("{} inclined by {:.6g} rad", rail.source, inclination);
  check_profile(out);
  return out;
}

RailReference rail_reference(const Profile& rail, double gauge_depth) {
  RailReference r;
  const auto it = std::min_element(rail.z.begin(), rail.z.end());
  const std::size_t itop = static_cast<std::size_t>(it - rail.z.begin());
  r.top_y = rail.y[itop];
  r.top_z = rail.z[itop];
  const double zg = r.top_z + gauge_depth;
  // Walk from the top towards the gauge side (decreasing y) to the first crossing of depth zg.
  for (std::size_t i = itop; i > 0; --i) {
    if (rail.z[i - 1] >= zg && rail.z[i] < zg) {
      const double t = (zg - rail.z[i]) / (rail.z[i - 1] - rail.z[i]);
      r.gauge_y = rail.y[i] + t * (rail.y[i - 1] - rail.y[i]);
      r.gauge_z = zg;
      return r;
    }
  }
  throw std::invalid_argument(fmt::format(
      "{}: the rail profile does not reach {:.3f} mm below the top of rail on its gauge side; "
      "cannot measure the gauge",
      rail.source, gauge_depth * 1e3));
}

Profile resample_profile(const Profile& p, double ds) {
  if (!(ds > 0.0)) throw std::invalid_argument("resample_profile: ds must be > 0 [m]");
  const detail::ParamSpline sp(p.y, p.z);
  const std::size_t n =
      std::max<std::size_t>(4, static_cast<std::size_t>(std::ceil(sp.length() / ds)) + 1);
  Profile out;
  out.kind = p.kind;
  out.source = fmt::format("{} resampled every {:.4g} mm", p.source, ds * 1e3);
  for (std::size_t k = 0; k < n; ++k) {
    const double s = sp.length() * static_cast<double>(k) / static_cast<double>(n - 1);
    const std::size_t i = sp.y.segment(s);
    double y, dy, ddy, z, dz, ddz;
    sp.y.eval(i, s, y, dy, ddy);
    sp.z.eval(i, s, z, dz, ddz);
    out.y.push_back(y);
    out.z.push_back(z);
  }
  out.line.assign(n, 0);
  check_profile(out);
  return out;
}

Profile smooth_profile(const Profile& p, double sigma) {
  if (!(sigma > 0.0)) throw std::invalid_argument("smooth_profile: sigma must be > 0 [m]");
  std::vector<double> s(p.size(), 0.0);
  for (std::size_t i = 1; i < p.size(); ++i) {
    s[i] = s[i - 1] + std::hypot(p.y[i] - p.y[i - 1], p.z[i] - p.z[i - 1]);
  }
  Profile out = p;
  out.source = fmt::format("{} smoothed (sigma {:.4g} mm)", p.source, sigma * 1e3);
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    // Symmetric window truncated at the ends so the end points stay fixed.
    const double half = std::min({3.0 * sigma, s[i] - s.front(), s.back() - s[i]});
    double wsum = 0.0, ysum = 0.0, zsum = 0.0;
    for (std::size_t j = 0; j < p.size(); ++j) {
      const double d = s[j] - s[i];
      if (std::abs(d) > half) continue;
      // Trapezoidal weights so uneven point spacing does not bias the average.
      const double dsj = 0.5 * ((j + 1 < p.size() ? s[j + 1] : s[j]) - (j > 0 ? s[j - 1] : s[j]));
      const double w = std::exp(-0.5 * d * d / (sigma * sigma)) * std::max(dsj, 1e-12);
      wsum += w;
      ysum += w * p.y[j];
      zsum += w * p.z[j];
    }
    if (wsum > 0.0) {
      out.y[i] = ysum / wsum;
      out.z[i] = zsum / wsum;
    }
  }
  check_profile(out);
  return out;
}

Profile make_conical_tread(double conicity, double y_min, double y_max, double step) {
  if (!std::isfinite(conicity) || !(y_max > y_min) || !(step > 0.0)) {
    throw std::invalid_argument(
        "make_conical_tread: need finite conicity, y_max > y_min and step > 0 [m]");
  }
  Profile p;
  p.kind = ProfileKind::wheel;
  p.source = fmt::format("conical tread 1/{:.4g}", 1.0 / conicity);
  const auto n = static_cast<std::size_t>(std::ceil((y_max - y_min) / step)) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = y_min + (y_max - y_min) * static_cast<double>(i) / static_cast<double>(n - 1);
    p.y.push_back(y);
    p.z.push_back(-conicity * y);  // radius grows towards the flange side (negative y)
  }
  p.line.assign(n, 0);
  check_profile(p);
  return p;
}

Profile splice_conical_tread(const Profile& wheel, double conicity, double y_join) {
  Profile out;
  out.kind = ProfileKind::wheel;
  out.source = fmt::format("{} with a 1/{:.4g} conical tread from y = {:.3f} mm", wheel.source,
                           1.0 / conicity, y_join * 1e3);
  double z_join = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i + 1 < wheel.size(); ++i) {
    if (wheel.y[i] <= y_join && wheel.y[i + 1] > y_join) {
      const double t = (y_join - wheel.y[i]) / (wheel.y[i + 1] - wheel.y[i]);
      z_join = wheel.z[i] + t * (wheel.z[i + 1] - wheel.z[i]);
    }
  }
  if (!std::isfinite(z_join)) {
    throw std::invalid_argument(
        fmt::format("splice_conical_tread: y_join = {:.3f} mm is outside the profile {}",
                    y_join * 1e3, wheel.source));
  }
  for (std::size_t i = 0; i < wheel.size() && wheel.y[i] < y_join; ++i) {
    out.y.push_back(wheel.y[i]);
    out.z.push_back(wheel.z[i]);
  }
  const double step = 0.5e-3;
  for (double y = y_join; y <= wheel.y.back() + 1e-12; y += step) {
    out.y.push_back(y);
    out.z.push_back(z_join - conicity * (y - y_join));
  }
  out.line.assign(out.y.size(), 0);
  check_profile(out);
  return out;
}

}  // namespace ferro::contact
