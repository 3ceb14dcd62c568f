// Static equilibrium of the vehicle model: damped Newton on the accelerations with every
// velocity zero, and a continuation in speed where Newton from rest fails (documented at
// static_equilibrium in vehicle_model.hpp).

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynamics.hpp"
#include "output_signals.hpp"

namespace ferro::vehicle {
namespace {

using detail::BodyData;
using detail::ModelData;

struct NewtonOutcome {
  bool converged = false;
  double residual = 0.0;  ///< largest scaled residual at the end [-]
  int iterations = 0;
};

// Relative to the weight: 1e-9 is far below the 0.1 % wheel-load test and above the round-off
// of the contact forces (~1e-13 of the weight); kStallTol accepts a Newton that stalled at the
// geometry's resolution (a table or search resolves gaps to ~1e-10 m, which a Hertz stiffness of
// ~1e9 N/m turns into ~1e-7 of a wheel load).
constexpr double kResidualTol = 1e-9;  // [-]
constexpr double kStallTol = 1e-6;     // [-]
constexpr double kStep = 1e-8;         // finite-difference step [m, rad]

/// The equilibrium's unknowns (positions, spin perturbations, series-damper deflections), their
/// residuals (accelerations of the positions, rates of the other two) and the residual scales.
class Problem {
 public:
  Problem(const VehicleModel& model, double t) : m_(model.data()), ws_(model.workspace()), t_(t) {
    const double g = m_.in.config.gravity;
    // Each residual is scaled to a fraction of the body's weight: a translational acceleration
    // by 1/g (force / weight), an angular acceleration by r_k/g with r_k = sqrt(I_k/m) the
    // radius of gyration (moment / (weight r_k)), a series-damper deflection rate by 1/(g 1 s).
    // The longitudinal position of the whole vehicle is neutral (no longitudinal stiffness to
    // the ground at zero velocity): the car body's x stays at its rest value and defines it.
    for (const BodyData& b : m_.bodies) {
      for (std::size_t d = 0; d < 6; ++d) {
        if (b.q[d] < 0 || (d == 0 && b.kind == BodyKind::car_body)) continue;
        add(b.q[d], b.v[d],
            d < 3 ? 1.0 / g
                  : std::sqrt(b.inertia[static_cast<Eigen::Index>(d - 3)] / b.mass) / g);
      }
      if (b.spin >= 0) add(b.spin, b.spin, std::sqrt(b.inertia[1] / b.mass) / g);
      if (b.track >= 0) add_track(b.track, *m_.track, wheel_load(g));
    }
    for (const detail::ElementData& e : m_.elements) {
      if (e.state >= 0) add(e.state, e.state, 1.0 / g);  // [s/m]: 1 m/s counts as 1 g
    }
    xdot_.resize(m_.n_states);
    const auto n = size();
    r_.resize(n);
    r_trial_.resize(n);
    r_step_.resize(n);
    jacobian_.resize(n, n);
  }

  [[nodiscard]] Eigen::Index size() const { return static_cast<Eigen::Index>(unknown_.size()); }
  [[nodiscard]] const std::vector<int>& unknowns() const { return unknown_; }

  /// The rest state with every wheelset lowered onto the rails (touching height of the centred
  /// pose, found by bisection on the source's contacts, then a typical Hertz approach), so that
  /// Newton starts with contact stiffness.
  [[nodiscard]] std::vector<double> lowered_rest() const {
    std::vector<double> guess(m_.n_states, 0.0);
    std::vector<contact::WheelRailContact> points;
    for (const BodyData& b : m_.bodies) {
      if (!b.has_contact || b.q[2] < 0) continue;
      double lifted = -0.02, penetrating = 0.02;  // pose.vertical bracket [m]
      for (int it = 0; it < 40; ++it) {
        contact::WheelsetPose pose;
        pose.vertical = 0.5 * (lifted + penetrating);
        m_.in.geometry->contacts(pose, points);
        (points.empty() ? lifted : penetrating) = pose.vertical;
      }
      guess[static_cast<std::size_t>(b.q[2])] = -(penetrating + 1.0e-4);
    }
    return guess;
  }

  /// Damped Newton from x (updated in place) at `speed` (NaN: the profile's V(t)): numerical
  /// Jacobian, minimum-norm steps (weakly determined directions stay near rest), step halved
  /// until the residual's 2-norm falls.
  NewtonOutcome newton(std::vector<double>& x, double speed, int max_iterations) {
    NewtonOutcome out;
    if (!residual(x, speed, r_)) {
      out.residual = std::numeric_limits<double>::infinity();
      return out;
    }
    const Eigen::Index n = size();
    for (; out.iterations < max_iterations; ++out.iterations) {
      out.residual = r_.lpNorm<Eigen::Infinity>();
      if (out.residual < kResidualTol) {
        out.converged = true;
        return out;
      }
      for (Eigen::Index j = 0; j < n; ++j) {
        std::vector<double> xp = x;
        xp[static_cast<std::size_t>(unknown_[static_cast<std::size_t>(j)])] += kStep;
        if (!residual(xp, speed, r_step_)) return out;
        jacobian_.col(j) = (r_step_ - r_) / kStep;
      }
      const Eigen::VectorXd dx = jacobian_.completeOrthogonalDecomposition().solve(-r_);
      if (!line_search(x, dx, speed)) break;
    }
    out.residual = r_.lpNorm<Eigen::Infinity>();
    out.converged = out.residual < kStallTol;  // stalled at the geometry's resolution
    return out;
  }

 private:
  /// The track's positions, their accelerations scaled like a body's (rolls by the radius of
  /// gyration of the rail or sleeper).
  /// The model's mean static wheel load [N].
  [[nodiscard]] double wheel_load(double g) const {
    double mass = 0.0;
    for (const BodyData& b : m_.bodies) mass += b.mass;
    return mass * g / (2.0 * static_cast<double>(std::max<std::size_t>(1, m_.contact_bodies.size())));
  }

  /// The track's positions; their residuals are the forces on the rail and sleeper bodies (mass
  /// times acceleration) relative to the static wheel load they carry, not to their own weight
  /// (a rail body of 60 kg carries a thousand times its weight), and moments relative to that
  /// load times the body's radius of gyration.
  void add_track(int first, const track::CoRunningTrackParams& p, double wheel_load) {
    const double masses[3] = {p.rail_mass_lateral, p.rail_mass_vertical, p.rail_roll_inertia};
    const double sleeper[3] = {p.sleeper_mass_lateral, p.sleeper_mass_vertical,
                               p.sleeper_roll_inertia};
    const double rail_gyration = std::sqrt(p.rail_roll_inertia / p.rail_mass_vertical);
    const double sleeper_gyration = std::sqrt(p.sleeper_roll_inertia / p.sleeper_mass_vertical);
    for (int j = 0; j < track::kTrackPositions; ++j) {
      const double inertia = j < 6 ? masses[j % 3] : sleeper[j % 3];
      const double arm = j % 3 != 2 ? 1.0 : (j < 6 ? rail_gyration : sleeper_gyration);
      add(first + j, first + track::kTrackPositions + j, inertia / (wheel_load * arm));
    }
  }

  void add(int unknown, int residual, double scale) {
    unknown_.push_back(unknown);
    residual_.push_back(residual);
    scale_.push_back(scale);
  }

  /// Scaled residual at `state`; false where the model cannot be evaluated (a pose outside a
  /// contact table, the track's end) or gives a non-finite residual.
  bool residual(const std::vector<double>& state, double speed, Eigen::VectorXd& r) {
    try {
      detail::evaluate(m_, ws_, t_, state, xdot_, {}, speed);
    } catch (const std::exception&) {
      return false;
    }
    for (Eigen::Index i = 0; i < size(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      r[i] = xdot_[static_cast<std::size_t>(residual_[k])] * scale_[k];
      if (!std::isfinite(r[i])) return false;
    }
    return true;
  }

  bool line_search(std::vector<double>& x, const Eigen::VectorXd& dx, double speed) {
    double lambda = 1.0;
    for (int ls = 0; ls < 30; ++ls, lambda *= 0.5) {
      std::vector<double> xt = x;
      for (Eigen::Index j = 0; j < size(); ++j) {
        xt[static_cast<std::size_t>(unknown_[static_cast<std::size_t>(j)])] += lambda * dx[j];
      }
      if (residual(xt, speed, r_trial_) && r_trial_.norm() < r_.norm()) {
        x = std::move(xt);
        r_ = r_trial_;
        return true;
      }
    }
    return false;
  }

  const ModelData& m_;
  detail::Workspace& ws_;
  double t_;
  std::vector<int> unknown_, residual_;
  std::vector<double> scale_, xdot_;
  Eigen::VectorXd r_, r_trial_, r_step_;
  Eigen::MatrixXd jacobian_;
};

/// Continuation in speed from the equilibrium x at V = 0 to V(t). The residual is not smooth:
/// the wheel-rail contact changes its points (tread, flange root, flange: kinks where a point
/// appears or fades in), and a bump stop's table has kinks; Newton from rest can end against such
/// a kink or step with a large residual, typically a sharp curve at speed where the wheelsets
/// roll on their flanges and the secondary lateral suspension takes the car body's versine. At
/// V = 0 the creepages vanish (no sliding velocity) and the equilibrium is that of the elastic
/// suspension, gravity, cant and normal contact alone, which Newton finds from rest. From there
/// the speed is raised in steps, each Newton started from the previous equilibrium extrapolated
/// along the path: first to the regularisation speed, over which the creep forces grow from zero
/// to their rolling values (creepages are the sliding velocity over max(V, regularisation
/// speed)), then to the target speed (centrifugal force, cant deficiency). A step whose Newton
/// fails is halved; the criteria are those of the direct solve.
std::vector<double> continue_in_speed(Problem& problem, std::vector<double> x, double v_target,
                                      double v_reg, double direct_residual) {
  // Iterations a continuation step may take before it is halved, and the smallest step [m/s].
  constexpr int kStepIterations = 30;
  const double min_step = 1e-6 * std::max(v_target, v_reg);
  std::vector<double> x_prev = x;  // the accepted point before x, for the secant predictor
  double v = 0.0, v_prev = 0.0;
  double last_residual = 0.0;
  for (const double v_end : {std::min(v_target, v_reg), v_target}) {
    double h = v_end - v;
    while (v < v_end) {
      const double v_try = v_end - v <= h * (1.0 + 1e-12) ? v_end : v + h;
      bool accepted = false;
      // Secant predictor along the path first, then the previous equilibrium as it is.
      for (const bool predict : {v > v_prev, false}) {
        std::vector<double> xt = x;
        if (predict) {
          const double ratio = (v_try - v) / (v - v_prev);
          for (const int k : problem.unknowns()) {
            const auto i = static_cast<std::size_t>(k);
            xt[i] += ratio * (x[i] - x_prev[i]);
          }
        }
        const NewtonOutcome o = problem.newton(xt, v_try, kStepIterations);
        last_residual = o.residual;
        if (o.converged) {
          x_prev = std::move(x);
          x = std::move(xt);
          v_prev = v;
          v = v_try;
          // A step that converged quickly may double (within its segment).
          if (o.iterations <= kStepIterations / 4) h *= 2.0;
          accepted = true;
          break;
        }
      }
      if (accepted) continue;
      h *= 0.5;
      if (h < min_step) {
        throw std::runtime_error(fmt::format(
            "static_equilibrium: Newton did not converge (largest residual {:.3g} of the weight "
            "from rest); the continuation in speed from V = 0 stopped at {:.6g} m/s of {:.6g} "
            "(largest residual {:.3g})",
            direct_residual, v, v_target, last_residual));
      }
    }
  }
  return x;
}

// The equilibrium of the bodies (the output filters left at their guess).
std::vector<double> mechanical_equilibrium(const VehicleModel& model, double t,
                                           std::span<const double> start) {
  const ModelData& m = model.data();
  if (!start.empty() && start.size() != m.n_states) {
    throw std::invalid_argument(fmt::format(
        "static_equilibrium: start has {} entries, the model {} states", start.size(), m.n_states));
  }
  Problem problem(model, t);
  const std::vector<double> guess = problem.lowered_rest();
  if (problem.size() == 0) {
    return start.empty() ? guess : std::vector<double>(start.begin(), start.end());
  }

  // 1. Newton from the given start, or from rest with the wheelsets lowered onto the rails.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> x = start.empty() ? guess : std::vector<double>(start.begin(), start.end());
  const NewtonOutcome direct = problem.newton(x, nan, 200);
  if (direct.converged) return x;

  // 2. Continuation in speed from the equilibrium at V = 0.
  x = guess;
  const NewtonOutcome at_rest = problem.newton(x, 0.0, 200);
  if (!at_rest.converged) {
    throw std::runtime_error(fmt::format(
        "static_equilibrium: Newton did not converge (largest residual {:.3g} of the weight; at "
        "V = 0, the start of the continuation in speed: {:.3g})",
        direct.residual, at_rest.residual));
  }
  return continue_in_speed(problem, std::move(x), m.in.speed.speed(t),
                           m.in.config.wheel_rail.regularisation_speed, direct.residual);
}

}  // namespace

std::vector<double> static_equilibrium(const VehicleModel& model, double t,
                                       std::span<const double> start) {
  std::vector<double> x = mechanical_equilibrium(model, t, start);
  detail::set_output_filters_steady(model.data(), model.workspace(), t, x);
  return x;
}

}  // namespace ferro::vehicle
