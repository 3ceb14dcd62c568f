#pragma once
// Dense surface-compliance operator, invariant along the rolling direction x: the influence of
// a unit traction on element (ix_s, iy_s) at element (ix_o, iy_o) depends on ix_o - ix_s, iy_o
// and iy_s. This is what a finite-element model of a straight rail (translation invariance) or
// of a wheel (axisymmetry) gives when one column of surface elements is loaded.
//
// References: Toumi (2016) eqs. (70)-(76), (117)-(120) (products, rolling difference); Kalker,
// "Three-dimensional elastic bodies in rolling contact" (1990) section 5.2 (numerical influence
// coefficients in the steady-rolling problem); Vollebregt, CONTACT user guide (influence
// coefficients read from a finite-element model).
// Known deviations: products are direct sums (O(nx^2 ny^2)), fine for the grids of K_ij studies
// (<= ~60 x 60); the preconditioner is the FFT circulant inverse of a half-space whose shear
// modulus matches the operator's mean tangential self-compliance (exact for half-space data).

#include <memory>
#include <vector>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/compliance_operator.hpp"
#include "ferro/contact/mim/grid.hpp"
#include "ferro/contact/mim/influence_operator.hpp"

namespace ferro::contact::mim {

/// Influence coefficients [m/Pa] of a loaded column: value(c, ox, iy_o, iy_s) for offsets
/// ox = ix_o - ix_s in [-nx, nx] (2 nx + 1 values; ox = nx is needed by the rolling difference),
/// stored at ((ox + nx) * ny + iy_o) * ny + iy_s. u_z = zz p; u_x = xx tau_x + xy tau_y;
/// u_y = yx tau_x + yy tau_y (relative displacement of body 1 minus body 2).
struct ColumnInfluence {
  int nx = 0;
  int ny = 0;
  std::vector<double> zz, xx, xy, yx, yy;
  [[nodiscard]] std::size_t index(int ox, int iy_obs, int iy_src) const {
    return (static_cast<std::size_t>(ox + nx) * static_cast<std::size_t>(ny) +
            static_cast<std::size_t>(iy_obs)) *
               static_cast<std::size_t>(ny) +
           static_cast<std::size_t>(iy_src);
  }
  [[nodiscard]] std::size_t size() const {
    return static_cast<std::size_t>(2 * nx + 1) * static_cast<std::size_t>(ny) *
           static_cast<std::size_t>(ny);
  }
  /// Allocates nx, ny with zeros.
  static ColumnInfluence zeros(int nx, int ny);
  /// The half-space closed forms (annex B.3) on `grid` (the oracle of the dense operator).
  static ColumnInfluence half_space(const Grid& grid, const CombinedMaterial& material);
  /// Throws std::invalid_argument naming the first inconsistent or non-finite entry.
  void validate(const std::string& where = "ColumnInfluence") const;
};

/// An operator given by explicit influence kernels zz, xx, xy, yx, yy [m/Pa]: the products, the
/// rolling difference (B - A) tau / h, the self terms and the preconditioner (FFT circulant
/// inverse of a half-space whose shear modulus matches the mean tangential self-compliance),
/// shared by every stored-coefficient operator. A derived class supplies the kernels, the
/// product of one kernel and the mean self terms (then calls finish()).
class KernelOperator : public ComplianceOperator {
 public:
  ~KernelOperator() override;
  [[nodiscard]] const CombinedMaterial& material() const override;
  void normal(const double* pressure, double* displacement_z) override;
  void tangential(const double* traction_x, const double* traction_y, double* displacement_x,
                  double* displacement_y) override;
  void rolling_difference(const double* traction_x, const double* traction_y, double* out_x,
                          double* out_y) override;
  void tangential_inverse(const double* in_x, const double* in_y, double* out_x,
                          double* out_y) override;
  [[nodiscard]] bool has_coarse() const override { return false; }
  [[nodiscard]] ComplianceOperator& coarse() override;
  [[nodiscard]] double normal_self() const override { return self_zz_; }
  [[nodiscard]] double tangential_self_x() const override { return self_xx_; }
  [[nodiscard]] double tangential_self_y() const override { return self_yy_; }
  [[nodiscard]] double rolling_self() const override { return roll_self_; }

 protected:
  struct Kernels {
    const std::vector<double>* zz = nullptr;
    const std::vector<double>* xx = nullptr;
    const std::vector<double>* xy = nullptr;
    const std::vector<double>* yx = nullptr;
    const std::vector<double>* yy = nullptr;
  };
  /// out(ix, iy) += sum over sources of k(observation (ix + shift, iy), source) in(source).
  virtual void accumulate(const std::vector<double>& k, int shift, const double* in,
                          double* out) const = 0;
  /// Stores the kernels and the mean self terms (checked > 0, the message naming `name`) and
  /// builds the preconditioner from `reference`.
  void finish(Kernels kernels, double self_zz, double self_xx, double self_yy, double roll_self,
              const CombinedMaterial& reference, const char* name);

 private:
  Kernels k_;
  const char* name_ = "KernelOperator";
  std::unique_ptr<InfluenceOperator> preconditioner_;
  double self_zz_ = 0.0, self_xx_ = 0.0, self_yy_ = 0.0, roll_self_ = 0.0;
  std::vector<double> work_;
};

class DenseInfluenceOperator final : public KernelOperator {
 public:
  /// `reference` is the half-space pair whose FFT circulant inverse preconditions the tangential
  /// solver after scaling its shear modulus to the operator's mean tangential self-compliance.
  DenseInfluenceOperator(const Grid& grid, ColumnInfluence coefficients,
                         const CombinedMaterial& reference);
  ~DenseInfluenceOperator() override;

  [[nodiscard]] const Grid& grid() const override { return grid_; }
  [[nodiscard]] const ColumnInfluence& coefficients() const { return c_; }

 private:
  // out(ixo, iyo) += sum k(ixo - ixs + shift, iyo, iys) in(ixs, iys)
  void accumulate(const std::vector<double>& k, int shift, const double* in,
                  double* out) const override;
  Grid grid_;
  ColumnInfluence c_;
};

}  // namespace ferro::contact::mim
