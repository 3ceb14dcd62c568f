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

KernelOperator::~KernelOperator() = default;

void KernelOperator::finish(Kernels kernels, double self_zz, double self_xx, double self_yy,
                            double roll_self, const CombinedMaterial& reference,
                            const char* name) {
  k_ = kernels;
  name_ = name;
  self_zz_ = self_zz;
  self_xx_ = self_xx;
  self_yy_ = self_yy;
  roll_self_ = roll_self;
  if (!(self_zz_ > 0.0) || !(self_xx_ > 0.0) || !(self_yy_ > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "{}.coefficients: the self-compliances zz, xx, yy must be > 0", name_));
  }
  // Preconditioner: half-space with G scaled so that its A^xx self-compliance matches.
  const Grid& g = grid();
  const double ref_self = influence_coefficients(0.0, 0.0, g.dx, g.dy, reference).xx;
  CombinedMaterial scaled = reference;
  const double ratio = ref_self / self_xx_;
  scaled.shear_modulus *= ratio;
  scaled.contact_modulus *= ratio;
  preconditioner_ = std::make_unique<InfluenceOperator>(g, scaled);
  work_.resize(g.size());
}

const CombinedMaterial& KernelOperator::material() const { return preconditioner_->material(); }

void KernelOperator::normal(const double* pressure, double* displacement_z) {
  std::fill(displacement_z, displacement_z + grid().size(), 0.0);
  accumulate(*k_.zz, 0, pressure, displacement_z);
}

void KernelOperator::tangential(const double* traction_x, const double* traction_y,
                                double* displacement_x, double* displacement_y) {
  std::fill(displacement_x, displacement_x + grid().size(), 0.0);
  std::fill(displacement_y, displacement_y + grid().size(), 0.0);
  accumulate(*k_.xx, 0, traction_x, displacement_x);
  accumulate(*k_.xy, 0, traction_y, displacement_x);
  accumulate(*k_.yx, 0, traction_x, displacement_y);
  accumulate(*k_.yy, 0, traction_y, displacement_y);
}

void KernelOperator::rolling_difference(const double* traction_x, const double* traction_y,
                                        double* out_x, double* out_y) {
  // (B - A) tau / h with B(X) = A(X + h): displacement one element towards +x minus in place.
  const std::size_t n = grid().size();
  std::fill(out_x, out_x + n, 0.0);
  std::fill(out_y, out_y + n, 0.0);
  accumulate(*k_.xx, 1, traction_x, out_x);
  accumulate(*k_.xy, 1, traction_y, out_x);
  accumulate(*k_.yx, 1, traction_x, out_y);
  accumulate(*k_.yy, 1, traction_y, out_y);
  std::fill(work_.begin(), work_.end(), 0.0);
  accumulate(*k_.xx, 0, traction_x, work_.data());
  accumulate(*k_.xy, 0, traction_y, work_.data());
  const double inv_h = 1.0 / grid().dx;
  for (std::size_t i = 0; i < n; ++i) out_x[i] = (out_x[i] - work_[i]) * inv_h;
  std::fill(work_.begin(), work_.end(), 0.0);
  accumulate(*k_.yx, 0, traction_x, work_.data());
  accumulate(*k_.yy, 0, traction_y, work_.data());
  for (std::size_t i = 0; i < n; ++i) out_y[i] = (out_y[i] - work_[i]) * inv_h;
}

void KernelOperator::tangential_inverse(const double* in_x, const double* in_y, double* out_x,
                                        double* out_y) {
  preconditioner_->tangential_inverse(in_x, in_y, out_x, out_y);
}

ComplianceOperator& KernelOperator::coarse() {
  throw std::logic_error(fmt::format(
      "{}: no coarse grid (set TangentialSolverOptions.nested = false)", name_));
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
  double zz = 0.0, xx = 0.0, yy = 0.0, roll = 0.0;
  for (int iy = 0; iy < grid_.ny; ++iy) {
    zz += c_.zz[c_.index(0, iy, iy)];
    xx += c_.xx[c_.index(0, iy, iy)];
    yy += c_.yy[c_.index(0, iy, iy)];
    roll += (c_.xx[c_.index(0, iy, iy)] - c_.xx[c_.index(1, iy, iy)]) / grid_.dx;
  }
  const double inv_ny = 1.0 / grid_.ny;
  finish({&c_.zz, &c_.xx, &c_.xy, &c_.yx, &c_.yy}, zz * inv_ny, xx * inv_ny, yy * inv_ny,
         roll * inv_ny, reference, "DenseInfluenceOperator");
}

DenseInfluenceOperator::~DenseInfluenceOperator() = default;


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






}  // namespace ferro::contact::mim
