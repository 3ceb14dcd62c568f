#pragma once
// Surface-compliance operator of the MIM solvers: the products u = A p, u = A^tt tau and the
// rolling difference (B^tt - A^tt) tau / h on a regular grid, for any compliance (half-space by
// FFT, half-space plus an interfacial layer, dense coefficients from a finite-element model).
//
// References: Toumi (2016) eqs. (74)-(76), (100), (117)-(120).
// Known deviations: none (an interface; the implementations state theirs).

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/grid.hpp"

namespace ferro::contact::mim {

/// The normal, sliding and steady-rolling solvers take any ComplianceOperator. Products are not
/// thread-safe (implementations may share work buffers); use one operator per thread.
class ComplianceOperator {
 public:
  virtual ~ComplianceOperator() = default;
  ComplianceOperator() = default;
  ComplianceOperator(const ComplianceOperator&) = delete;
  ComplianceOperator& operator=(const ComplianceOperator&) = delete;

  [[nodiscard]] virtual const Grid& grid() const = 0;
  /// Half-space material the operator is built on or compared with (preconditioner scale).
  [[nodiscard]] virtual const CombinedMaterial& material() const = 0;

  /// u_z = A^zz p_n [m] for pressures p_n [Pa]; arrays of grid().size().
  virtual void normal(const double* pressure, double* displacement_z) = 0;
  /// u = A^tt tau [m] (eqs. 70-71, 100) for tractions (tau_x, tau_y) [Pa].
  virtual void tangential(const double* traction_x, const double* traction_y,
                          double* displacement_x, double* displacement_y) = 0;
  /// d = (B^tt - A^tt) tau / h [-] with B^tt(X) = A^tt(X + h), h = dx (eqs. 117-120): the
  /// forward difference of the tangential displacement towards the leading edge (+x).
  virtual void rolling_difference(const double* traction_x, const double* traction_y,
                                  double* out_x, double* out_y) = 0;
  /// Preconditioner: an approximation of (A^tt restricted to a patch)^-1 applied to a grid
  /// field [Pa / m].
  virtual void tangential_inverse(const double* in_x, const double* in_y, double* out_x,
                                  double* out_y) = 0;

  /// Whether coarse() exists (nested iteration of the tangential solver needs it).
  [[nodiscard]] virtual bool has_coarse() const = 0;
  /// Same compliance on the grid coarsened by two in each direction (element (I, J) covers fine
  /// elements 2I..2I+1, 2J..2J+1), created on first use and kept. Throws std::logic_error when
  /// has_coarse() is false.
  [[nodiscard]] virtual ComplianceOperator& coarse() = 0;

  /// Self-influence A^zz of an element on itself [m/Pa] (diagonal of A^zz).
  [[nodiscard]] virtual double normal_self() const = 0;
  /// Diagonal entries A^xx_ii, A^yy_ii [m/Pa].
  [[nodiscard]] virtual double tangential_self_x() const = 0;
  [[nodiscard]] virtual double tangential_self_y() const = 0;
  /// Diagonal of -(B^xx - A^xx)/h, i.e. (A^xx(0) - A^xx(h))/h [1/Pa].
  [[nodiscard]] virtual double rolling_self() const = 0;
};

}  // namespace ferro::contact::mim
