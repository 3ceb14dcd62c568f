// Dense, x-invariant surface-compliance operator (numerical influence coefficients).
//
// References: Toumi (2016) eqs. (70)-(76), (117)-(120); Kalker (1990) section 5.2.
// Known deviations: see dense_operator.hpp (direct sums; scaled half-space preconditioner).

#include "ferro/contact/mim/dense_operator.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "ferro/contact/mim/influence.hpp"

namespace ferro::contact::mim {

ColumnInfluence ColumnInfluence::zeros(int nx, int ny) {
  ColumnInfluence c;
  c.nx = nx;
  c.ny = ny;
  const std::size_t n = c.size();
  for (std::vector<double>* v : {&c.zz, &c.xx, &c.xy, &c.yx, &c.yy}) v->assign(n, 0.0);
  return c;
}

ColumnInfluence ColumnInfluence::half_space(const Grid& grid, const CombinedMaterial& material) {
  grid.validate("ColumnInfluence.grid");
  ColumnInfluence c = zeros(grid.nx, grid.ny);
  for (int ox = -grid.nx; ox <= grid.nx; ++ox)
    for (int io = 0; io < grid.ny; ++io)
      for (int is = 0; is < grid.ny; ++is) {
        const InfluenceCoefficients k =
            influence_coefficients(ox * grid.dx, (io - is) * grid.dy, grid.dx, grid.dy, material);
        const std::size_t i = c.index(ox, io, is);
        c.zz[i] = k.zz;
        c.xx[i] = k.xx;
        c.xy[i] = k.xy;
        c.yx[i] = k.xy;
        c.yy[i] = k.yy;
      }
  return c;
}

void ColumnInfluence::validate(const std::string& where) const {
  if (nx < 1 || ny < 1) {
    throw std::invalid_argument(fmt::format("{}: nx, ny must be >= 1, got {} x {}", where, nx, ny));
  }
  const std::pair<const char*, const std::vector<double>*> parts[] = {
      {"zz", &zz}, {"xx", &xx}, {"xy", &xy}, {"yx", &yx}, {"yy", &yy}};
  for (const auto& [name, v] : parts) {
    if (v->size() != size()) {
      throw std::invalid_argument(fmt::format("{}.{}: has {} values, (2 nx + 1) ny^2 = {}", where,
                                              name, v->size(), size()));
    }
    for (std::size_t i = 0; i < v->size(); ++i) {
      if (!std::isfinite((*v)[i])) {
        throw std::invalid_argument(fmt::format("{}.{}[{}]: not finite", where, name, i));
      }
    }
  }
}

DenseInfluenceOperator::DenseInfluenceOperator(const Grid& grid, ColumnInfluence coefficients,
                                               const CombinedMaterial& reference)
    : grid_(grid), c_(std::move(coefficients)) {
  grid_.validate("DenseInfluenceOperator.grid");
  c_.validate("DenseInfluenceOperator.coefficients");
  if (c_.nx != grid_.nx || c_.ny != grid_.ny) {
    throw std::invalid_argument(
        fmt::format("DenseInfluenceOperator: coefficients are for {} x {} elements, the grid has "
                    "{} x {}",
                    c_.nx, c_.ny, grid_.nx, grid_.ny));
  }
  // Mean diagonals over the rows (equal on every row for a half-space).
  for (int iy = 0; iy < grid_.ny; ++iy) {
    self_zz_ += c_.zz[c_.index(0, iy, iy)];
    self_xx_ += c_.xx[c_.index(0, iy, iy)];
    self_yy_ += c_.yy[c_.index(0, iy, iy)];
    roll_self_ += (c_.xx[c_.index(0, iy, iy)] - c_.xx[c_.index(1, iy, iy)]) / grid_.dx;
  }
  const double inv_ny = 1.0 / grid_.ny;
  self_zz_ *= inv_ny;
  self_xx_ *= inv_ny;
  self_yy_ *= inv_ny;
  roll_self_ *= inv_ny;
  if (!(self_zz_ > 0.0) || !(self_xx_ > 0.0) || !(self_yy_ > 0.0)) {
    throw std::invalid_argument(
        "DenseInfluenceOperator.coefficients: the self-compliances zz, xx, yy must be > 0");
  }
  // Preconditioner: half-space with G scaled so that its A^xx self-compliance matches.
  const double ref_self = influence_coefficients(0.0, 0.0, grid_.dx, grid_.dy, reference).xx;
  CombinedMaterial scaled = reference;
  const double ratio = ref_self / self_xx_;
  scaled.shear_modulus *= ratio;
  scaled.contact_modulus *= ratio;
  preconditioner_ = std::make_unique<InfluenceOperator>(grid_, scaled);
  work_.resize(grid_.size());
}

DenseInfluenceOperator::~DenseInfluenceOperator() = default;

const CombinedMaterial& DenseInfluenceOperator::material() const {
  return preconditioner_->material();
}

void DenseInfluenceOperator::accumulate(const std::vector<double>& k, int shift, const double* in,
                                        double* out) const {
  const int nx = grid_.nx, ny = grid_.ny;
  for (int is = 0; is < ny; ++is)
    for (int ixs = 0; ixs < nx; ++ixs) {
      const double t = in[grid_.index(ixs, is)];
      if (t == 0.0) continue;  // sparse tractions (outside the patch) cost nothing
      for (int io = 0; io < ny; ++io) {
        double* row = out + grid_.index(0, io);
        for (int ixo = 0; ixo < nx; ++ixo) {
          row[ixo] += k[c_.index(ixo - ixs + shift, io, is)] * t;
        }
      }
    }
}

void DenseInfluenceOperator::normal(const double* pressure, double* displacement_z) {
  std::fill(displacement_z, displacement_z + grid_.size(), 0.0);
  accumulate(c_.zz, 0, pressure, displacement_z);
}

void DenseInfluenceOperator::tangential(const double* traction_x, const double* traction_y,
                                        double* displacement_x, double* displacement_y) {
  std::fill(displacement_x, displacement_x + grid_.size(), 0.0);
  std::fill(displacement_y, displacement_y + grid_.size(), 0.0);
  accumulate(c_.xx, 0, traction_x, displacement_x);
  accumulate(c_.xy, 0, traction_y, displacement_x);
  accumulate(c_.yx, 0, traction_x, displacement_y);
  accumulate(c_.yy, 0, traction_y, displacement_y);
}

void DenseInfluenceOperator::rolling_difference(const double* traction_x, const double* traction_y,
                                                double* out_x, double* out_y) {
  // (B - A) tau / h with B(X) = A(X + h): displacement one element towards +x minus in place.
  const std::size_t n = grid_.size();
  std::fill(out_x, out_x + n, 0.0);
  std::fill(out_y, out_y + n, 0.0);
  accumulate(c_.xx, 1, traction_x, out_x);
  accumulate(c_.xy, 1, traction_y, out_x);
  accumulate(c_.yx, 1, traction_x, out_y);
  accumulate(c_.yy, 1, traction_y, out_y);
  std::fill(work_.begin(), work_.end(), 0.0);
  accumulate(c_.xx, 0, traction_x, work_.data());
  accumulate(c_.xy, 0, traction_y, work_.data());
  const double inv_h = 1.0 / grid_.dx;
  for (std::size_t i = 0; i < n; ++i) out_x[i] = (out_x[i] - work_[i]) * inv_h;
  std::fill(work_.begin(), work_.end(), 0.0);
  accumulate(c_.yx, 0, traction_x, work_.data());
  accumulate(c_.yy, 0, traction_y, work_.data());
  for (std::size_t i = 0; i < n; ++i) out_y[i] = (out_y[i] - work_[i]) * inv_h;
}

void DenseInfluenceOperator::tangential_inverse(const double* in_x, const double* in_y,
                                                double* out_x, double* out_y) {
  preconditioner_->tangential_inverse(in_x, in_y, out_x, out_y);
}

ComplianceOperator& DenseInfluenceOperator::coarse() {
  throw std::logic_error(
      "DenseInfluenceOperator: no coarse grid (set TangentialSolverOptions.nested = false)");
}

}  // namespace ferro::contact::mim
