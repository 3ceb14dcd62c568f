// SUNDIALS adapters: CVODE (BDF + Newton, dense or banded; Adams + fixed point), ARKODE
// ERKStep (explicit Runge-Kutta) and ARKODE ARKStep with an implicit, L-stable, stiffly
// accurate ESDIRK table (Newton, dense or banded). SUNDIALS 6.x API; their callbacks, linear
// solver and output loop: sundials_support.hpp.
#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "sundials_support.hpp"

namespace ferro::vehicle::detail {
namespace {

// The user data of one run of `system` by `method`; with the output blocks of its Newton
// matrix when the method is implicit.
UserData user_data(const OdeSystem& system, const StepMonitor& monitor, const std::string& method,
                   bool implicit) {
  UserData ud;
  ud.system = &system;
  ud.monitor = &monitor;
  ud.method = method;
  if (implicit) ud.blocks = OutputBlocks::make(system, system.jacobian_pattern());
  return ud;
}

class CvodeIntegrator final : public Integrator {
 public:
  explicit CvodeIntegrator(IntegratorSettings s) : s_(std::move(s)) {}
  [[nodiscard]] std::string name() const override { return s_.method; }

  IntegrationResult integrate(const OdeSystem& system, std::span<const double> x0,
                              const std::vector<double>& times, const Observer& observer) override {
    Handles h;
    const StepMonitor monitor(system, stop_);
    const bool bdf = s_.method == "cvode_bdf";
    UserData ud = user_data(system, monitor, s_.method, bdf);
    const auto n = static_cast<sunindextype>(system.size());
    check(SUNContext_Create(nullptr, &h.ctx), "SUNContext_Create");
    h.y = N_VNew_Serial(n, h.ctx);
    std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(h.y));
    h.mem = CVodeCreate(bdf ? CV_BDF : CV_ADAMS, h.ctx);
    if (h.mem == nullptr) throw std::runtime_error("CVodeCreate failed");
    check(CVodeSetErrHandlerFn(h.mem, error_handler, &ud), "CVodeSetErrHandlerFn");
    check(CVodeInit(h.mem, sundials_rhs, times.front(), h.y), "CVodeInit");
    check(CVodeSetUserData(h.mem, &ud), "CVodeSetUserData");
    set_tolerances(h, system, s_, CVodeSStolerances, CVodeSVtolerances);
    if (std::isfinite(s_.max_step)) check(CVodeSetMaxStep(h.mem, s_.max_step), "CVodeSetMaxStep");
    if (s_.initial_step > 0.0) check(CVodeSetInitStep(h.mem, s_.initial_step), "CVodeSetInitStep");
    check(CVodeSetMaxNumSteps(h.mem, s_.max_steps), "CVodeSetMaxNumSteps");
    if (s_.max_order > 0) check(CVodeSetMaxOrd(h.mem, s_.max_order), "CVodeSetMaxOrd");
    if (bdf && s_.stability_limit_detection) {
      check(CVodeSetStabLimDet(h.mem, SUNTRUE), "CVodeSetStabLimDet");
    }
    if (bdf) {
      make_direct_solver(h, system, s_.linear_solver, ud);
      check(CVodeSetLinearSolver(h.mem, h.LS, h.A), "CVodeSetLinearSolver");
      if (s_.linear_solver != "band") {
        check(CVodeSetJacFn(h.mem, dense_dq_jacobian), "CVodeSetJacFn");
      }
      check(CVodeSetJacEvalFrequency(h.mem, s_.jacobian_max_steps), "CVodeSetJacEvalFrequency");
    } else {
      h.NLS = SUNNonlinSol_FixedPoint(h.y, 0, h.ctx);
      check(CVodeSetNonlinearSolver(h.mem, h.NLS), "CVodeSetNonlinearSolver");
    }
    const PackageCalls calls{
        [&](double tout, double* t) { return CVode(h.mem, tout, h.y, t, CV_ONE_STEP); },
        CVodeGetDky, CVodeGetCurrentTime, CVodeGetNumSteps, CVodeGetReturnFlagName};
    return run_loop(h, ud, times, observer, s_.max_steps, calls);
  }

 private:
  IntegratorSettings s_;
};

class ArkodeErkIntegrator final : public Integrator {
 public:
  explicit ArkodeErkIntegrator(IntegratorSettings s) : s_(std::move(s)) {}
  [[nodiscard]] std::string name() const override { return s_.method; }

  IntegrationResult integrate(const OdeSystem& system, std::span<const double> x0,
                              const std::vector<double>& times, const Observer& observer) override {
    Handles h;
    h.arkode = true;
    const StepMonitor monitor(system, stop_);
    UserData ud = user_data(system, monitor, s_.method, false);
    const auto n = static_cast<sunindextype>(system.size());
    check(SUNContext_Create(nullptr, &h.ctx), "SUNContext_Create");
    h.y = N_VNew_Serial(n, h.ctx);
    std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(h.y));
    h.mem = ERKStepCreate(sundials_rhs, times.front(), h.y, h.ctx);
    if (h.mem == nullptr) throw std::runtime_error("ERKStepCreate failed");
    check(ERKStepSetErrHandlerFn(h.mem, error_handler, &ud), "ERKStepSetErrHandlerFn");
    check(ERKStepSetUserData(h.mem, &ud), "ERKStepSetUserData");
    set_tolerances(h, system, s_, ERKStepSStolerances, ERKStepSVtolerances,
                   /*scaled=*/false);
    check(ERKStepSetOrder(h.mem, s_.erk_order), "ERKStepSetOrder");
    if (std::isfinite(s_.max_step))
      check(ERKStepSetMaxStep(h.mem, s_.max_step), "ERKStepSetMaxStep");
    if (s_.initial_step > 0.0)
      check(ERKStepSetInitStep(h.mem, s_.initial_step), "ERKStepSetInitStep");
    check(ERKStepSetMaxNumSteps(h.mem, s_.max_steps), "ERKStepSetMaxNumSteps");
    if (s_.fixed_step > 0.0) check(ERKStepSetFixedStep(h.mem, s_.fixed_step), "ERKStepSetFixedStep");
    const PackageCalls calls{
        [&](double tout, double* t) { return ERKStepEvolve(h.mem, tout, h.y, t, ARK_ONE_STEP); },
        ERKStepGetDky, ERKStepGetCurrentTime, ERKStepGetNumSteps, ERKStepGetReturnFlagName};
    return run_loop(h, ud, times, observer, s_.max_steps, calls);
  }

 private:
  IntegratorSettings s_;
};

// Fully implicit ARKStep with ESDIRK4(3)6L[2]SA (Kennedy & Carpenter 2016): L-stable, stiffly
// accurate, so lightly damped stiff modes (a wheelset bouncing on the Hertz stiffness) are
// damped by the method instead of limiting the step, as they do for BDF of order 3-5 whose
// stability regions exclude part of the imaginary axis.
class ArkodeDirkIntegrator final : public Integrator {
  static constexpr int kMaxNewtonIterations = 6;

 public:
  explicit ArkodeDirkIntegrator(IntegratorSettings s) : s_(std::move(s)) {}
  [[nodiscard]] std::string name() const override { return s_.method; }

  IntegrationResult integrate(const OdeSystem& system, std::span<const double> x0,
                              const std::vector<double>& times, const Observer& observer) override {
    Handles h;
    h.arkode = true;
    h.arkstep = true;
    const StepMonitor monitor(system, stop_);
    UserData ud = user_data(system, monitor, s_.method, true);
    const auto n = static_cast<sunindextype>(system.size());
    check(SUNContext_Create(nullptr, &h.ctx), "SUNContext_Create");
    h.y = N_VNew_Serial(n, h.ctx);
    std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(h.y));
    h.mem = ARKStepCreate(nullptr, sundials_rhs, times.front(), h.y, h.ctx);
    if (h.mem == nullptr) throw std::runtime_error("ARKStepCreate failed");
    check(ARKStepSetErrHandlerFn(h.mem, error_handler, &ud), "ARKStepSetErrHandlerFn");
    check(ARKStepSetUserData(h.mem, &ud), "ARKStepSetUserData");
    set_tolerances(h, system, s_, ARKStepSStolerances, ARKStepSVtolerances);
    check(ARKStepSetTableNum(h.mem, ARKODE_ESDIRK436L2SA_6_3_4, ARKODE_ERK_NONE),
          "ARKStepSetTableNum");
    if (std::isfinite(s_.max_step))
      check(ARKStepSetMaxStep(h.mem, s_.max_step), "ARKStepSetMaxStep");
    if (s_.initial_step > 0.0)
      check(ARKStepSetInitStep(h.mem, s_.initial_step), "ARKStepSetInitStep");
    check(ARKStepSetMaxNumSteps(h.mem, s_.max_steps), "ARKStepSetMaxNumSteps");
    if (s_.fixed_step > 0.0) check(ARKStepSetFixedStep(h.mem, s_.fixed_step), "ARKStepSetFixedStep");
    make_direct_solver(h, system, s_.linear_solver, ud);
    check(ARKStepSetLinearSolver(h.mem, h.LS, h.A), "ARKStepSetLinearSolver");
    if (s_.linear_solver != "band") {
      check(ARKStepSetJacFn(h.mem, dense_dq_jacobian), "ARKStepSetJacFn");
    }
    check(ARKStepSetJacEvalFrequency(h.mem, s_.jacobian_max_steps),
          "ARKStepSetJacEvalFrequency");
    // Up to kMaxNewtonIterations Newton iterations per stage before the step is retried with a
    // fresh Jacobian (ARKODE's default of 3 makes a retry, and a Jacobian, of most steps at
    // rtol <= 1e-6 here), and each stage predicted by the maximum-order interpolant of the
    // previous step.
    check(ARKStepSetMaxNonlinIters(h.mem, kMaxNewtonIterations), "ARKStepSetMaxNonlinIters");
    check(ARKStepSetPredictorMethod(h.mem, 1), "ARKStepSetPredictorMethod");
    const PackageCalls calls{
        [&](double tout, double* t) { return ARKStepEvolve(h.mem, tout, h.y, t, ARK_ONE_STEP); },
        ARKStepGetDky, ARKStepGetCurrentTime, ARKStepGetNumSteps, ARKStepGetReturnFlagName};
    return run_loop(h, ud, times, observer, s_.max_steps, calls);
  }

 private:
  IntegratorSettings s_;
};

}  // namespace

std::unique_ptr<Integrator> make_arkode_dirk(const IntegratorSettings& settings) {
  return std::make_unique<ArkodeDirkIntegrator>(settings);
}

std::unique_ptr<Integrator> make_cvode(const IntegratorSettings& settings) {
  return std::make_unique<CvodeIntegrator>(settings);
}
std::unique_ptr<Integrator> make_arkode_erk(const IntegratorSettings& settings) {
  return std::make_unique<ArkodeErkIntegrator>(settings);
}

}  // namespace ferro::vehicle::detail
