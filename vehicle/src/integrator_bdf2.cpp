// bdf2: the two-step backward differentiation formula at a fixed step, solved by a simplified
// Newton iteration with a finite-difference Jacobian kept over many steps.
//
// For a vehicle on a flexible track the stiffest modes (rails on the Hertz contact and the pads,
// 0.5-1 kHz, and the rails' roll under the creep forces, real eigenvalues near -1.6e4 /s) need
// no resolution for the vehicle's forces and motions below ~50 Hz, but they are excited at every
// change of the contact (point births on the tread, cell boundaries of a contact table), so an
// error-controlled method keeps its step at tens of microseconds to follow them. BDF2 is
// L-stable: at a fixed step it damps those modes in one step and answers the slow dynamics to
// second order; its accuracy at a step is measured against a tight-tolerance run
// (`ferrodyn bench work-precision`). SUNDIALS has no fixed-step mode for CVODE's BDF, and
// ARKODE's fixed-step DIRK stops at the first Newton failure; this loop refreshes its Jacobian
// and, as a last resort, splits the step when Newton does not converge.
//
// Formula: y_{n+1} - 4/3 y_n + 1/3 y_{n-1} = 2/3 h f(t_{n+1}, y_{n+1}); the first step (and a
// split step's pieces) by the implicit Euler formula y_{n+1} - y_n = h f(t_{n+1}, y_{n+1}).
// Newton on G(y) = y - psi - gamma h f(t, y) with the matrix I - gamma h J (J the Jacobian at the
// last refresh, forward differences with the increment sqrt(u max(1e-5, |y_j|)) as RADAU5 forms
// it, columns grouped by the system's sparsity pattern), from the predictor of the last three
// points; converged when the weighted RMS norm of the correction (weights 1 / (rtol |y_i| +
// atol_i), atol_i = atol times the system's tolerance scale of state i) falls below 0.1 (1 - rho)
// / rho given the observed contraction rho, or below 0.01 when the corrected iterate's residual
// is already within the tolerance. The system's output states stay out of both tests and out of
// the iterations: affine in themselves with a constant Jacobian and read by no other state, they
// are solved once, after the others have converged, from the last residual and correction. The
// Newton matrix is factored by a sparse LU on the system's Jacobian pattern (output_blocks.hpp),
// its fill-reducing column ordering found on the first factorisation of each kept factor slot
// and reused for the run. A Newton that diverges (a correction more than twice the
// previous one) or takes more than 8 iterations is restarted with a fresh Jacobian, then the
// step is taken as two implicit-Euler halves (recursively, down to h / 2^20). Outputs between two
// steps come from the quadratic
// through the last three points (second order, as the method).
//
// References: Hairer & Wanner, "Solving Ordinary Differential Equations II" (2nd ed., 1996),
// III.1 (BDF, stability), IV.8 (simplified Newton, convergence tests, RADAU5's Jacobian
// increments); Curtiss & Hirschfelder (1952).
// Known deviations: no error control (the step is the user's choice); a split step lowers the
// order to one over that step.

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "integrator_impl.hpp"
#include "output_blocks.hpp"

namespace ferro::vehicle::detail {
namespace {

using Vector = Eigen::VectorXd;

struct Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Bdf2 final : public Integrator {
 public:
  explicit Bdf2(const IntegratorSettings& s) : s_(s) {}
  [[nodiscard]] std::string name() const override { return "bdf2"; }
  IntegrationResult integrate(const OdeSystem& system, std::span<const double> x0,
                              const std::vector<double>& output_times,
                              const Observer& observer) override;

 private:
  /// f(t, y) into out; throws Failure when the right-hand side refuses (a recoverable code
  /// makes the caller split the step).
  void rhs(double t, const Vector& y, Vector& out) {
    if (monitor_->stop_requested()) throw StopRequested{};
    ++rhs_count_;
    const int code = system_->rhs(t, std::span<const double>(y.data(), n_),
                                  std::span<double>(out.data(), n_));
    if (code < 0) throw Failure(fmt::format("right-hand side failed (code {}) at t = {:.9g} s", code, t));
    if (code > 0) throw Recoverable{};
  }
  struct Recoverable {};

  /// Forward differences, one right-hand side per group of columns that touch disjoint rows
  /// (the system's jacobian_pattern()).
  void refresh_jacobian(double t, const Vector& y) {
    constexpr double kUnitRoundoff = 2.220446049250313e-16;
    Vector f0(n_), f1(n_), yp = y;
    rhs(t, y, f0);
    jacobian_.set_zero();
    for (const std::vector<int>& group : groups_) {
      for (const int j : group) {
        yp[j] = y[j] + std::sqrt(kUnitRoundoff * std::max(1e-5, std::abs(y[j])));
      }
      rhs(t, yp, f1);
      for (const int j : group) {
        const double inc = yp[j] - y[j];  // the increment actually represented
        yp[j] = y[j];
        const auto col = static_cast<std::size_t>(j);
        if (pattern_.empty()) {
          for (std::size_t i = 0; i < n_; ++i) jacobian_.set(i, col, (f1[i] - f0[i]) / inc);
          continue;
        }
        const std::vector<int>& rows = pattern_[col];
        for (const int i : rows) {
          const double v = (f1[i] - f0[i]) / inc;
          const auto row = static_cast<std::size_t>(i);
          // An output row keeps its non-zeros alone (most of a filter's couplings are exact
          // zeros: only its first section reads the model); the dynamic block keeps its pattern.
          if (v == 0.0 && row != col && blocks_->is_output[row] != 0) continue;
          jacobian_.set(row, col, v);
        }
        // An output state's diagonal, always in the block D.
        if (blocks_->is_output[col] != 0 && std::find(rows.begin(), rows.end(), j) == rows.end())
          jacobian_.set(col, col, 0.0);
      }
    }
    jacobian_.order_by_column();  // the groups set the columns out of order
    ++jacobians_;
    jacobian_age_ = 0;
    for (Factor& f : factors_) f.current = false;  // the Newton matrices must be refactored
  }

  /// The factored Newton matrix I - gamma_h J of the current Jacobian, in the output-block form
  /// (output_blocks.hpp) when the output states feed nothing back: the other states first, then
  /// the output states from theirs.
  struct Factor {
    double gamma_h = 0.0;
    bool current = false;  ///< factored from the current Jacobian
    OutputBlockMatrix matrix;
    OutputBlockLu lu;  ///< keeps its sparse ordering from one factorisation to the next
  };

  /// A step alternates between a few values of gamma_h (BDF2's 2h/3, the implicit-Euler halves
  /// of a split step): each is factored once per Jacobian and kept, in a fixed set of slots
  /// reused for the next Jacobians (the oldest factor gives its slot to a new one).
  const Factor& factor(double gamma_h) {
    for (const Factor& f : factors_) {
      if (f.current && f.gamma_h == gamma_h) return f;
    }
    Factor* f = nullptr;
    for (Factor& g : factors_) {
      if (!g.current) {
        f = &g;
        break;
      }
    }
    if (f == nullptr) {
      f = &factors_[next_slot_];
      next_slot_ = (next_slot_ + 1) % factors_.size();
    }
    f->gamma_h = gamma_h;
    f->current = true;
    f->matrix = jacobian_;
    f->matrix.scale_add_identity(-gamma_h);
    f->lu.compute(f->matrix);  // a singular matrix shows as a non-finite correction
    return *f;
  }

  [[nodiscard]] double wrms(const Vector& d, const Vector& y) const {
    double sum = 0.0;
    for (Eigen::Index i = 0; i < d.size(); ++i) {
      const double w = d[i] / (s_.rtol * std::abs(y[i]) + atol_[i]);
      sum += w * w;
    }
    return std::sqrt(sum / static_cast<double>(tested_));
  }

  /// Solves y - psi - gamma h f(t, y) = 0 from the predictor y; false when Newton fails.
  bool newton(double t, const Vector& psi, double gamma_h, Vector& y) {
    // Divergence: a correction more than twice the previous one (a contraction near 1 may still
    // converge within the iterations allowed, and a split step costs a refactorisation).
    constexpr double kRdiv = 2.0;
    const Factor& matrix = factor(gamma_h);
    Vector &f = f_, &r = r_, &d = d_;  // the run's work vectors
    // The iterations correct the other states only; the output states, which feed nothing back
    // and are affine in themselves, keep the predictor's values and are solved once, from the
    // last iteration's residual and correction (the block solve's second half): the same
    // Newton step for them as correcting them at every iteration, at one output solve a step.
    for (const Eigen::Index i : blocks_->output) d[i] = 0.0;
    const auto converged = [&] {
      matrix.lu.solve_outputs(matrix.matrix, minus_r_.data(), d.data());
      for (const Eigen::Index i : blocks_->output) {
        if (!std::isfinite(d[i])) return false;
        y[i] += d[i];
      }
      return true;
    };
    double previous = 0.0, rho = 0.0;
    for (int it = 0; it < 8; ++it) {
      try {
        rhs(t, y, f);
      } catch (const Recoverable&) {
        return false;
      }
      ++iterations_;
      r = y - psi - gamma_h * f;
      minus_r_ = -r;
      matrix.lu.solve_dynamic(matrix.matrix, minus_r_.data(), d.data());
      if (!d.allFinite()) return false;
      y += d;
      const double norm = wrms(d, y);
      // A correction a tenth below the tolerance ends the iteration whatever the contraction,
      // provided the iterate it corrects already satisfies the step's equation to within the
      // tolerance: at a discontinuity of f (a contact point's geometry stepping between two table
      // cells) the iterates alternate between two values that the split steps bring within that,
      // while a Jacobian formed across the jump (huge) gives tiny corrections of a wrong iterate.
      if (norm < 0.01 && wrms(r, y) < 1.0) return converged();
      if (it > 0) {
        rho = norm / previous;
        if (rho > kRdiv) return false;
        if (rho < 1.0 && norm * rho / (1.0 - rho) < 0.1) return converged();
      }
      if (it >= 4) slow_ = true;  // converging, but slowly: refresh before the next step
      previous = norm;
    }
    return false;
  }

  /// One implicit step to t from the history: BDF2 (`second` and uniform spacing h) or implicit
  /// Euler; with a stale Jacobian refreshed once, then split in two implicit-Euler halves.
  void step(double t, double h, const Vector& y_n, const Vector* y_nm1, const Vector* y_nm2,
            Vector& y, int depth);
  /// Sizes, tolerances, Jacobian pattern and output blocks of `system`; counters zeroed.
  void prepare(const OdeSystem& system);
  /// `result` with the run's right-hand-side, Jacobian and Newton-iteration counts.
  [[nodiscard]] IntegrationResult counted(IntegrationResult result) const;

  IntegratorSettings s_;
  const OdeSystem* system_ = nullptr;
  const StepMonitor* monitor_ = nullptr;  ///< stop request and divergence guard
  std::size_t n_ = 0;
  Vector atol_;  ///< atol per state (the system's tolerance scales)
  std::size_t tested_ = 0;  ///< states in the convergence test (all but the output states)
  std::vector<std::vector<int>> pattern_, groups_;  ///< Jacobian sparsity and column groups
  /// The output states and the others when the outputs feed nothing back, else all dynamic.
  std::shared_ptr<const OutputBlocks> blocks_;
  OutputBlockMatrix jacobian_;
  std::vector<Factor> factors_;
  std::size_t next_slot_ = 0;  ///< the slot a new factor takes when all hold current ones
  Vector f_, r_, d_, minus_r_;  ///< Newton's work vectors, sized once per run
  long jacobian_age_ = 0, jacobians_ = 0, rhs_count_ = 0, splits_ = 0, iterations_ = 0;
  bool slow_ = false;
};

void Bdf2::step(double t, double h, const Vector& y_n, const Vector* y_nm1, const Vector* y_nm2,
                Vector& y, int depth) {
  const bool second = y_nm1 != nullptr;
  const double gamma_h = (second ? 2.0 / 3.0 : 1.0) * h;
  const Vector psi = second ? Vector((4.0 * y_n - *y_nm1) / 3.0) : y_n;
  // Predictor: the quadratic through the last three points, the line through two, or y_n.
  const Vector predictor = y_nm2 != nullptr ? Vector(3.0 * (y_n - *y_nm1) + *y_nm2)
                           : second         ? Vector(2.0 * y_n - *y_nm1)
                                            : y_n;
  for (int attempt = 0; attempt < 2; ++attempt) {
    y = predictor;
    if (newton(t, psi, gamma_h, y)) return;
    if (jacobian_age_ == 0) break;  // a fresh Jacobian failed already
    refresh_jacobian(t - h, y_n);
  }
  if (depth >= 20) {
    throw Failure(fmt::format("the Newton iteration did not converge at t = {:.9g} s even with a "
                              "fresh Jacobian and the step split to {:.3g} s",
                              t, h));
  }
  ++splits_;
  Vector middle(n_);
  step(t - 0.5 * h, 0.5 * h, y_n, nullptr, nullptr, middle, depth + 1);
  step(t, 0.5 * h, middle, nullptr, nullptr, y, depth + 1);
}

void Bdf2::prepare(const OdeSystem& system) {
  system_ = &system;
  n_ = system.size();
  const auto n = static_cast<Eigen::Index>(n_);
  atol_ = Vector::Constant(n, s_.atol);
  pattern_ = system.jacobian_pattern();
  if (pattern_.size() != n_) pattern_.clear();
  groups_ = jacobian_column_groups(pattern_, n_);
  if (const auto scales = system.tolerance_scales(); !scales.empty()) {
    for (Eigen::Index i = 0; i < n; ++i) atol_[i] *= scales[static_cast<std::size_t>(i)];
  }
  // Output states (filters of the model's own quantities, linear with a constant Jacobian) out
  // of the convergence test: Newton solves them exactly for the iterate of the other states.
  const auto outputs = system.output_states();
  for (const std::size_t i : outputs)
    atol_[static_cast<Eigen::Index>(i)] = std::numeric_limits<double>::infinity();
  tested_ = std::max<std::size_t>(1, n_ - outputs.size());
  // The dynamic block by a sparse LU when the pattern is known (a vehicle's bodies couple to
  // their neighbours only), else dense.
  blocks_ = pattern_.empty() ? nullptr : OutputBlocks::make(system, pattern_, true);
  if (blocks_ == nullptr) blocks_ = OutputBlocks::all_dynamic(n_, pattern_);
  jacobian_ = OutputBlockMatrix(blocks_);
  f_.resize(n);
  r_.resize(n);
  d_.resize(n);
  minus_r_.resize(n);
  constexpr std::size_t kKept = 6;
  factors_ = std::vector<Factor>(kKept);
  next_slot_ = 0;
  rhs_count_ = jacobians_ = splits_ = iterations_ = 0;
}

IntegrationResult Bdf2::counted(IntegrationResult result) const {
  result.rhs_evaluations = rhs_count_;
  result.jacobians = jacobians_;
  result.newton_iterations = iterations_;
  result.step_splits = splits_;
  return result;
}

/// The state at t in (t_n, t_np1], t_np1 = t_n + h: the step's end y_np1, or the quadratic
/// through the last three points (the line through the last two on the first step, k = 0).
Eigen::VectorXd interpolate(double t, double t_n, double t_np1, double h, long k,
                            const Eigen::VectorXd& y_nm1, const Eigen::VectorXd& y_n,
                            const Eigen::VectorXd& y_np1) {
  if (std::abs(t - t_np1) <= 1e-12 * h) return y_np1;
  if (k == 0) return y_n + (t - t_n) / h * (y_np1 - y_n);
  const double u = (t - t_n) / h;  // in (0, 1): nodes at -1, 0, 1
  return 0.5 * u * (u - 1.0) * y_nm1 + (1.0 - u * u) * y_n + 0.5 * u * (u + 1.0) * y_np1;
}

IntegrationResult Bdf2::integrate(const OdeSystem& system, std::span<const double> x0,
                                  const std::vector<double>& times, const Observer& observer) {
  const StepMonitor monitor(system, stop_);
  monitor_ = &monitor;
  prepare(system);
  const auto n = static_cast<Eigen::Index>(n_);
  IntegrationResult result;
  const double h = s_.fixed_step;
  const double t0 = times.front();
  Vector y_nm2(n), y_nm1(n), y_n = Eigen::Map<const Vector>(x0.data(), n), y_np1(n);
  auto report = [&](double t, const Vector& x) {
    result.t_reached = t;
    result.state.assign(x.data(), x.data() + n);
    return observer(t, result.state);
  };
  if (!report(t0, y_n)) {
    result.status = IntegrationResult::Status::kInterrupted;
    return counted(result);
  }
  std::size_t next = 1;
  long k = 0;  // steps taken: y_n is at t0 + k h
  // Ends the run with a failure at the last completed step (y_n).
  const auto fail = [&](const std::string& message) {
    result.status = IntegrationResult::Status::kSolverFailure;
    result.message = message;
    result.t_reached = t0 + static_cast<double>(k) * h;
    result.state.assign(y_n.data(), y_n.data() + n);
  };
  try {
    refresh_jacobian(t0, y_n);
    while (next < times.size()) {
      const double t_n = t0 + static_cast<double>(k) * h;
      const double t_np1 = t0 + static_cast<double>(k + 1) * h;
      if (jacobian_age_ >= s_.jacobian_max_steps || slow_) {
        slow_ = false;
        refresh_jacobian(t_n, y_n);
      }
      step(t_np1, h, y_n, k > 0 ? &y_nm1 : nullptr, k > 1 ? &y_nm2 : nullptr, y_np1, 0);
      ++jacobian_age_;
      ++result.steps;
      // A step that leaves the bounds (or any non-finite state) ends the run with that state.
      if (std::string cause = monitor.divergence(t_np1, std::span<const double>(y_np1.data(), n_));
          !cause.empty()) {
        result.status = IntegrationResult::Status::kSolverFailure;
        result.message = fmt::format("bdf2 (fixed step {} s) at t = {:.9g} s (last output t = "
                                     "{:.9g} s): {}",
                                     h, t_np1, result.t_reached, cause);
        result.t_reached = t_np1;
        result.state.assign(y_np1.data(), y_np1.data() + n);
        return counted(result);
      }
      // Outputs in (t_n, t_np1].
      for (; next < times.size() && times[next] <= t_np1 + 1e-12 * h; ++next) {
        if (!report(times[next], interpolate(times[next], t_n, t_np1, h, k, y_nm1, y_n, y_np1))) {
          result.status = IntegrationResult::Status::kInterrupted;
          return counted(result);
        }
      }
      std::swap(y_nm2, y_nm1);
      std::swap(y_nm1, y_n);
      std::swap(y_n, y_np1);
      ++k;
      if (monitor.stop_requested()) throw StopRequested{};
    }
  } catch (const StopRequested&) {
    // y_n is the state at the end of the last completed step.
    result.status = IntegrationResult::Status::kInterrupted;
    result.t_reached = t0 + static_cast<double>(k) * h;
    result.state.assign(y_n.data(), y_n.data() + n);
  } catch (const std::exception& e) {
    fail(fmt::format("bdf2 (fixed step {} s) at t = {:.9g} s (last output t = {:.9g} s): {}", h,
                     t0 + static_cast<double>(k) * h, result.t_reached, e.what()));
  } catch (const Recoverable&) {
    fail(fmt::format("bdf2 (fixed step {} s): the right-hand side refused the state at t = "
                     "{:.9g} s where the Jacobian is formed",
                     h, t0 + static_cast<double>(k) * h));
  }
  return counted(result);
}

}  // namespace

std::unique_ptr<Integrator> make_bdf2(const IntegratorSettings& settings) {
  return std::make_unique<Bdf2>(settings);
}

}  // namespace ferro::vehicle::detail
