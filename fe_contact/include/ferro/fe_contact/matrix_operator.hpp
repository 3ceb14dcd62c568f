#pragma once
// Dense surface-compliance operator without translation invariance: the influence of a unit
// traction on element s at element centre o is a full matrix, as for a rail whose yielded zone
// under the wheel is fixed in the contact frame. Observations cover the grid plus one column
// beyond its leading edge (x index nx), which the rolling difference (B - A) tau / h needs.
//
// References: Toumi (2016) eqs. (70)-(76), (117)-(120) (products, rolling difference); Kalker,
// "Three-dimensional elastic bodies in rolling contact" (1990) section 5.2 (numerical influence
// coefficients); Vollebregt, CONTACT user guide (influence coefficients from an FE model).
// Known deviations: products are direct O(n^2) sums (grids of K_ij studies, n <= ~500); the
// preconditioner is the FFT circulant inverse of a half-space whose shear modulus matches the
// operator's mean tangential self-compliance; no coarse grid (nested iteration off).

#include <memory>
#include <string>
#include <vector>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/compliance_operator.hpp"
#include "ferro/contact/mim/dense_operator.hpp"
#include "ferro/contact/mim/grid.hpp"
#include "ferro/contact/mim/influence_operator.hpp"

namespace ferro::fe_contact {

/// Full influence matrices [m/Pa]: value at observation o = iy * (nx + 1) + ix (ix in [0, nx])
/// of a unit traction on source element s = grid.index(ix, iy), stored at o * grid.size() + s.
/// u_z = zz p; u_x = xx tau_x + xy tau_y; u_y = yx tau_x + yy tau_y (relative displacement of
/// body 1 minus body 2, as contact::mim::ColumnInfluence).
struct SurfaceCompliance {
  contact::mim::Grid grid;
  std::vector<double> zz, xx, xy, yx, yy;
  [[nodiscard]] std::size_t observations() const {
    return static_cast<std::size_t>(grid.nx + 1) * static_cast<std::size_t>(grid.ny);
  }
  [[nodiscard]] std::size_t observation(int ix, int iy) const {
    return static_cast<std::size_t>(iy) * static_cast<std::size_t>(grid.nx + 1) +
           static_cast<std::size_t>(ix);
  }
  [[nodiscard]] std::size_t index(int ix_obs, int iy_obs, std::size_t source) const {
    return observation(ix_obs, iy_obs) * grid.size() + source;
  }
  /// Zero matrices on `grid`.
  static SurfaceCompliance zeros(const contact::mim::Grid& grid);
  /// The half-space pair's closed forms (annex B.3) on `grid`.
  static SurfaceCompliance half_space(const contact::mim::Grid& grid,
                                      const contact::CombinedMaterial& material);
  /// Adds the tangential entries (xx, xy, yx, yy) of `other` (same grid); zz is left alone.
  void add_tangential(const SurfaceCompliance& other);
  /// Throws std::invalid_argument naming the first inconsistent or non-finite entry.
  void validate(const std::string& where = "SurfaceCompliance") const;
};

class MatrixComplianceOperator final : public contact::mim::KernelOperator {
 public:
  /// `reference`: the half-space pair whose FFT inverse, scaled to the mean tangential
  /// self-compliance, preconditions the tangential solver.
  MatrixComplianceOperator(SurfaceCompliance coefficients,
                           const contact::CombinedMaterial& reference);
  ~MatrixComplianceOperator() override;

  [[nodiscard]] const contact::mim::Grid& grid() const override { return c_.grid; }
  [[nodiscard]] const SurfaceCompliance& coefficients() const { return c_; }

 private:
  // out(ix, iy) += sum_s k(observation(ix + shift, iy), s) in(s) over the grid's ix.
  void accumulate(const std::vector<double>& k, int shift, const double* in,
                  double* out) const override;
  SurfaceCompliance c_;
};

}  // namespace ferro::fe_contact
