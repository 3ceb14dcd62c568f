// Influence coefficients (annex B.3) and the FFT influence products against independent methods.
#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "ferro/contact/mim/influence.hpp"
#include "ferro/contact/mim/influence_operator.hpp"

using namespace ferro::contact;
using namespace ferro::contact::mim;

namespace {

CombinedMaterial steel_pair() {
  const Material m = Material::from_young(210.0e9, 0.28);
  return combine(m, m);
}

// Gauss-Legendre quadrature (Boost.Math, 8 points per direction, 4 x 4 panels) of the surface
// kernels of eqs. (70)-(72) over an element that does not contain the field point: an
// independent check of the closed-form primitives.
InfluenceCoefficients quadrature(double x, double y, double dx, double dy,
                                 const CombinedMaterial& m) {
  using Gauss = boost::math::quadrature::gauss<double, 8>;
  const double nu = m.poisson;
  const double scale = 1.0 / (std::numbers::pi * m.shear_modulus);
  // Integral over the element of one kernel k(u, v), u = x - zeta, v = y - eta.
  auto integrate = [&](auto kernel) {
    constexpr int kPanels = 4;
    const double pdx = dx / kPanels, pdy = dy / kPanels;
    double sum = 0.0;
    for (int px = 0; px < kPanels; ++px) {
      for (int py = 0; py < kPanels; ++py) {
        const double x0 = -0.5 * dx + px * pdx, y0 = -0.5 * dy + py * pdy;
        sum += Gauss::integrate(
            [&](double zeta) {
              return Gauss::integrate([&](double eta) { return kernel(x - zeta, y - eta); }, y0,
                                      y0 + pdy);
            },
            x0, x0 + pdx);
      }
    }
    return scale * sum;
  };
  InfluenceCoefficients s;
  s.zz = integrate([&](double u, double v) { return (1.0 - nu) / std::hypot(u, v); });
  s.xx = integrate([&](double u, double v) {
    const double r = std::hypot(u, v);
    return (1.0 - nu) / r + nu * u * u / (r * r * r);
  });
  s.yy = integrate([&](double u, double v) {
    const double r = std::hypot(u, v);
    return (1.0 - nu) / r + nu * v * v / (r * r * r);
  });
  s.xy = integrate([&](double u, double v) {
    const double r = std::hypot(u, v);
    return nu * u * v / (r * r * r);
  });
  return s;
}

}  // namespace

// The closed forms (B.13)-(B.20) must equal direct quadrature of the Boussinesq-Cerruti kernels.
// Tolerance: 1e-9 relative, the quadrature error of 8-point Gauss on 16 panels at >= 1 element
// distance (smooth integrand) is below 1e-10.
TEST(MimInfluence, ClosedFormMatchesQuadrature) {
  constexpr double kRelTol = 1.0e-9;
  const CombinedMaterial m = steel_pair();
  const double dx = 0.5e-3, dy = 0.3e-3;
  for (auto [ox, oy] : std::vector<std::pair<int, int>>{{1, 0}, {0, 1}, {2, -3}, {-5, 4}, {1, 1}}) {
    const InfluenceCoefficients c = influence_coefficients(ox * dx, oy * dy, dx, dy, m);
    const InfluenceCoefficients q = quadrature(ox * dx, oy * dy, dx, dy, m);
    EXPECT_NEAR(c.zz, q.zz, kRelTol * std::abs(q.zz)) << ox << "," << oy;
    EXPECT_NEAR(c.xx, q.xx, kRelTol * std::abs(q.xx)) << ox << "," << oy;
    EXPECT_NEAR(c.yy, q.yy, kRelTol * std::abs(q.yy)) << ox << "," << oy;
    EXPECT_NEAR(c.xy, q.xy, kRelTol * std::abs(q.zz)) << ox << "," << oy;
  }
}

// Love's closed form for the centre of a uniformly loaded square of side d on one half-space:
// w = 4 ln(1 + sqrt 2) d (1 - nu^2) p / (pi E) (Johnson 1985 section 3.3); the relative
// displacement of two identical bodies is twice that. Tolerance 1e-12 relative (round-off).
TEST(MimInfluence, SquareCentreMatchesLove) {
  const Material steel = Material::from_young(210.0e9, 0.28);
  const CombinedMaterial m = combine(steel, steel);
  const double d = 1.0e-3;
  const double love = 2.0 * 4.0 * std::log(1.0 + std::sqrt(2.0)) * d * (1.0 - 0.28 * 0.28) /
                      (std::numbers::pi * 210.0e9);
  EXPECT_NEAR(influence_coefficients(0.0, 0.0, d, d, m).zz, love, 1.0e-12 * love);
}

// FFT products equal the direct Toeplitz sums (zero padding makes them exact). Seeded random
// tractions. Tolerance 1e-10 of the largest value: double-precision FFT round-off.
TEST(MimInfluence, FftProductsMatchDirectSums) {
  const CombinedMaterial m = steel_pair();
  const Grid grid = Grid::centred(9, 6, 0.4e-3, 0.7e-3);
  InfluenceOperator op(grid, m);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> dist(-1.0e6, 1.0e6);
  std::vector<double> p(grid.size()), tx(grid.size()), ty(grid.size());
  for (auto* f : {&p, &tx, &ty})
    for (double& v : *f) v = dist(rng);
  std::vector<double> uz(grid.size()), ux(grid.size()), uy(grid.size()), dx_(grid.size()),
      dy_(grid.size());
  op.normal(p.data(), uz.data());
  op.tangential(tx.data(), ty.data(), ux.data(), uy.data());
  op.rolling_difference(tx.data(), ty.data(), dx_.data(), dy_.data());
  double scale = 0.0, scale_d = 0.0;
  std::vector<double> ez(grid.size()), ex(grid.size()), ey(grid.size()), edx(grid.size()),
      edy(grid.size());
  for (int iy = 0; iy < grid.ny; ++iy)
    for (int ix = 0; ix < grid.nx; ++ix) {
      const std::size_t i = grid.index(ix, iy);
      for (int jy = 0; jy < grid.ny; ++jy)
        for (int jx = 0; jx < grid.nx; ++jx) {
          const std::size_t j = grid.index(jx, jy);
          const double X = (ix - jx) * grid.dx, Y = (iy - jy) * grid.dy;
          const InfluenceCoefficients a = influence_coefficients(X, Y, grid.dx, grid.dy, m);
          const InfluenceCoefficients b =
              influence_coefficients(X + grid.dx, Y, grid.dx, grid.dy, m);
          ez[i] += a.zz * p[j];
          ex[i] += a.xx * tx[j] + a.xy * ty[j];
          ey[i] += a.xy * tx[j] + a.yy * ty[j];
          edx[i] += ((b.xx - a.xx) * tx[j] + (b.xy - a.xy) * ty[j]) / grid.dx;
          edy[i] += ((b.xy - a.xy) * tx[j] + (b.yy - a.yy) * ty[j]) / grid.dx;
        }
      scale = std::max({scale, std::abs(ez[i]), std::abs(ex[i]), std::abs(ey[i])});
      scale_d = std::max({scale_d, std::abs(edx[i]), std::abs(edy[i])});
    }
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_NEAR(uz[i], ez[i], 1.0e-10 * scale);
    EXPECT_NEAR(ux[i], ex[i], 1.0e-10 * scale);
    EXPECT_NEAR(uy[i], ey[i], 1.0e-10 * scale);
    EXPECT_NEAR(dx_[i], edx[i], 1.0e-10 * scale_d);
    EXPECT_NEAR(dy_[i], edy[i], 1.0e-10 * scale_d);
  }
}
