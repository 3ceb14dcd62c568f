// Design alignment: section start states and the moving track frame.
//
// References: EN 13803:2017 (clothoid and linear cant ramp); Abramowitz & Stegun (1964) 25.4.29
// (Gauss-Legendre quadrature, here Boost.Math's boost::math::quadrature::gauss).
// Known deviations: see alignment.hpp (quadrature instead of Fresnel integrals; the one-sided
// cant second derivative at ramp ends).

#include "ferro/track/alignment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace ferro::track {
namespace {

// Gauss-Legendre with 8 nodes per panel.
using GaussLegendre8 = boost::math::quadrature::gauss<double, 8>;
// Largest heading change over one quadrature panel [rad]. With 8 nodes the quadrature error of
// a cosine of a quadratic phase that varies by 0.5 rad is ~(0.25)^16/16! of the panel length.
constexpr double kMaxPanelTurn = 0.5;

// sin(x)/x, accurate near 0.
double sinc(double x) {
  if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
  return std::sin(x) / x;
}

}  // namespace

Eigen::Vector3d TrackFrame::angular_rate_per_length() const {
  return angular_rate_per_length(std::sin(cant_angle), std::cos(cant_angle));
}

Eigen::Vector3d TrackFrame::d_angular_rate_per_length() const {
  return d_angular_rate_per_length(std::sin(cant_angle), std::cos(cant_angle));
}

Eigen::Vector3d TrackFrame::angular_rate_per_length(double sp, double cp) const {
  return {-d_cant_angle, -curvature * sp, curvature * cp};
}

Eigen::Vector3d TrackFrame::d_angular_rate_per_length(double sp, double cp) const {
  return {-dd_cant_angle, -d_curvature * sp - curvature * cp * d_cant_angle,
          d_curvature * cp - curvature * sp * d_cant_angle};
}

Eigen::Vector3d TrackFrame::left_rail_position() const {
  return position + 0.5 * rail_spacing * rotation.col(1);
}

Eigen::Vector3d TrackFrame::right_rail_position() const {
  return position - 0.5 * rail_spacing * rotation.col(1);
}

Alignment::Alignment(const TrackDesign& design) : design_(design) {
  design_.validate();
  const auto& secs = design_.sections;
  const std::size_t n = secs.size();
  // End values of every section (curvature, cant, widening); transitions filled below.
  auto own_curvature = [&](std::size_t i) {
    return secs[i].kind == SectionKind::kCurve ? 1.0 / secs[i].radius : 0.0;
  };
  starts_.resize(n);
  double s = design_.start_s, x = design_.start_x, y = design_.start_y;
  double heading = design_.start_heading;
  for (std::size_t i = 0; i < n; ++i) {
    SectionState& st = starts_[i];
    const SectionSpec& sec = secs[i];
    st.s = s;
    st.length = sec.length;
    st.x = x;
    st.y = y;
    st.heading = heading;
    if (sec.kind == SectionKind::kTransition) {
      // Neighbours are never transitions (validated); the track ends count as straight.
      const double k0 = i > 0 ? own_curvature(i - 1) : 0.0;
      const double k1 = i + 1 < n ? own_curvature(i + 1) : 0.0;
      const double c0 = i > 0 ? secs[i - 1].cant : 0.0;
      const double c1 = i + 1 < n ? secs[i + 1].cant : 0.0;
      const double w0 = i > 0 ? secs[i - 1].gauge_widening : 0.0;
      const double w1 = i + 1 < n ? secs[i + 1].gauge_widening : 0.0;
      st.curvature = k0;
      st.d_curvature = (k1 - k0) / sec.length;
      st.cant = c0;
      st.d_cant = (c1 - c0) / sec.length;
      st.widening = w0;
      st.d_widening = (w1 - w0) / sec.length;
    } else {
      st.curvature = own_curvature(i);
      st.cant = sec.cant;
      st.widening = sec.gauge_widening;
    }
    // Advance to the section end.
    const Eigen::Vector2d d = plan_offset(st, sec.length);
    x += d.x();
    y += d.y();
    heading += st.curvature * sec.length + 0.5 * st.d_curvature * sec.length * sec.length;
    s += sec.length;
  }
  end_s_ = s;
}

Eigen::Vector2d Alignment::plan_offset(const SectionState& st, double u) {
  const double k0 = st.curvature, dk = st.d_curvature;
  if (dk == 0.0) {
    // Circular arc (or straight): chord of length u sinc(k u / 2) along heading + k u / 2.
    const double half_turn = 0.5 * k0 * u;
    const double chord = u * sinc(half_turn);
    const double dir = st.heading + half_turn;
    return {chord * std::cos(dir), chord * std::sin(dir)};
  }
  // Clothoid: integrate (cos, sin) of the heading change theta(v) = k0 v + dk v^2 / 2 over
  // [0, u] by Gauss-Legendre on panels of bounded turn, then rotate by the start heading.
  const double k_max = std::max(std::abs(k0), std::abs(k0 + dk * u));
  const int panels = std::max(1, static_cast<int>(std::ceil(k_max * u / kMaxPanelTurn)));
  const double h = u / panels;
  // Tangent (cos theta, sin theta) as the complex exp(i theta).
  const auto tangent = [k0, dk](double v) { return std::polar(1.0, v * (k0 + 0.5 * dk * v)); };
  std::complex<double> chord(0.0, 0.0);
  for (int p = 0; p < panels; ++p) chord += GaussLegendre8::integrate(tangent, p * h, (p + 1) * h);
  const double cx = chord.real(), cy = chord.imag();
  const double ch = std::cos(st.heading), sh = std::sin(st.heading);
  return {ch * cx - sh * cy, sh * cx + ch * cy};
}

int Alignment::locate(double s) const {
  if (!(s >= starts_.front().s && s <= end_s_)) {
    throw std::out_of_range(fmt::format("track: arc length s = {} m is outside the design [{}, {}]",
                                        s, starts_.front().s, end_s_));
  }
  // Last section whose start is <= s.
  const auto it = std::upper_bound(starts_.begin(), starts_.end(), s,
                                   [](double v, const SectionState& st) { return v < st.s; });
  return static_cast<int>(std::distance(starts_.begin(), it)) - 1;
}

Eigen::Vector3d Alignment::position(double s) const {
  const SectionState& st = starts_[locate(s)];
  const Eigen::Vector2d d = plan_offset(st, s - st.s);
  return {st.x + d.x(), st.y + d.y(), 0.0};
}

TrackFrame Alignment::frame(double s) const {
  const int i = locate(s);
  const SectionState& st = starts_[i];
  const double u = s - st.s;
  TrackFrame f;
  f.s = s;
  f.section = i;
  f.heading = st.heading + u * (st.curvature + 0.5 * st.d_curvature * u);
  const double ch = std::cos(f.heading), sh = std::sin(f.heading);
  // On a straight section the chord runs along the heading: plan_offset's u (cos, sin) of it.
  const Eigen::Vector2d d = st.curvature == 0.0 && st.d_curvature == 0.0
                                ? Eigen::Vector2d(u * ch, u * sh)
                                : plan_offset(st, u);
  f.position = {st.x + d.x(), st.y + d.y(), 0.0};
  f.curvature = st.curvature + st.d_curvature * u;
  f.d_curvature = st.d_curvature;
  f.cant = st.cant + st.d_cant * u;
  f.d_cant = st.d_cant;
  f.dd_cant = 0.0;
  f.rail_spacing = design_.rail_spacing;
  f.gauge = design_.gauge + st.widening + st.d_widening * u;
  f.d_gauge = st.d_widening;
  // Cant angle phi = asin(D / b) and its derivatives (D'' = 0 inside a section):
  // phi' = D' / (b cos phi), phi'' = D'' / (b cos phi) + D'^2 sin phi / (b^2 cos^3 phi).
  const double b = design_.rail_spacing;
  const double sp = f.cant / b;
  const double cp = std::sqrt(1.0 - sp * sp);
  f.cant_angle = std::asin(sp);
  f.d_cant_angle = f.d_cant / (b * cp);
  f.dd_cant_angle = f.dd_cant / (b * cp) + f.d_cant * f.d_cant * sp / (b * b * cp * cp * cp);
  // R = Rz(heading) Rx(-phi).
  f.rotation << ch, -sh * cp, -sh * sp,  //
      sh, ch * cp, ch * sp,              //
      0.0, -sp, cp;
  return f;
}

}  // namespace ferro::track
