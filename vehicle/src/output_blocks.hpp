#pragma once
// The block structure of a system with output states (OdeSystem::output_states): filters of the
// system's own quantities that feed nothing back, so its Jacobian, and every Newton matrix
// I - gamma h J, is block lower triangular, [A 0; C D], the other ("dynamic") states first.
// A is stored dense; C and D are kept by their non-zeros (D always with its diagonal), so copying
// and scaling a matrix costs the dynamic block and the few couplings, not the square of the
// whole state count. The LU factors A and each group of output states that D connects (one
// filter cascade) and solves A x_d = b_d, then D x_o = b_o - C x_d group by group. When the
// system's Jacobian pattern is known, A can be factored as a sparse matrix of that pattern (a
// vehicle's bodies couple to their neighbours only: a quarter of A is non-zero, and the factors
// of the main ERRI scene hold 40 % of a dense LU's entries). Used by the bdf2
// loop and by the SUNDIALS adapters' linear solver.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <memory>
#include <vector>

#include "ferro/vehicle/ode_system.hpp"

namespace ferro::vehicle::detail {

/// The partition of the states into dynamic and output states.
struct OutputBlocks {
  std::vector<Eigen::Index> dynamic, output;  ///< state indices, increasing
  std::vector<Eigen::Index> slot;             ///< per state: its index in dynamic or output
  std::vector<char> is_output;                ///< per state: 1 for an output state
  /// The non-zeros of the dynamic block A (the Jacobian's pattern and the diagonal), column by
  /// column in dynamic slots, rows increasing; empty: A is factored dense.
  std::vector<std::vector<Eigen::Index>> dynamic_pattern;

  /// The partition of `system`'s states, or null when it declares no output states, or when
  /// `pattern` (its jacobian_pattern(), column j listing the rows column j reaches; empty when
  /// unknown) shows an output state reaching a dynamic state's derivative. With `sparse` (and
  /// a pattern) A is factored by a sparse LU whose ordering is found once for the pattern.
  [[nodiscard]] static std::shared_ptr<const OutputBlocks> make(
      const OdeSystem& system, const std::vector<std::vector<int>>& pattern, bool sparse = false);
  /// Every state dynamic; A dense, or sparse by `pattern` (as make()) when it is given.
  [[nodiscard]] static std::shared_ptr<const OutputBlocks> all_dynamic(
      std::size_t n, const std::vector<std::vector<int>>& pattern = {});
};

/// A non-zero of the C or D block: row (output slot), column (dynamic slot for C, output slot
/// for D), value.
struct BlockEntry {
  Eigen::Index row, col;
  double value;
};

/// A matrix in block form: the dynamic block A dense, C and D by their entries.
struct OutputBlockMatrix {
  std::shared_ptr<const OutputBlocks> blocks;
  Eigen::MatrixXd a;
  std::vector<BlockEntry> c, d;

  OutputBlockMatrix() = default;
  explicit OutputBlockMatrix(std::shared_ptr<const OutputBlocks> b);
  /// All entries zero (C and D emptied).
  void set_zero();
  /// Element (i, j) of the whole matrix, by state indices. An output column reaching a dynamic
  /// row has no place in the block form: the caller must not set one (OutputBlocks::make).
  void set(std::size_t i, std::size_t j, double value);
  /// C's entries by increasing column (the order in which the solve subtracts them), for a
  /// caller that set them in another order.
  void order_by_column();
  /// M = g M + I.
  void scale_add_identity(double g);
};

/// False when a pivot of `lu` is zero or not finite (singular to working precision).
[[nodiscard]] bool pivots_ok(const Eigen::PartialPivLU<Eigen::MatrixXd>& lu);

/// LU of an OutputBlockMatrix: partial-pivoting LU of A (dense, or sparse when the blocks
/// carry A's pattern: Eigen's SparseLU, column ordering by COLAMD found on the first
/// factorisation and kept for the next ones of the same object) and of each connected group of
/// D.
class OutputBlockLu {
 public:
  /// False when a pivot is zero or not finite (the matrix is singular to working precision).
  bool compute(const OutputBlockMatrix& m);
  /// x = M^-1 b over the whole state vector (b and x of the matrix's state count, distinct).
  void solve(const OutputBlockMatrix& m, const double* b, double* x) const;
  /// The first half of solve(): x's dynamic entries (x_d = A^-1 b_d); its output entries are
  /// not written. A Newton iteration whose convergence test leaves the output states out
  /// needs no more until it has converged.
  void solve_dynamic(const OutputBlockMatrix& m, const double* b, double* x) const;
  /// The second half: x's output entries from b's and the x_d of the last solve_dynamic()
  /// (x_o = D^-1 (b_o - C x_d)); its dynamic entries are not written.
  void solve_outputs(const OutputBlockMatrix& m, const double* b, double* x) const;

 private:
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
  Eigen::PartialPivLU<Eigen::MatrixXd> dynamic_;
  /// The sparse path: A's non-zeros, its LU (pattern analysed once), whether it is in use.
  SparseMatrix sparse_matrix_;
  std::unique_ptr<Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>>> sparse_;
  bool sparse_analysed_ = false, sparse_ok_ = false;
  struct Group {
    std::vector<Eigen::Index> slots;  ///< output slots
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  };
  std::vector<Group> groups_;
  /// Work vectors of solve(), sized on the first call.
  mutable Eigen::VectorXd bd_, xd_, bo_, bg_, xg_;
};

}  // namespace ferro::vehicle::detail
