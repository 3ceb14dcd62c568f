#pragma once
// MIM (boundary-element) rolling contact in one call: normal problem, then steady rolling, with
// the results a tangential-model adapter needs (forces, moment, approach, fields).
//
// References: Toumi (2016) chapter 2 (eqs. 74-123); see normal_solver.hpp and
// tangential_solver.hpp.
// Known deviations: quasi-identical bodies (K = 0); see the solver headers.

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/grid.hpp"
#include "ferro/contact/mim/influence_operator.hpp"
#include "ferro/contact/mim/normal_solver.hpp"
#include "ferro/contact/mim/tangential_solver.hpp"

namespace ferro::contact::mim {

/// Normal load: exactly one of the two must be set (the other NaN).
struct NormalLoad {
  double normal_force = std::numeric_limits<double>::quiet_NaN();  ///< F_n [N]
  double approach = std::numeric_limits<double>::quiet_NaN();      ///< delta [m]
  void validate(const std::string& where = "NormalLoad") const;
};

struct MimOptions {
  NormalSolverOptions normal;
  TangentialSolverOptions tangential;
};

/// Complete MIM solution. Fields are on `grid` (row-major, x fastest). Forces act on body 1
/// (the body whose displacement is u1 in u = u1 - u2), in the contact frame: x rolling
/// direction, z normal.
struct MimResult {
  Grid grid;
  double normal_force = 0.0;        ///< F_n [N]
  double force_x = 0.0;             ///< F_x [N]
  double force_y = 0.0;             ///< F_y [N]
  double moment_z = 0.0;            ///< M_z about the grid origin [N m]
  double approach = 0.0;            ///< delta [m]
  Field pressure;                   ///< p_n [Pa]
  Field traction_x;                 ///< tau_x [Pa]
  Field traction_y;                 ///< tau_y [Pa]
  Field slip_x;                     ///< w_x / V in slip elements [-]
  Field slip_y;                     ///< w_y / V in slip elements [-]
  std::vector<ElementState> state;  ///< exterior / stick (adhesion) / slip
  // Convergence record
  /// The pressure reaches the outermost grid elements: the patch is probably truncated.
  bool patch_truncated = false;
  int normal_iterations = 0;
  double gap_residual = 0.0;
  double penetration_residual = 0.0;
  int tangential_matvecs = 0;
  double stick_residual = 0.0;
  double direction_residual = 0.0;
  double coulomb_residual = 0.0;
  bool converged = false;
};

/// Normal then steady-rolling solve on an arbitrary undeformed gap z [m] sampled on op.grid();
/// `workspace` is the caller's scratch of the tangential solve.
[[nodiscard]] MimResult solve_rolling_contact(ComplianceOperator& op, const Field& gap,
                                              const NormalLoad& load, const RollingInput& rolling,
                                              const MimOptions& options,
                                              TangentialWorkspace& workspace);
/// Same with a workspace of its own (allocated for this solve).
[[nodiscard]] MimResult solve_rolling_contact(ComplianceOperator& op, const Field& gap,
                                              const NormalLoad& load, const RollingInput& rolling,
                                              const MimOptions& options = {});

/// Hertzian input, as a tangential (creep-force) model receives it.
struct HertzRollingInput {
  double semi_axis_x = std::numeric_limits<double>::quiet_NaN();   ///< a [m] (rolling direction)
  double semi_axis_y = std::numeric_limits<double>::quiet_NaN();   ///< b [m]
  double normal_force = std::numeric_limits<double>::quiet_NaN();  ///< F_n [N]
  RollingInput rolling;                                            ///< creepages, spin, mu
  Material body1;
  Material body2;
  int elements_minor = 40;  ///< elements across the shorter axis of the ellipse [-]
  /// false: `elements_minor` square elements across the shorter axis (N x N a/b elements at
  /// a/b >= 1); true: `elements_minor` x `elements_minor` rectangular elements over the patch
  /// (grid_over_ellipse), the same resolution of each axis at every a/b.
  bool grid_over_patch = false;
  /// Grid over the patch only: forces and moment extrapolated in the element count from this
  /// grid (N) and the grid of M = ceil(N / 2) (Richardson at second order, F = F_N + (F_N - F_M)
  /// M^2 / (N^2 - M^2)); fields, residuals and convergence are the N grid's (converged = both).
  /// About 1.3 x the cost of the N grid, and at N = 25 half the force error of N = 40 alone
  /// (docs/VALIDATION.md, bench contact).
  bool extrapolate = false;
  /// Throws std::invalid_argument naming the field; elements_minor must lie in
  /// [4, max_elements_minor(a, b)]; extrapolate needs grid_over_patch and elements_minor >= 12
  /// (the coarse grid of 6 x 6 or more).
  void validate(const std::string& where = "HertzRollingInput") const;
};

/// Largest grid a Hertzian MIM solve accepts [elements]. The FFT operator needs about 0.5 kB
/// per element (padded real and complex buffers, eleven kernel spectra), so this is some
/// 150 MB and a solve of a few tens of seconds; larger requests are bad input, not a job.
inline constexpr std::size_t kMaxGridElements = std::size_t{1} << 18;

/// Largest elements_minor (elements across the shorter axis) whose grid for an a x b ellipse
/// stays within kMaxGridElements; below 4 when the aspect ratio is too large for any grid.
[[nodiscard]] int max_elements_minor(double semi_axis_x, double semi_axis_y);

/// Builds the gap that reproduces the ellipse a x b under F_n (hertz_gap.hpp), a grid with
/// `elements_minor` elements across the shorter axis, solves. One-shot: builds its influence
/// operator; repeated calls should use HertzMimSolver, which keeps them.
[[nodiscard]] MimResult solve_hertz_rolling(const HertzRollingInput& input,
                                            const MimOptions& options = {});

/// Repeated Hertzian MIM solves (the body of a tangential-model adapter or a table builder).
/// The half-space influence coefficients are homogeneous (degree 1 in the element size, -1 in
/// G), so every patch is solved in units of the element size h and of G on a unit grid whose
/// influence operator (kernels + FFTW plans) depends only on (nx, ny, nu) and is cached; results
/// are scaled back (forces G h^2, moment G h^3, stresses G, approach h). The last normal
/// solution on each cached grid is reused when the next patch has the same unit-grid gap and
/// load (K = 0: the normal problem does not depend on the creepages; the reuse is exact). Not
/// thread-safe: use one solver per thread.
class HertzMimSolver {
 public:
  explicit HertzMimSolver(MimOptions options = {}, std::size_t max_cached_grids = 16);
  ~HertzMimSolver();
  HertzMimSolver(const HertzMimSolver&) = delete;
  HertzMimSolver& operator=(const HertzMimSolver&) = delete;

  [[nodiscard]] MimResult solve(const HertzRollingInput& input);
  /// Unit-grid operators built so far (cache misses).
  [[nodiscard]] int operators_built() const { return operators_built_; }

 private:
  struct Entry;
  MimResult solve_grid(const HertzRollingInput& input);
  MimOptions options_;
  std::size_t max_cached_;
  std::vector<std::unique_ptr<Entry>> cache_;
  TangentialWorkspace workspace_;  ///< scratch of the tangential solves, reused
  int operators_built_ = 0;
};

/// Writes grid, forces, convergence record and the fields (2-D datasets [ny][nx]: pressure_Pa,
/// traction_x_Pa, traction_y_Pa, slip_x, slip_y, state) into an HDF5 file (HDF5 C API). Throws
/// std::runtime_error if the file cannot be written.
void write_hdf5(const MimResult& result, const std::string& path);

}  // namespace ferro::contact::mim
