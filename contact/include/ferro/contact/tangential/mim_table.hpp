#pragma once
// Tabulated MIM: steady-rolling creep forces of Hertzian patches precomputed with the MIM solver
// over normalised creepages and the ellipse ratio, stored in HDF5, interpolated by the
// tangential model "mim_table" (option "table" = path of the HDF5 file).
//
// Normalisation (exact for Hertzian patches with K = 0 at a fixed nu: the dimensionless
// steady-rolling problem depends only on a/b, nu and the creepages scaled by G c / (mu p0)):
//   s = mu F_n,  c = sqrt(a b),  C_ij = Kalker's coefficients (annex A.2) at (a/b, nu_table),
//   xi_x* = G a b C11 xi_x / s,  xi_y* = G a b C22 xi_y / s,  phi* = G c^3 C23 phi / s,
//   f_x = F_x / s,  f_y = F_y / s,  m_z = M_z / (s c).
// With this scaling the linear-theory slopes are 1 along each axis (Kalker's theory would give
// f_x = -xi_x*), and saturation starts near 1. Symmetries of the Hertzian problem (reversal of
// all creepages negates the forces; the y-mirror maps (xi_y, phi) -> (-xi_y, -phi) and
// (f_y, m_z) -> (-f_y, -m_z)) give f_x(-xi_x) = -f_x, f_y(-xi_x) = f_y, m_z(-xi_x) = m_z, so
// the table stores xi_x* >= 0 and xi_y* >= 0 only. HDF5 layout: docs/OUTPUT.md
// (format_version 2: the spin axis holds psi = phi* kappa(a/b) / kappa(1), see
// mim_table_spin_scale, so that every a/b saturates at about the same psi: at a/b = 0.2 the
// force saturates by phi* ~ 0.25, at a/b = 1 near phi* ~ 1).
// The interpolated force is bounded by Coulomb: |(f_x, f_y)| <= 1.
// K_ij reduction factors enter through the normalisation: xi_x* = G a b K11 C11 xi_x / s etc.
// (the linear slopes become K_ij C_ij as in the other models, the full-slip limit stays mu F_n;
// the shape of the transition is the full theory's, stretched along each creepage axis).
//
// References: Toumi (2016) chapter 2 (MIM), eqs. (38)-(40) (signs, C_ij), annex A.2; Kalker,
// "Three-dimensional elastic bodies in rolling contact" (1990) ch. 2 (normalisation).
// Known deviations: nu is fixed per table (a problem whose combined nu differs by more than
// 0.02 is rejected); outside the table the creepage vector is scaled down onto the table's box
// (direction kept; the box edges are in or near full slip) and a/b is clamped to the axis;
// interpolation is tensor-product cubic Hermite (three-point derivatives), not exact between
// nodes; the table's MIM grid (`elements`) sets its discretisation error.

#include <string>
#include <vector>

#include "ferro/contact/tangential/tangential_model.hpp"

namespace ferro::contact {

struct MimTableSpec {
  std::vector<double> ratio;  ///< a/b nodes [-], increasing, > 0 (interpolated in log a/b)
  std::vector<double> xi_x;   ///< xi_x* nodes, increasing, first 0 [-]
  std::vector<double> xi_y;   ///< xi_y* nodes, increasing, first 0 [-]
  std::vector<double> spin;   ///< psi nodes (spin in its saturation scale), increasing [-]
  double poisson = 0.28;      ///< combined nu of the table [-]
  int elements = 20;          ///< MIM elements across the shorter axis (grid "minor") [-]
  /// MIM grid of every node, as the mim model's option: "minor" (square elements, `elements`
  /// across the shorter axis), "patch" (`elements` x `elements` over the patch) or
  /// "patch_richardson" (patch grid, forces extrapolated from `elements` and ceil(elements/2)).
  std::string grid = "minor";
  int threads = 1;  ///< build threads (one MIM solver each)
  /// Node density: each interval of xi_x, xi_y and spin is split into `density` equal parts
  /// before the build (1 = the nodes as given) [-].
  int density = 1;
  void validate() const;
  /// The spec with the density applied (density 1).
  [[nodiscard]] MimTableSpec densified() const;
  /// Default table: 5 ratios 0.2 ... 5 (log-spaced), 8 x 8 x 29 creepage/spin nodes, MIM 20 x 20
  /// over the patch with Richardson extrapolation from 10 x 10 (grid "patch_richardson").
  static MimTableSpec default_spec();
};

/// Spin saturation scale kappa(a/b) / kappa(1), kappa = max(C11 b, C22 a) / (sqrt(ab) C23): the
/// largest rigid slip of the spin across the patch (phi b along x, phi a along y) in the linear
/// units of that direction, per unit phi*. Table spin nodes are psi = phi* times this factor.
[[nodiscard]] double mim_table_spin_scale(double ratio, double poisson);

/// Normalised creepages/forces of one evaluation (see the file comment).
struct MimTablePoint {
  double xi_x = 0.0, xi_y = 0.0, spin = 0.0;
};
struct MimTableValue {
  double f_x = 0.0, f_y = 0.0, m_z = 0.0;
};

class MimTable {
 public:
  /// Computes every node with the MIM (Hertzian gap, unit load, mu = 1, nu = spec.poisson).
  [[nodiscard]] static MimTable build(const MimTableSpec& spec);
  /// Reads a table written by write_hdf5; throws std::invalid_argument naming the file (and the
  /// dataset) when it cannot be opened or its layout is wrong, io::Hdf5Error when a dataset
  /// cannot be read.
  [[nodiscard]] static MimTable read_hdf5(const std::string& path);
  void write_hdf5(const std::string& path) const;

  /// Interpolated normalised forces at a/b = ratio and normalised creepages (any signs).
  [[nodiscard]] MimTableValue at(double ratio, MimTablePoint p) const;
  /// Forces of a Hertzian problem (normalises with the problem's G, a, b, F_n, mu).
  [[nodiscard]] TangentialSolution forces(const TangentialProblem& problem) const;
  /// Normalised creepages of a problem (for tests and the builder).
  [[nodiscard]] MimTablePoint normalise(const TangentialProblem& problem) const;

  [[nodiscard]] const MimTableSpec& spec() const { return spec_; }
  /// Node value (ir, ix, iy, is), row-major in that order.
  [[nodiscard]] MimTableValue node(int ir, int ix, int iy, int is) const;

 private:
  MimTableSpec spec_;
  std::vector<double> fx_, fy_, mz_;  ///< [ratio][xi_x][xi_y][spin]
  std::vector<double> log_ratio_;     ///< log of spec_.ratio
  std::vector<double> spin_scale_;    ///< mim_table_spin_scale at each ratio node
  void init_axes();
  [[nodiscard]] std::size_t index(int ir, int ix, int iy, int is) const;
};

/// One point of the table-versus-direct error map (normalised units of the file comment).
struct MimTableErrorPoint {
  double ratio = 0.0;                         ///< a/b [-]
  double xi_x = 0.0, xi_y = 0.0, spin = 0.0;  ///< xi_x*, xi_y*, phi* [-]
  MimTableValue table;                        ///< interpolated
  MimTableValue direct;                       ///< MIM on the table's grid
  double error = 0.0;                         ///< |f_table - f_direct| (x, y) [mu F_n]
};

/// Largest xi_x*, xi_y* and |psi| drawn by the error map (the transition and the onset of full
/// slip, where interpolation is hardest).
constexpr double kErrorMapCreepMax = 3.0;

/// Table against direct MIM (same elements) at `points` seeded random points: a/b log-uniform
/// over the table, xi_x*, xi_y* uniform in [0, kErrorMapCreepMax], psi uniform in +-3.
[[nodiscard]] std::vector<MimTableErrorPoint> mim_table_error_map(const MimTable& table, int points,
                                                                  unsigned seed = 1,
                                                                  int threads = 1);

/// Tangential model "mim_table": option "table" (HDF5 path, required).
class MimTableModel final : public TangentialModel {
 public:
  static std::unique_ptr<TangentialModel> from_options(const ModelOptions& options);
  explicit MimTableModel(MimTable table) : table_(std::move(table)) {}
  [[nodiscard]] std::string_view name() const override { return "mim_table"; }
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;
  [[nodiscard]] const MimTable& table() const { return table_; }

 private:
  MimTable table_;
};

}  // namespace ferro::contact
