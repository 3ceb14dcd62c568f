#pragma once
// Normal contact problem on a regular grid: bound-constrained conjugate gradients.
//
// References: Toumi (2016) eqs. (77)-(87) (complementarity, approach or load control);
// Polonsky & Keer, "A numerical method for solving rough contact problems based on the
// multi-level multi-summation and conjugate gradient techniques", Wear 231 (1999) 206-219
// (the constrained CG iteration used here, with force control by mean-gap removal).
// Known deviations: the thesis's MIM re-solves an active set with plain CG (step 2-5 of
// section 2.2.2.3) and borders the matrix for load control (eq. 87); this implementation reaches
// the same discrete solution with the Polonsky-Keer constrained CG, which never forms A^zz
// (products by FFT, InfluenceOperator). Stopping test: the complementarity residuals below.

#include <limits>

#include "ferro/contact/mim/grid.hpp"
#include "ferro/contact/mim/influence_operator.hpp"

namespace ferro::contact::mim {

struct NormalSolverOptions {
  /// Stop when max |e_z| over the contact elements and the worst penetration outside are both
  /// below tolerance * (largest normal displacement) [-].
  double tolerance = 1.0e-8;
  int max_iterations = 5000;
  void validate(const std::string& where = "NormalSolverOptions") const;
};

struct NormalGridSolution {
  Field pressure;             ///< p_n per element [Pa]
  Field deformed_gap;         ///< e_z = u_z + z - delta per element [m]
  double normal_force = 0.0;  ///< F_n = dx dy sum p [N] (eq. 85)
  double approach = 0.0;      ///< delta [m]
  int iterations = 0;
  int contact_elements = 0;
  /// Elements of the outermost grid rows/columns carrying pressure: > 0 means the patch reaches
  /// the grid boundary and is probably truncated (enlarge the grid).
  int boundary_contact_elements = 0;
  /// max |e_z| over elements with p > 0, divided by the largest u_z [-].
  double gap_residual = std::numeric_limits<double>::quiet_NaN();
  /// max(-e_z) over elements with p = 0 (penetration), divided by the largest u_z [-].
  double penetration_residual = std::numeric_limits<double>::quiet_NaN();
  bool converged = false;
};

/// Prescribed approach delta [m]; `gap` is the undeformed separation z(x, y) [m] per element.
[[nodiscard]] NormalGridSolution solve_normal_approach(ComplianceOperator& op, const Field& gap,
                                                       double approach,
                                                       const NormalSolverOptions& options = {});

/// Prescribed total normal force F_n > 0 [N]; the approach is an output.
[[nodiscard]] NormalGridSolution solve_normal_force(ComplianceOperator& op, const Field& gap,
                                                    double normal_force,
                                                    const NormalSolverOptions& options = {});

}  // namespace ferro::contact::mim
