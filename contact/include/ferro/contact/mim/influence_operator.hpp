#pragma once
// Matrix-free influence products u = A p on a regular grid by zero-padded FFT convolution, for
// the elastic half-space, optionally with an interfacial (third-body) layer.
//
// References: Toumi (2016) eqs. (74)-(76), (100), (117)-(120); annex B.3 for the coefficients.
// Vollebregt, "User guide for CONTACT" (2014) and Liu, Wang & Liu, Wear 243 (2000) for
// discrete convolution + FFT (DC-FFT) with zero padding, which makes the cyclic convolution
// equal to the aperiodic (Toeplitz) sum exactly.
// Interfacial layer: Vollebregt, CONTACT user guide, "interfacial layer" (a thin layer of thickness
// h and shear modulus G3 between the bodies adds the local tangential compliance h / G3, i.e. a
// term on the diagonal of A^tt); Toumi (2016) section 3 (third-body layer on the rail).
// Known deviations: products are exact up to round-off (no truncation of the kernel). The layer
// adds tangential compliance only: its normal compliance h / (lambda3 + 2 G3) is not modelled.

#include <memory>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/compliance_operator.hpp"
#include "ferro/contact/mim/grid.hpp"

namespace ferro::contact::mim {

/// Holds the FFTW plans, the kernel spectra and the work buffers for one grid and one material
/// pair. Plans are made once in the constructor and reused by every product. The products are
/// not thread-safe (they share the work buffers); use one operator per thread.
class InfluenceOperator final : public ComplianceOperator {
 public:
  /// `measure_plans` asks FFTW to time candidate algorithms (slower construction, faster
  /// products); the default estimates.
  InfluenceOperator(const Grid& grid, const CombinedMaterial& material, bool measure_plans = false);
  /// Half-space plus an interfacial layer of local tangential compliance
  /// `layer_compliance` = h / G3 [m/Pa] (>= 0; 0 is the plain half-space).
  InfluenceOperator(const Grid& grid, const CombinedMaterial& material, double layer_compliance,
                    bool measure_plans = false);
  ~InfluenceOperator() override;

  [[nodiscard]] const Grid& grid() const override;
  [[nodiscard]] const CombinedMaterial& material() const override;

  /// u_z = A^zz p_n [m] for pressures p_n [Pa]; arrays of grid().size().
  void normal(const double* pressure, double* displacement_z) override;
  /// u = A^tt tau [m] (eqs. 70-71, 100) for tractions (tau_x, tau_y) [Pa].
  void tangential(const double* traction_x, const double* traction_y, double* displacement_x,
                  double* displacement_y) override;
  /// d = (B^tt - A^tt) tau / h [-] with B^tt(X) = A^tt(X + h), h = dx (eqs. 117-120): the
  /// forward difference of the tangential displacement towards the leading edge (+x).
  void rolling_difference(const double* traction_x, const double* traction_y, double* out_x,
                          double* out_y) override;

  /// Preconditioner: the exact inverse of the cyclic (circulant) extension of A^tt on the
  /// zero-padded FFT grid, applied to a grid field and restricted back to the grid [Pa / m].
  /// Approximates (A^tt restricted to a patch)^-1 (Strang/Chan-type circulant preconditioner).
  void tangential_inverse(const double* in_x, const double* in_y, double* out_x, double* out_y) override;

  /// Operator on the grid coarsened by two in each direction (element (I, J) covers fine
  /// elements 2I..2I+1, 2J..2J+1), created on first use and kept. Used for nested iteration.
  [[nodiscard]] bool has_coarse() const override { return true; }
  [[nodiscard]] InfluenceOperator& coarse() override;
  /// Interfacial-layer compliance h / G3 [m/Pa] (0: plain half-space).
  [[nodiscard]] double layer_compliance() const;

  /// Self-influence A^zz of an element on itself [m/Pa] (diagonal of A^zz).
  [[nodiscard]] double normal_self() const override;
  /// Diagonal entries A^xx_ii, A^yy_ii [m/Pa].
  [[nodiscard]] double tangential_self_x() const override;
  [[nodiscard]] double tangential_self_y() const override;
  /// Diagonal of -(B^xx - A^xx)/h, i.e. (A^xx(0) - A^xx(h))/h [1/Pa].
  [[nodiscard]] double rolling_self() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ferro::contact::mim
