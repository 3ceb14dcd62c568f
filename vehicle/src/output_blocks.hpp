#pragma once
// The block structure of a system with output states (OdeSystem::output_states): filters of the
// system's own quantities that feed nothing back, so its Jacobian, and every Newton matrix
// I - gamma h J, is block lower triangular, [A 0; C D], the other ("dynamic") states first.
// A is dense; C and D are kept by their non-zeros (D always with its diagonal), so copying and
// scaling a matrix costs the dynamic block and the few couplings, not the square of the whole
// state count. The LU factors A and each group of output states that D connects (one filter
// cascade) and solves A x_d = b_d, then D x_o = b_o - C x_d group by group. Used by the bdf2
// loop and by the SUNDIALS adapters' linear solver.
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "ferro/vehicle/ode_system.hpp"

namespace ferro::vehicle::detail {

/// The partition of the states into dynamic and output states.
struct OutputBlocks {
  std::vector<Eigen::Index> dynamic, output;  ///< state indices, increasing
  std::vector<Eigen::Index> slot;             ///< per state: its index in dynamic or output
  std::vector<char> is_output;                ///< per state: 1 for an output state

  /// The partition of `system`'s states, or null when it declares no output states, or when
  /// `pattern` (its jacobian_pattern(), column j listing the rows column j reaches; empty when
  /// unknown) shows an output state reaching a dynamic state's derivative.
  [[nodiscard]] static std::shared_ptr<const OutputBlocks> make(
      const OdeSystem& system, const std::vector<std::vector<int>>& pattern);
  /// Every state dynamic (a plain dense matrix in block form).
  [[nodiscard]] static std::shared_ptr<const OutputBlocks> all_dynamic(std::size_t n);
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

/// LU of an OutputBlockMatrix: partial-pivoting LU of A and of each connected group of D.
class OutputBlockLu {
 public:
  /// False when a pivot is zero or not finite (the matrix is singular to working precision).
  bool compute(const OutputBlockMatrix& m);
  /// x = M^-1 b over the whole state vector (b and x of the matrix's state count, distinct).
  void solve(const OutputBlockMatrix& m, const double* b, double* x) const;

 private:
  Eigen::PartialPivLU<Eigen::MatrixXd> dynamic_;
  struct Group {
    std::vector<Eigen::Index> slots;  ///< output slots
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  };
  std::vector<Group> groups_;
};

}  // namespace ferro::vehicle::detail
