// Standard profile generators.
//
// References: EN 13715:2006 (S1002 wheel profile, piecewise definition; the coefficients are
// the published ones, as tabulated e.g. in Iwnicki (ed.), "Handbook of Railway Vehicle Dynamics"
// (2006) and in DLR's S1002 definition by H. Netter).
// Known deviations: none for S1002 (exact formulae; sampled). A 60E1 arc generator is not
// provided: its tangency abscissae were not found in a reliable source (see the report).

#include <cmath>
#include <stdexcept>

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

}  // namespace ferro::contact
