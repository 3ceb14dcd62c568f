#pragma once
// A first-order ODE system x' = f(t, x) as the integrators see it, plus the named output
// signals a run records. Integrators contain no physics; models contain no integrator.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace ferro::vehicle {

/// Return codes of rhs(), SUNDIALS' contract: 0 ok, > 0 recoverable (the solver retries with a
/// smaller step), < 0 fatal (the run stops and reports the cause).
inline constexpr int kRhsOk = 0;
inline constexpr int kRhsRecoverable = 1;
inline constexpr int kRhsFatal = -1;

/// A bound |x[index]| <= limit that the state of a physical solution never leaves, derived from
/// the model's geometry (e.g. a wheelset's lateral displacement far beyond its flange
/// clearance): a state beyond it means the integration has diverged.
struct StateBound {
  std::size_t index = 0;
  double limit = 0.0;  ///< [state unit]
  std::string reason;  ///< what lies beyond, e.g. "the flange has crossed the rail head"
};

/// A named output signal with its SI unit.
struct SignalInfo {
  std::string name;
  std::string unit;
  std::string description;
};

class OdeSystem {
 public:
  virtual ~OdeSystem() = default;

  /// Number of states.
  [[nodiscard]] virtual std::size_t size() const = 0;
  /// x' = f(t, x). Must be a pure function of (t, x): no hidden mutable state (FSAL steppers reuse
  /// derivatives). Returns kRhsOk, a positive recoverable code or a negative fatal code.
  virtual int rhs(double t, std::span<const double> x, std::span<double> xdot) const = 0;
  /// State names with units, e.g. "y [m]"; size() entries.
  [[nodiscard]] virtual std::vector<SignalInfo> state_info() const = 0;
  /// Output signals derived from (t, x) (forces, creepages, ...), written beside the states.
  [[nodiscard]] virtual std::vector<SignalInfo> signal_info() const { return {}; }
  /// Evaluates signal_info().size() derived signals into `out`.
  virtual void signals(double t, std::span<const double> x, std::span<double> out) const {}
  /// Optional half-bandwidths of the Jacobian (upper, lower) for banded linear solvers;
  /// {-1, -1} when unknown (dense).
  [[nodiscard]] virtual std::pair<int, int> jacobian_bandwidth() const { return {-1, -1}; }
  /// Bounds no physical state leaves (the integrators' divergence guard: after every step each
  /// state must be finite and within them, or the run stops as a solver failure naming the
  /// state). Empty: finiteness only.
  [[nodiscard]] virtual std::vector<StateBound> state_bounds() const { return {}; }
  /// Output states, increasing: filters of the system's own quantities integrated with it (a
  /// low-pass of a force before the output grid samples it). No derivative of another state
  /// depends on them, and theirs are affine in them with a constant matrix. The adaptive
  /// SUNDIALS integrators leave them out of the error test, and the dense Newton solver solves
  /// them after the other states by substitution. Default: none.
  [[nodiscard]] virtual std::vector<std::size_t> output_states() const { return {}; }
  /// Optional scale of each state's absolute tolerance (atol_i = atol * scale_i), size() entries;
  /// empty when every state takes atol as it is. A model gives the rate of a stiff, fast
  /// component the natural frequency of that component as its scale: an error dv in the rate
  /// of a mode at omega moves its position by dv / omega.
  [[nodiscard]] virtual std::vector<double> tolerance_scales() const { return {}; }
  /// Optional structural sparsity of the Jacobian: for each state j, the states i whose rate
  /// may depend on state j at any state (a superset of the nonzeros is fine; a missing entry
  /// makes a finite-difference Jacobian wrong there); empty when unknown (dense).
  [[nodiscard]] virtual std::vector<std::vector<int>> jacobian_pattern() const { return {}; }
};

/// Groups of states whose Jacobian columns touch disjoint rows in `pattern` (a
/// jacobian_pattern()), so that one finite difference perturbing every state of a group gives
/// all of its columns (Curtis, Powell & Reid, IMA J. Appl. Math. 13 (1974) 117-119): greedy,
/// the columns taken largest first (most rows first, state order among equals; Welsh & Powell,
/// Computer J. 10 (1967) 85-86), each into the first group it does not clash with. No partition
/// has fewer groups than the largest row's count of non-zeros; on Manchester vehicle 1 with
/// its discrete track and output filters this ordering reaches that bound (48 groups, where
/// state order took 60). Groups list their states increasing. An empty pattern gives one group
/// per state.
[[nodiscard]] std::vector<std::vector<int>> jacobian_column_groups(
    const std::vector<std::vector<int>>& pattern, std::size_t n);

/// Central-difference Jacobian J = df/dx at (t, x), row-major size() x size(). Step per state:
/// h_j = rel_step * max(|x_j|, scale_j) with scale_j = 1 when not given. Throws
/// std::runtime_error when rhs fails.
[[nodiscard]] std::vector<double> numerical_jacobian(const OdeSystem& system, double t,
                                                     std::span<const double> x,
                                                     double rel_step = 1e-7,
                                                     std::span<const double> scale = {});

}  // namespace ferro::vehicle
