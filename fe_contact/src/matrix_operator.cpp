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
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t s = g.index(ix, iy);
      self_zz_ += c_.zz[c_.index(ix, iy, s)];
      self_xx_ += c_.xx[c_.index(ix, iy, s)];
      self_yy_ += c_.yy[c_.index(ix, iy, s)];
      roll_self_ += (c_.xx[c_.index(ix, iy, s)] - c_.xx[c_.index(ix + 1, iy, s)]) / g.dx;
    }
  const double inv_n = 1.0 / static_cast<double>(g.size());
  self_zz_ *= inv_n;
  self_xx_ *= inv_n;
  self_yy_ *= inv_n;
  roll_self_ *= inv_n;
  if (!(self_zz_ > 0.0) || !(self_xx_ > 0.0) || !(self_yy_ > 0.0)) {
    throw std::invalid_argument(
        "MatrixComplianceOperator.coefficients: the self-compliances zz, xx, yy must be > 0");
  }
  const double ref_self = mim::influence_coefficients(0.0, 0.0, g.dx, g.dy, reference).xx;
  contact::CombinedMaterial scaled = reference;
  const double ratio = ref_self / self_xx_;
  scaled.shear_modulus *= ratio;
  scaled.contact_modulus *= ratio;
  preconditioner_ = std::make_unique<mim::InfluenceOperator>(g, scaled);
  work_.resize(g.size());
}

MatrixComplianceOperator::~MatrixComplianceOperator() = default;

const contact::CombinedMaterial& MatrixComplianceOperator::material() const {
  return preconditioner_->material();
}

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

void MatrixComplianceOperator::normal(const double* pressure, double* displacement_z) {
  std::fill(displacement_z, displacement_z + c_.grid.size(), 0.0);
  accumulate(c_.zz, 0, pressure, displacement_z);
}

void MatrixComplianceOperator::tangential(const double* traction_x, const double* traction_y,
                                          double* displacement_x, double* displacement_y) {
  const std::size_t n = c_.grid.size();
  std::fill(displacement_x, displacement_x + n, 0.0);
  std::fill(displacement_y, displacement_y + n, 0.0);
  accumulate(c_.xx, 0, traction_x, displacement_x);
  accumulate(c_.xy, 0, traction_y, displacement_x);
  accumulate(c_.yx, 0, traction_x, displacement_y);
  accumulate(c_.yy, 0, traction_y, displacement_y);
}

void MatrixComplianceOperator::rolling_difference(const double* traction_x,
                                                  const double* traction_y, double* out_x,
                                                  double* out_y) {
  // Displacement one element towards +x (the leading edge) minus in place, over h = dx.
  const std::size_t n = c_.grid.size();
  const double inv_h = 1.0 / c_.grid.dx;
  std::fill(out_x, out_x + n, 0.0);
  std::fill(out_y, out_y + n, 0.0);
  accumulate(c_.xx, 1, traction_x, out_x);
  accumulate(c_.xy, 1, traction_y, out_x);
  accumulate(c_.yx, 1, traction_x, out_y);
  accumulate(c_.yy, 1, traction_y, out_y);
  std::fill(work_.begin(), work_.end(), 0.0);
  accumulate(c_.xx, 0, traction_x, work_.data());
  accumulate(c_.xy, 0, traction_y, work_.data());
  for (std::size_t i = 0; i < n; ++i) out_x[i] = (out_x[i] - work_[i]) * inv_h;
  std::fill(work_.begin(), work_.end(), 0.0);
  accumulate(c_.yx, 0, traction_x, work_.data());
  accumulate(c_.yy, 0, traction_y, work_.data());
  for (std::size_t i = 0; i < n; ++i) out_y[i] = (out_y[i] - work_[i]) * inv_h;
}

void MatrixComplianceOperator::tangential_inverse(const double* in_x, const double* in_y,
                                                  double* out_x, double* out_y) {
  preconditioner_->tangential_inverse(in_x, in_y, out_x, out_y);
}

mim::ComplianceOperator& MatrixComplianceOperator::coarse() {
  throw std::logic_error(
      "MatrixComplianceOperator: no coarse grid (set TangentialSolverOptions.nested = false)");
}

}  // namespace ferro::fe_contact
