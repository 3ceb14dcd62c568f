// Full-matrix surface-compliance operator (no translation invariance).
//
// References: see matrix_operator.hpp.
// Known deviations: see matrix_operator.hpp (direct sums, scaled half-space preconditioner).

#include "ferro/fe_contact/matrix_operator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/mim/influence.hpp"

namespace ferro::fe_contact {

namespace mim = contact::mim;

SurfaceCompliance SurfaceCompliance::zeros(const mim::Grid& grid) {
  grid.validate("SurfaceCompliance.grid");
  SurfaceCompliance c;
  c.grid = grid;
  const std::size_t n = c.observations() * grid.size();
  for (std::vector<double>* v : {&c.zz, &c.xx, &c.xy, &c.yx, &c.yy}) v->assign(n, 0.0);
  return c;
}

SurfaceCompliance SurfaceCompliance::half_space(const mim::Grid& grid,
                                                const contact::CombinedMaterial& material) {
  SurfaceCompliance c = zeros(grid);
  for (int iyo = 0; iyo < grid.ny; ++iyo)
    for (int ixo = 0; ixo <= grid.nx; ++ixo)
      for (int iys = 0; iys < grid.ny; ++iys)
        for (int ixs = 0; ixs < grid.nx; ++ixs) {
          const mim::InfluenceCoefficients k = mim::influence_coefficients(
              (ixo - ixs) * grid.dx, (iyo - iys) * grid.dy, grid.dx, grid.dy, material);
          const std::size_t i = c.index(ixo, iyo, grid.index(ixs, iys));
          c.zz[i] = k.zz;
          c.xx[i] = k.xx;
          c.xy[i] = k.xy;
          c.yx[i] = k.xy;
          c.yy[i] = k.yy;
        }
  return c;
}

void SurfaceCompliance::add_tangential(const SurfaceCompliance& other) {
  if (other.grid.nx != grid.nx || other.grid.ny != grid.ny || other.xx.size() != xx.size()) {
    throw std::invalid_argument("SurfaceCompliance::add_tangential: the grids differ");
  }
  for (std::size_t i = 0; i < xx.size(); ++i) {
    xx[i] += other.xx[i];
    xy[i] += other.xy[i];
    yx[i] += other.yx[i];
    yy[i] += other.yy[i];
  }
}

void SurfaceCompliance::validate(const std::string& where) const {
  grid.validate(where + ".grid");
  const std::size_t n = observations() * grid.size();
  const std::pair<const char*, const std::vector<double>*> parts[] = {
      {"zz", &zz}, {"xx", &xx}, {"xy", &xy}, {"yx", &yx}, {"yy", &yy}};
  for (const auto& [name, v] : parts) {
    if (v->size() != n) {
      throw std::invalid_argument(fmt::format("{}.{}: has {} values, (nx + 1) ny nx ny = {}",
                                              where, name, v->size(), n));
    }
    for (std::size_t i = 0; i < v->size(); ++i) {
      if (!std::isfinite((*v)[i])) {
        throw std::invalid_argument(fmt::format("{}.{}[{}]: not finite", where, name, i));
      }
    }
  }
}

MatrixComplianceOperator::MatrixComplianceOperator(SurfaceCompliance coefficients,
                                                   const contact::CombinedMaterial& reference)
    : c_(std::move(coefficients)) {
  c_.validate("MatrixComplianceOperator.coefficients");
  const mim::Grid& g = c_.grid;
  // Mean diagonals (the self-compliances used by the solvers' scalings).
  double zz = 0.0, xx = 0.0, yy = 0.0, roll = 0.0;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t s = g.index(ix, iy);
      zz += c_.zz[c_.index(ix, iy, s)];
      xx += c_.xx[c_.index(ix, iy, s)];
      yy += c_.yy[c_.index(ix, iy, s)];
      roll += (c_.xx[c_.index(ix, iy, s)] - c_.xx[c_.index(ix + 1, iy, s)]) / g.dx;
    }
  const double inv_n = 1.0 / static_cast<double>(g.size());
  finish({&c_.zz, &c_.xx, &c_.xy, &c_.yx, &c_.yy}, zz * inv_n, xx * inv_n, yy * inv_n,
         roll * inv_n, reference, "MatrixComplianceOperator");
}

MatrixComplianceOperator::~MatrixComplianceOperator() = default;


void MatrixComplianceOperator::accumulate(const std::vector<double>& k, int shift,
                                          const double* in, double* out) const {
  const mim::Grid& g = c_.grid;
  const std::size_t n = g.size();
  for (std::size_t s = 0; s < n; ++s) {
    const double t = in[s];
    if (t == 0.0) continue;  // sparse tractions (outside the patch) cost nothing
    for (int iy = 0; iy < g.ny; ++iy)
      for (int ix = 0; ix < g.nx; ++ix) out[g.index(ix, iy)] += k[c_.index(ix + shift, iy, s)] * t;
  }
}






}  // namespace ferro::fe_contact
