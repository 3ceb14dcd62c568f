#pragma once
// Time integrators behind one interface: SUNDIALS CVODE (BDF + Newton with a dense or banded
// linear solver; Adams + fixed-point), SUNDIALS ARKODE (explicit Runge-Kutta, ESDIRK),
// Boost.Odeint (runge_kutta_dopri5 with dense output, rosenbrock4, Bogacki-Shampine order 3 at a
// fixed step: odeint_bs3), and bdf2, the two-step BDF at a fixed step with a simplified Newton
// (integrator_bdf2.cpp). No physics in here.
//
// Right-hand-side return codes (OdeSystem): 0 ok; > 0 recoverable -- CVODE (BDF and Adams)
// retries with a smaller step; ARKODE's explicit ERKStep and Odeint cannot retry and report a
// solver failure at that time; < 0 fatal -- every integrator stops and reports time, state and
// cause.
//
// After every accepted step each integrator checks the state (the divergence guard): a
// non-finite state, or one beyond the system's state_bounds(), stops the run as a solver
// failure naming the state, its value, the bound and the time. A stop request
// (Integrator::set_stop_request) is polled before every right-hand side and after every step:
// the run then ends as an interruption at its last completed step.

#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ferro/vehicle/ode_system.hpp"

namespace ferro::vehicle {

/// Integrator choice and tolerances, as read from a scene's `solver` part.
struct IntegratorSettings {
  std::string method = "cvode_bdf";                           ///< one of available_integrators()
  double rtol = 1e-8;                                         ///< relative tolerance [-]
  double atol = 1e-10;                                        ///< absolute tolerance [state units]
  double max_step = std::numeric_limits<double>::infinity();  ///< [s]
  double initial_step = 0.0;                                  ///< [s]; 0 lets the integrator choose
  std::string linear_solver = "dense";                        ///< cvode_bdf only: "dense" or "band"
  long max_steps = 1000000;  ///< internal steps allowed between two outputs
  int erk_order = 4;         ///< arkode_erk: method order (2..8)
  /// cvode_bdf / cvode_adams: highest order the method may use (0: the method's own, 5 for BDF,
  /// 12 for Adams). BDF orders 1 and 2 are A-stable: an undamped stiff oscillation (a
  /// wheelset's vertical mode on the Hertz stiffness) then limits the step by accuracy only.
  int max_order = 0;
  /// cvode_bdf: BDF stability limit detection (lowers the order when an oscillatory mode near
  /// the imaginary axis makes orders 3-5 unstable).
  bool stability_limit_detection = false;
  /// cvode_bdf / arkode_dirk: most steps between two finite-difference Jacobians of the Newton
  /// matrix. The solver still refreshes the Jacobian whenever a Newton iteration fails to
  /// converge, so a stale one costs iterations, never accuracy (the error test is unchanged).
  /// SUNDIALS' own default is 51 (CVODE) / 51 (ARKODE); on whole vehicles, where a dense
  /// Jacobian costs one right-hand side per state, 1000 takes 25-35 % of the CPU time off a
  /// run (docs/PERFORMANCE.md, "Jacobian age").
  long jacobian_max_steps = 1000;
  /// arkode_erk / arkode_dirk / odeint_bs3 / bdf2 (the last two need one): a constant step [s] with no
  /// error control (0: adaptive steps under rtol / atol). The error is then the method's
  /// truncation error at that step, to be measured against a tight-tolerance run
  /// (`ferrodyn bench work-precision --integrators METHOD@STEP`).
  double fixed_step = 0.0;

  /// Throws std::invalid_argument naming the field and the allowed values.
  void validate(const std::string& where = "solver") const;
};

/// Names accepted in IntegratorSettings::method.
[[nodiscard]] const std::vector<std::string>& available_integrators();

/// Whether a method runs at IntegratorSettings::fixed_step (arkode_erk, arkode_dirk,
/// odeint_bs3, bdf2).
[[nodiscard]] bool takes_fixed_step(const std::string& method);

/// Called at every output time with the interpolated state; return false to stop the run
/// (interruption). t is the output time.
using Observer = std::function<bool(double t, std::span<const double> x)>;

struct IntegrationResult {
  enum class Status { kCompleted, kInterrupted, kSolverFailure };
  Status status = Status::kCompleted;
  /// Last time with a valid state [s]: the last output time, or for an interruption or a
  /// failure between outputs, the end of the last completed step.
  double t_reached = 0.0;
  std::vector<double> state;  ///< state at t_reached
  std::string message;        ///< cause of a failure, empty otherwise
  long steps = 0;             ///< internal steps taken
  long rhs_evaluations = 0;   ///< right-hand-side calls (Jacobians' included)
  long jacobians = 0;         ///< Jacobians formed (bdf2; 0 where the package does not say)
  long newton_iterations = 0; ///< Newton iterations (bdf2; 0 where the package does not say)
  /// Steps split into two implicit-Euler halves because Newton did not converge with a fresh
  /// Jacobian, each half counted again when it splits (bdf2; 0 for the other integrators).
  long step_splits = 0;
};

[[nodiscard]] std::string to_string(IntegrationResult::Status status);

/// Polled by an integrator before every right-hand side and after every step; true stops the
/// integration at once. Must be cheap (e.g. an atomic load).
using StopRequest = std::function<bool()>;

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// From now on integrate() polls `stop`: once it returns true, integrate() returns
  /// kInterrupted with the state of the last completed step (t_reached: that step's end).
  void set_stop_request(StopRequest stop) { stop_ = std::move(stop); }
  [[nodiscard]] virtual std::string name() const = 0;
  /// Integrates from (output_times.front(), x0) through every output time, calling `observer`
  /// at each (including the first). Never throws for solver trouble: the result says what
  /// happened, when, and in which state.
  virtual IntegrationResult integrate(const OdeSystem& system, std::span<const double> x0,
                                      const std::vector<double>& output_times,
                                      const Observer& observer) = 0;

 protected:
  StopRequest stop_;  ///< empty: never stop early
};

/// Factory from settings; throws std::invalid_argument for an unknown method.
[[nodiscard]] std::unique_ptr<Integrator> make_integrator(const IntegratorSettings& settings);

/// Output times t0, t0+dt, ..., t_end (t_end included even if not a multiple of dt).
[[nodiscard]] std::vector<double> output_grid(double t0, double t_end, double dt);

}  // namespace ferro::vehicle
