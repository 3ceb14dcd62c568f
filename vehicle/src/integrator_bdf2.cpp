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
// is already within the tolerance. The system's output states stay out of both tests: linear with
// a constant Jacobian, Newton solves them exactly for the iterate of the other states. A Newton that diverges (a correction more than twice the
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
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "integrator_impl.hpp"

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
    for (const std::vector<int>& group : groups_) {
      for (const int j : group) {
        yp[j] = y[j] + std::sqrt(kUnitRoundoff * std::max(1e-5, std::abs(y[j])));
      }
      rhs(t, yp, f1);
      for (const int j : group) {
        const double inc = yp[j] - y[j];  // the increment actually represented
        yp[j] = y[j];
        jacobian_.col(j).setZero();
        if (pattern_.empty()) {
          jacobian_.col(j) = (f1 - f0) / inc;
        } else {
          for (const int i : pattern_[static_cast<std::size_t>(j)]) {
            jacobian_(i, j) = (f1[i] - f0[i]) / inc;
          }
        }
      }
    }
    ++jacobians_;
    jacobian_age_ = 0;
    factors_.clear();  // the Newton matrices must be refactored
  }

  /// The factored Newton matrix I - gamma_h J of the current Jacobian, solved by blocks when
  /// the output states feed nothing back (J block lower-triangular): the other states first,
  /// then the output states from theirs.
  struct Factor {
    double gamma_h = 0.0;
    Eigen::PartialPivLU<Eigen::MatrixXd> states;   ///< I - gamma_h J over the states
    Eigen::PartialPivLU<Eigen::MatrixXd> outputs;  ///< over the output states (block case)
    Eigen::SparseMatrix<double> coupling;          ///< -gamma_h J(outputs, states) (block case)
  };

  /// A step alternates between a few values of gamma_h (BDF2's 2h/3, the implicit-Euler halves
  /// of a split step): each is factored once per Jacobian and kept.
  const Factor& factor(double gamma_h) {
    constexpr std::size_t kKept = 6;
    for (const Factor& f : factors_) {
      if (f.gamma_h == gamma_h) return f;
    }
    if (factors_.size() >= kKept) factors_.erase(factors_.begin());
    Factor f;
    f.gamma_h = gamma_h;
    if (output_index_.empty()) {
      const auto n = static_cast<Eigen::Index>(n_);
      f.states.compute(Eigen::MatrixXd::Identity(n, n) - gamma_h * jacobian_);
    } else {
      const auto ns = static_cast<Eigen::Index>(state_index_.size());
      const auto no = static_cast<Eigen::Index>(output_index_.size());
      f.states.compute(Eigen::MatrixXd::Identity(ns, ns) -
                       gamma_h * jacobian_(state_index_, state_index_));
      f.outputs.compute(Eigen::MatrixXd::Identity(no, no) -
                        gamma_h * jacobian_(output_index_, output_index_));
      // The outputs' dependence on the states, by the pattern's entries (a few per row).
      std::vector<Eigen::Triplet<double>> entries;
      for (std::size_t k = 0; k < state_index_.size(); ++k) {
        const auto j = state_index_[k];
        for (const int i : pattern_[static_cast<std::size_t>(j)]) {
          const Eigen::Index slot = output_slot_[static_cast<std::size_t>(i)];
          if (slot >= 0) entries.emplace_back(slot, static_cast<Eigen::Index>(k), -gamma_h * jacobian_(i, j));
        }
      }
      f.coupling.resize(no, ns);
      f.coupling.setFromTriplets(entries.begin(), entries.end());
    }
    factors_.push_back(std::move(f));
    return factors_.back();
  }

  /// (I - gamma_h J)^-1 b.
  [[nodiscard]] Vector solve(const Factor& f, const Vector& b) const {
    if (output_index_.empty()) return f.states.solve(b);
    const Vector ds = f.states.solve(Vector(b(state_index_)));
    const Vector dout = f.outputs.solve(Vector(b(output_index_) - f.coupling * ds));
    Vector d(n_);
    d(state_index_) = ds;
    d(output_index_) = dout;
    return d;
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
    Vector f(n_), r(n_), d(n_);
    double previous = 0.0, rho = 0.0;
    for (int it = 0; it < 8; ++it) {
      try {
        rhs(t, y, f);
      } catch (const Recoverable&) {
        return false;
      }
      ++iterations_;
      r = y - psi - gamma_h * f;
      d = solve(matrix, -r);
      if (!d.allFinite()) return false;
      y += d;
      const double norm = wrms(d, y);
      // A correction a tenth below the tolerance ends the iteration whatever the contraction,
      // provided the iterate it corrects already satisfies the step's equation to within the
      // tolerance: at a discontinuity of f (a contact point's geometry stepping between two table
      // cells) the iterates alternate between two values that the split steps bring within that,
      // while a Jacobian formed across the jump (huge) gives tiny corrections of a wrong iterate.
      if (norm < 0.01 && wrms(r, y) < 1.0) return true;
      if (it > 0) {
        rho = norm / previous;
        if (rho > kRdiv) return false;
        if (rho < 1.0 && norm * rho / (1.0 - rho) < 0.1) return true;
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

  IntegratorSettings s_;
  const OdeSystem* system_ = nullptr;
  std::size_t n_ = 0;
  Vector atol_;  ///< atol per state (the system's tolerance scales)
  std::size_t tested_ = 0;  ///< states in the convergence test (all but the output states)
  std::vector<std::vector<int>> pattern_, groups_;  ///< Jacobian sparsity and column groups
  Eigen::MatrixXd jacobian_;
  std::vector<Factor> factors_;
  /// The output states and the others, when the outputs feed nothing back (else both empty).
  std::vector<Eigen::Index> state_index_, output_index_;
  std::vector<Eigen::Index> output_slot_;  ///< per state: its index among the outputs, or -1
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

IntegrationResult Bdf2::integrate(const OdeSystem& system, std::span<const double> x0,
                                  const std::vector<double>& times, const Observer& observer) {
  system_ = &system;
  n_ = system.size();
  const auto n = static_cast<Eigen::Index>(n_);
  jacobian_.resize(n, n);
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
  state_index_.clear();
  output_index_.clear();
  factors_.clear();
  if (!outputs.empty() && !pattern_.empty()) {
    std::vector<char> is_output(n_, 0);
    for (const std::size_t i : outputs) is_output[i] = 1;
    // Block-triangular only if no output column reaches a row of the other states.
    bool feeds_back = false;
    for (const std::size_t j : outputs) {
      for (const int i : pattern_[j]) feeds_back = feeds_back || !is_output[static_cast<std::size_t>(i)];
    }
    if (!feeds_back) {
      output_slot_.assign(n_, -1);
      for (std::size_t i = 0; i < n_; ++i) {
        if (is_output[i] != 0) output_slot_[i] = static_cast<Eigen::Index>(output_index_.size());
        (is_output[i] ? output_index_ : state_index_).push_back(static_cast<Eigen::Index>(i));
      }
    }
  }
  rhs_count_ = jacobians_ = splits_ = iterations_ = 0;
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
    return result;
  }
  std::size_t next = 1;
  long k = 0;  // steps taken: y_n is at t0 + k h
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
      if (!y_np1.allFinite()) throw Failure(fmt::format("the state became non-finite at t = {:.9g} s", t_np1));
      // Outputs in (t_n, t_np1]: the step's end, or the quadratic through the last three
      // points (the line through the last two on the first step).
      while (next < times.size() && times[next] <= t_np1 + 1e-12 * h) {
        const double t = times[next];
        Vector x(n);
        if (std::abs(t - t_np1) <= 1e-12 * h) {
          x = y_np1;
        } else if (k == 0) {
          x = y_n + (t - t_n) / h * (y_np1 - y_n);
        } else {
          const double u = (t - t_n) / h;  // in (0, 1): nodes at -1, 0, 1
          x = 0.5 * u * (u - 1.0) * y_nm1 + (1.0 - u * u) * y_n + 0.5 * u * (u + 1.0) * y_np1;
        }
        if (!report(t, x)) {
          result.status = IntegrationResult::Status::kInterrupted;
          result.rhs_evaluations = rhs_count_;
          return result;
        }
        ++next;
      }
      std::swap(y_nm2, y_nm1);
      std::swap(y_nm1, y_n);
      std::swap(y_n, y_np1);
      ++k;
    }
  } catch (const std::exception& e) {
    result.status = IntegrationResult::Status::kSolverFailure;
    result.message = fmt::format("bdf2 (fixed step {} s) at t = {:.9g} s (last output t = {:.9g} s): {}",
                                 h, t0 + static_cast<double>(k) * h, result.t_reached, e.what());
    result.t_reached = t0 + static_cast<double>(k) * h;
    result.state.assign(y_n.data(), y_n.data() + n);
  } catch (const Recoverable&) {
    result.status = IntegrationResult::Status::kSolverFailure;
    result.message = fmt::format(
        "bdf2 (fixed step {} s): the right-hand side refused the state at t = {:.9g} s where the "
        "Jacobian is formed",
        h, t0 + static_cast<double>(k) * h);
    result.t_reached = t0 + static_cast<double>(k) * h;
    result.state.assign(y_n.data(), y_n.data() + n);
  }
  result.rhs_evaluations = rhs_count_;
  result.jacobians = jacobians_;
  result.newton_iterations = iterations_;
  return result;
}

}  // namespace

std::unique_ptr<Integrator> make_bdf2(const IntegratorSettings& settings) {
  return std::make_unique<Bdf2>(settings);
}

}  // namespace ferro::vehicle::detail
