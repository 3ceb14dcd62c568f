#pragma once
// Tangential contact problems on the MIM grid: sliding with rigid shifts and steady rolling with
// creepages, Coulomb friction, adhesion/slip partition.
//
// References: Toumi (2016) eqs. (97)-(107) (sliding: s = u - delta_rigid, eqs. 103-105) and
// (111)-(123) (steady rolling: w/V = c - (B^tt - A^tt) tau / h, h = dx, c = (xi_x - y phi,
// xi_y + x phi)); Kalker, "Three-dimensional elastic bodies in rolling contact" (1990) ch. 5;
// Vollebregt, "A Gauss-Seidel type solver for special convex programs, with application to
// frictional contact mechanics", JOTA 87 (1995) for the active-set view.
// Known deviations: the thesis re-solves with an LU / CG inverse of A^tt after clipping the
// tractions (eq. 107); here the same discrete equations are solved matrix-free by an active-set
// (semi-smooth) Newton method: stick elements carry w = 0 (two equations), slip elements keep
// |tau| = mu p_n and carry the linearised direction condition tau = -mu p_n w/|w| (one equation
// for the component across the current direction); each linear system is solved by restarted
// GMRES with FFT products (right preconditioner: the FFT inverse of the circulant extension of
// A^tt, for rolling composed with the exact inverse of the x-difference, a running sum from the
// leading edge). Sets are updated (stick -> slip when
// |tau| > mu p_n as eq. 107, slip -> stick when w turns along tau) until the stick velocity and
// slip direction residuals are below tolerance.
// Steady rolling: the thesis's difference (B^tt - A^tt) tau / h (eq. 113) is first order at the
// element centre (it is centred half an element downstream, which leaves an O(h) error in the
// spin term, phi h / 2 of lateral rigid slip); it is used as D in the second-order upwind
// difference 1.5 D_i - 0.5 D_{i+1} = (-3 u_i + 4 u_{i+1} - u_{i+2}) / (2h) (first order only in
// the last grid column, outside the patch).
// Quasi-identical bodies (K = 0): tangential tractions do not change the pressure.

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "ferro/contact/mim/gmres.hpp"
#include "ferro/contact/mim/grid.hpp"
#include "ferro/contact/mim/influence_operator.hpp"

namespace ferro::contact::mim {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Rigid tangential shift of body 1 relative to body 2 (Cattaneo-Mindlin), eq. (97).
struct SlidingInput {
  double shift_x = kNaN;   ///< delta_x [m]
  double shift_y = kNaN;   ///< delta_y [m]
  double friction = kNaN;  ///< mu [-]
  void validate(const std::string& where = "SlidingInput") const;
};

/// Steady rolling towards +x with creepages, eq. (111).
struct RollingInput {
  double creepage_x = kNaN;  ///< xi_x [-]
  double creepage_y = kNaN;  ///< xi_y [-]
  double spin = kNaN;        ///< phi [1/m]
  double friction = kNaN;    ///< mu [-]
  void validate(const std::string& where = "RollingInput") const;
};

struct TangentialSolverOptions {
  /// Convergence: RMS over the stick elements of the slip velocity w (rolling) or slip s
  /// (sliding), and RMS over the slip elements of its component across the traction direction,
  /// both relative to the largest rigid slip |c|, below this value, with unchanged sets [-].
  double tolerance = 1.0e-5;
  /// Relative linear residual of the Newton steps taken while the stick/slip sets still change
  /// (inexact Newton); the last step is solved to the tolerance [-].
  double newton_forcing = 1.0e-2;
  int max_outer_iterations = 200;
  int max_matvecs = 20000;  ///< cap on FFT products in total
  int gmres_restart = 80;
  /// Start from the solution on the grid coarsened by two (recursively while both sides have
  /// >= 24 elements): same equations and tolerance on the final grid, fewer iterations.
  bool nested = false;
  /// Precondition the stick rows with the FFT inverse of the circulant extension of A^tt
  /// (one more FFT pair per Krylov iteration) on grids of at least this many elements; smaller
  /// grids use diagonal scaling (0: always the FFT inverse; a huge value: never). Measured: the
  /// FFT inverse halves the products on the sphere case at 100^2-200^2 elements (-25 to -40 %
  /// time); on small or elongated grids it saves fewer products than it costs (25 x 25 over a
  /// Hertzian patch: the same number of products, +60 % time; +40 % at 40 elements across).
  int fft_preconditioner_min_elements = 4096;
  /// RMS linear residual of a Newton step, relative to tolerance x max rigid slip [-].
  double linear_factor = 0.3;
  void validate(const std::string& where = "TangentialSolverOptions") const;
};

enum class ElementState : std::uint8_t { exterior = 0, stick = 1, slip = 2 };

struct TangentialGridSolution {
  Field traction_x;  ///< tau_x [Pa]
  Field traction_y;  ///< tau_y [Pa]
  /// Slip per element: sliding s = u - delta [m]; rolling w/V [-] (eq. 119). Zero in stick.
  Field slip_x;
  Field slip_y;
  std::vector<ElementState> state;
  double force_x = 0.0;   ///< F_x = dx dy sum tau_x [N]
  double force_y = 0.0;   ///< F_y [N]
  double moment_z = 0.0;  ///< M_z = dx dy sum (x tau_y - y tau_x) about the grid origin [N m]
  int stick_elements = 0;
  int slip_elements = 0;
  int outer_iterations = 0;
  int matvecs = 0;  ///< FFT influence products used
  /// RMS of |v| over stick elements / max |rigid slip| [-] (v = s or w/V)
  double stick_residual = kNaN;
  /// RMS over slip elements of the slip-velocity component across the traction direction,
  /// / max |rigid slip| (direction misfit of eqs. 99, 116) [-]
  double direction_residual = kNaN;
  /// max (|tau| - mu p) / (mu max p) over the patch; <= 0 when Coulomb holds [-]
  double coulomb_residual = kNaN;
  bool converged = false;
};

/// Caller-owned scratch of the tangential solves: the Krylov basis (about restart x 2n doubles),
/// reused from solve to solve so that the allocator does not return it to the system and fault it
/// in again each time (a quarter of the time of a 25 x 25 solve). It carries nothing from one
/// solve to the next; one workspace serves one thread of solves.
struct TangentialWorkspace {
  GmresWorkspace gmres;
};

/// Sliding (shift) problem on the pressure field `pressure` [Pa] from the normal solve.
[[nodiscard]] TangentialGridSolution solve_sliding(ComplianceOperator& op, const Field& pressure,
                                                   const SlidingInput& input,
                                                   const TangentialSolverOptions& options,
                                                   TangentialWorkspace& workspace);

/// Steady rolling problem on the pressure field `pressure` [Pa] from the normal solve.
[[nodiscard]] TangentialGridSolution solve_steady_rolling(ComplianceOperator& op,
                                                          const Field& pressure,
                                                          const RollingInput& input,
                                                          const TangentialSolverOptions& options,
                                                          TangentialWorkspace& workspace);
/// Same with a workspace of its own (allocated for this solve).
[[nodiscard]] TangentialGridSolution solve_steady_rolling(
    ComplianceOperator& op, const Field& pressure, const RollingInput& input,
    const TangentialSolverOptions& options = {});

}  // namespace ferro::contact::mim
