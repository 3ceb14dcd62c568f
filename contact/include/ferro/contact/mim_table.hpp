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
// the table stores xi_x* >= 0 and xi_y* >= 0 only. HDF5 layout: docs/OUTPUT.md.
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

#include "ferro/contact/tangential_model.hpp"

namespace ferro::contact {

struct MimTableSpec {
  std::vector<double> ratio;  ///< a/b nodes [-], increasing, > 0 (interpolated in log a/b)
  std::vector<double> xi_x;   ///< xi_x* nodes, increasing, first 0 [-]
  std::vector<double> xi_y;   ///< xi_y* nodes, increasing, first 0 [-]
  std::vector<double> spin;   ///< phi* nodes, increasing (negative and positive) [-]
  double poisson = 0.28;      ///< combined nu of the table [-]
  int elements = 20;          ///< MIM elements across the shorter axis [-]
  int threads = 1;            ///< build threads (one MIM solver each)
  void validate() const;
  /// Default table: 5 ratios 0.2 ... 5 (log-spaced), 8 x 8 x 11 creepage nodes, 16 elements.
  static MimTableSpec default_spec();
};

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
  /// Reads a table written by write_hdf5; throws std::invalid_argument naming the file and
  /// dataset when the layout is wrong, std::runtime_error when the file cannot be read.
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
  [[nodiscard]] std::size_t index(int ir, int ix, int iy, int is) const;
};

/// Tangential model "mim_table": option "table" (HDF5 path; default $FERRO_MIM_TABLE).
class MimTableModel final : public TangentialModel {
 public:
  explicit MimTableModel(MimTable table) : table_(std::move(table)) {}
  [[nodiscard]] std::string_view name() const override { return "mim_table"; }
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;
  [[nodiscard]] const MimTable& table() const { return table_; }

 private:
  MimTable table_;
};

}  // namespace ferro::contact
