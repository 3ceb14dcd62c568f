// Standard profile generators.
//
// References: EN 13715:2006 (S1002 wheel profile, piecewise definition; the coefficients are
// the published ones, as tabulated e.g. in Iwnicki (ed.), "Handbook of Railway Vehicle Dynamics"
// (2006) and in DLR's S1002 definition by H. Netter).
// EN 13674-1 (60E1 head: R300, R80, R13, 1:20 flanks).
// Known deviations: none for S1002 (exact formulae; sampled). 60E1: the arc tangency abscissae
// of the EN drawing were not available; the defaults are reconstructed from the Manchester
// benchmark rail file (see profile.hpp).

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "ferro/contact/geometry/profile.hpp"

namespace ferro::contact {
namespace {

// S1002 height F(s) [mm] at lateral coordinate s [mm] (s = profile y: flange at negative s).
double s1002_mm(double s) {
  auto circ = [](double a, double b, double c, double sign, double x) {
    const double d = b * b - (x + c) * (x + c);
    return a + sign * std::sqrt(std::max(d, 0.0));
  };
  if (s >= 32.15796) return 1.364323640 - 0.066666667 * s;  // A
  if (s >= -26.0) {                                         // B
    const double c[9] = {0.0,
                         -3.358537058e-02,
                         1.565681624e-03,
                         -2.810427944e-05,
                         5.844240864e-08,
                         -1.562379023e-08,
                         5.309217349e-15,
                         -5.957839843e-12,
                         2.646656573e-13};
    double v = 0.0;
    for (int k = 8; k >= 0; --k) v = v * s + c[k];
    return v;
  }
  if (s >= -35.0) {  // C
    const double c[8] = {-4.320221063e+03, -1.038384026e+03, -1.065501873e+02, -6.051367875,
                         -2.054332446e-01, -4.169739389e-03, -4.687195829e-05, -2.252755540e-07};
    double v = 0.0;
    for (int k = 7; k >= 0; --k) v = v * s + c[k];
    return v;
  }
  if (s >= -38.426669071) return circ(16.446, 13.0, 26.210665, -1.0, s);         // D
  if (s >= -39.764473993) return -93.576667419 - 2.747477419 * s;                // E
  if (s >= -49.662510381) return circ(8.834924130, 20.0, 58.558326413, 1.0, s);  // F
  if (s >= -62.764705882) return circ(16.0, 12.0, 55.0, 1.0, s);                 // G
  return circ(9.519259302, 20.5, 49.5, 1.0, s);                                  // H
}

}  // namespace

Profile make_s1002_wheel(double step) {
  if (!(step > 0.0 && step <= 1e-3)) {
    throw std::invalid_argument("make_s1002_wheel: step must be in (0, 1e-3] m");
  }
  Profile p;
  p.kind = ProfileKind::wheel;
  p.source = "S1002 (EN 13715 piecewise definition)";
  const double s0 = -70.0, s1 = 60.0, h = step * 1e3;
  const auto n = static_cast<std::size_t>(std::ceil((s1 - s0) / h));
  for (std::size_t i = 0; i <= n; ++i) {
    const double s = std::min(s0 + h * static_cast<double>(i), s1);
    p.y.push_back(s * 1e-3);
    p.z.push_back(s1002_mm(s) * 1e-3);
  }
  p.line.assign(p.y.size(), 0);
  check_profile(p);
  return p;
}

Profile make_60e1_rail(double y_r300_end, double y_r80_end, double depth, double step) {
  constexpr double r1 = 0.300, r2 = 0.080, r3 = 0.013, flank = 20.0;  // flank dz/dy = 20
  if (!(y_r300_end > 0.0 && y_r300_end < y_r80_end && y_r80_end < 0.036) || !(step > 0.0) ||
      !(depth > 0.015)) {
    throw std::invalid_argument(
        "make_60e1_rail: need 0 < y_r300_end < y_r80_end < 36 mm, depth > 15 mm, step > 0");
  }
  // Tangent angles (from the downward vertical) and centres, z down, crown centre (0, r1).
  const double a1 = std::asin(y_r300_end / r1);
  const double c2y = (r1 - r2) * std::sin(a1), c2z = r1 - (r1 - r2) * std::cos(a1);
  const double s2 = (y_r80_end - c2y) / r2;
  if (!(s2 > std::sin(a1) && s2 < 1.0)) {
    throw std::invalid_argument("make_60e1_rail: y_r80_end incompatible with the R80 arc");
  }
  const double a2 = std::asin(s2);
  const double c3y = c2y + (r2 - r3) * std::sin(a2), c3z = c2z - (r2 - r3) * std::cos(a2);
  const double a3 = std::atan(flank);  // R13 meets the 1:20 flank where its normal is (20, -1)
  std::vector<double> ry, rz;
  auto arc = [&](double cy, double cz, double r, double from, double to) {
    const int n = std::max(2, static_cast<int>(std::ceil(r * (to - from) / step)));
    for (int k = (ry.empty() ? 0 : 1); k <= n; ++k) {
      const double a = from + (to - from) * k / n;
      ry.push_back(cy + r * std::sin(a));
      rz.push_back(cz - r * std::cos(a));
    }
  };
  arc(0.0, r1, r1, 0.0, a1);
  arc(c2y, c2z, r2, a1, a2);
  arc(c3y, c3z, r3, a2, a3);
  const double ty = ry.back(), tz = rz.back();
  const double len = std::hypot(1.0, flank);
  for (double l = step; tz + l * flank / len <= depth; l += step) {
    ry.push_back(ty + l / len);
    rz.push_back(tz + l * flank / len);
  }
  Profile p;
  p.kind = ProfileKind::rail;
  p.source = "60E1 rail head (R300/R80/R13, 1:20 flanks)";
  for (std::size_t i = ry.size(); i-- > 1;) {
    p.y.push_back(-ry[i]);
    p.z.push_back(rz[i]);
  }
  p.y.insert(p.y.end(), ry.begin(), ry.end());
  p.z.insert(p.z.end(), rz.begin(), rz.end());
  p.line.assign(p.y.size(), 0);
  check_profile(p);
  return p;
}

}  // namespace ferro::contact
