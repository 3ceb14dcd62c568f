// The SUNDIALS adapters' callbacks, tolerances and output loop (sundials_support.hpp).
#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <fmt/format.h>

#include <cstdlib>
#include <exception>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "sundials_support.hpp"

namespace ferro::vehicle::detail {
namespace {

// The absolute tolerance of an output state that takes it out of the error test (weight
// 1/(rtol |y| + atol) ~ 1e-30).
constexpr double kOutputAtol = 1e30;

}  // namespace

Handles::~Handles() {
  if (mem != nullptr) {
    if (arkstep) {
      ARKStepFree(&mem);
    } else if (arkode) {
      ERKStepFree(&mem);
    } else {
      CVodeFree(&mem);
    }
  }
  if (NLS != nullptr) SUNNonlinSolFree(NLS);
  if (LS != nullptr) SUNLinSolFree(LS);
  if (A != nullptr) SUNMatDestroy(A);
  if (out != nullptr) N_VDestroy(out);
  if (y != nullptr) N_VDestroy(y);
  if (ctx != nullptr) SUNContext_Free(&ctx);
}

int sundials_rhs(realtype t, N_Vector y, N_Vector ydot, void* user_data) {
  auto* ud = static_cast<UserData*>(user_data);
  if (ud->monitor->stop_requested()) {
    ud->stopped = true;  // the solver gives up the step; run_loop reports the interruption
    return kRhsFatal;
  }
  const auto n = static_cast<std::size_t>(N_VGetLength(y));
  ++ud->rhs_evaluations;
  try {
    return ud->system->rhs(t, std::span<const double>(N_VGetArrayPointer(y), n),
                           std::span<double>(N_VGetArrayPointer(ydot), n));
  } catch (const std::exception& e) {
    ud->last_error = fmt::format("right-hand side threw at t = {} s: {}", t, e.what());
    return kRhsFatal;
  }
}

void error_handler(int error_code, const char* module, const char* function, char* msg,
                   void* user_data) {
  auto* ud = static_cast<UserData*>(user_data);
  if (ud->last_error.empty() || error_code != 0) {
    ud->last_error = fmt::format("{}::{}: {}", module, function, msg);
  }
}

std::string owned_flag_name(char* name) {
  std::string out = name != nullptr ? name : "unknown flag";
  std::free(name);
  return out;
}

void check(int flag, const char* what) {
  if (flag < 0)
    throw std::runtime_error(fmt::format("SUNDIALS setup failed in {} (flag {})", what, flag));
}

void set_tolerances(Handles& h, const OdeSystem& system, const IntegratorSettings& s,
                    int (*scalar)(void*, realtype, realtype),
                    int (*vector)(void*, realtype, N_Vector), bool scaled) {
  const std::vector<double> scales = scaled ? system.tolerance_scales() : std::vector<double>{};
  const std::vector<std::size_t> outputs = system.output_states();
  if (scales.empty() && outputs.empty()) {
    check(scalar(h.mem, s.rtol, s.atol), "SStolerances");
    return;
  }
  N_Vector atol = N_VClone(h.y);
  double* a = N_VGetArrayPointer(atol);
  const auto n = static_cast<std::size_t>(N_VGetLength(h.y));
  for (std::size_t i = 0; i < n; ++i) a[i] = s.atol * (scales.empty() ? 1.0 : scales[i]);
  for (const std::size_t i : outputs) a[i] = kOutputAtol;
  const int flag = vector(h.mem, s.rtol, atol);  // the solver keeps its own copy
  N_VDestroy(atol);
  check(flag, "SVtolerances");
}

namespace {

// The solver's current time and interpolated state, for failure reports.
void current_state(Handles& h, const PackageCalls& calls, double* t, std::vector<double>& y) {
  if (calls.get_time(h.mem, t) < 0) return;
  const sunindextype n = N_VGetLength(h.y);
  N_Vector tmp = N_VNew_Serial(n, h.ctx);
  if (calls.get_dky(h.mem, *t, 0, tmp) >= 0) {
    y.assign(N_VGetArrayPointer(tmp), N_VGetArrayPointer(tmp) + n);
  }
  N_VDestroy(tmp);
}

// The steps of one output interval, up to tout. Empty when they all passed; otherwise the
// run's end (solver failure, divergence, stop request) in `result`.
bool steps_to(double tout, Handles& h, UserData& ud, long max_steps, const PackageCalls& calls,
              double& t_step, std::vector<double>& y_step, IntegrationResult& result) {
  constexpr int kTooMuchWork = -1;  // CV_TOO_MUCH_WORK, ARK_TOO_MUCH_WORK
  const auto n = static_cast<std::size_t>(N_VGetLength(h.y));
  const double* yp = N_VGetArrayPointer(h.y);
  // Ends the run at time t with the state in y (the step that just ended, or one that failed).
  const auto stop_at = [&](double t, const double* y, IntegrationResult::Status status,
                           std::string message) {
    result.status = status;
    result.message = std::move(message);
    result.t_reached = t;
    result.state.assign(y, y + n);
    return false;
  };
  const auto flag_name = [&](int flag) { return owned_flag_name(calls.flag_name(flag)); };
  for (long steps = 0; t_step < tout; ++steps) {
    const double last_output = result.t_reached;
    if (steps >= max_steps) {
      return stop_at(
          t_step, y_step.data(), IntegrationResult::Status::kSolverFailure,
          fmt::format("{} at t = {:.9g} s (last output t = {:.9g} s): more than max_steps = {} "
                      "steps before output t = {:.9g} s",
                      flag_name(kTooMuchWork), t_step, last_output, max_steps, tout));
    }
    double t_new = t_step;
    const int flag = calls.step_one(tout, &t_new);
    if (flag < 0) {
      // The run ends at the last accepted step; the message gives where the solver was.
      if (ud.stopped) {
        return stop_at(t_step, y_step.data(), IntegrationResult::Status::kInterrupted, {});
      }
      double t_cur = t_step;
      std::vector<double> y_cur = y_step;
      current_state(h, calls, &t_cur, y_cur);
      return stop_at(t_step, y_step.data(), IntegrationResult::Status::kSolverFailure,
                     fmt::format("{} at t = {:.9g} s (last output t = {:.9g} s): {}",
                                 flag_name(flag), t_cur, last_output,
                                 ud.last_error.empty() ? "no detail" : ud.last_error));
    }
    // A step that leaves the bounds ends the run with the offending state.
    std::string cause = ud.monitor->divergence(t_new, std::span<const double>(yp, n));
    if (!cause.empty()) {
      return stop_at(t_new, yp, IntegrationResult::Status::kSolverFailure,
                     fmt::format("{} at t = {:.9g} s (last output t = {:.9g} s): {}", ud.method,
                                 t_new, last_output, cause));
    }
    t_step = t_new;
    y_step.assign(yp, yp + n);
    if (ud.monitor->stop_requested())
      return stop_at(t_step, y_step.data(), IntegrationResult::Status::kInterrupted, {});
  }
  return true;
}

// The outputs, each interpolated at its time after the steps that reach it.
IntegrationResult outputs_loop(Handles& h, UserData& ud, const std::vector<double>& times,
                               const Observer& observer, long max_steps,
                               const PackageCalls& calls) {
  IntegrationResult result;
  const auto n = static_cast<std::size_t>(N_VGetLength(h.y));
  const double* yp = N_VGetArrayPointer(h.y);
  h.out = N_VClone(h.y);
  const double* outp = N_VGetArrayPointer(h.out);
  result.t_reached = times.front();
  result.state.assign(yp, yp + n);
  if (!observer(times.front(), result.state)) {
    result.status = IntegrationResult::Status::kInterrupted;
    return result;
  }
  double t_step = times.front();           // end of the last accepted step
  std::vector<double> y_step(yp, yp + n);  // and the state there
  for (std::size_t i = 1; i < times.size(); ++i) {
    const double tout = times[i];
    if (!steps_to(tout, h, ud, max_steps, calls, t_step, y_step, result)) return result;
    const int flag = calls.get_dky(h.mem, tout, 0, h.out);
    if (flag < 0) {
      result.status = IntegrationResult::Status::kSolverFailure;
      result.message = fmt::format("{} interpolating the output t = {:.9g} s",
                                   owned_flag_name(calls.flag_name(flag)), tout);
      result.t_reached = t_step;
      result.state = y_step;
      return result;
    }
    // The interpolant between two accepted steps may leave the bounds the step ends keep.
    std::string cause = ud.monitor->divergence(tout, std::span<const double>(outp, n));
    if (!cause.empty()) {
      result.status = IntegrationResult::Status::kSolverFailure;
      result.message = fmt::format("{} at output t = {:.9g} s (last output t = {:.9g} s): {}",
                                   ud.method, tout, result.t_reached, cause);
      result.t_reached = tout;
      result.state.assign(outp, outp + n);
      return result;
    }
    result.t_reached = tout;
    result.state.assign(outp, outp + n);
    if (!observer(tout, result.state)) {
      result.status = IntegrationResult::Status::kInterrupted;
      return result;
    }
  }
  return result;
}

}  // namespace

IntegrationResult run_loop(Handles& h, UserData& ud, const std::vector<double>& times,
                           const Observer& observer, long max_steps, const PackageCalls& calls) {
  IntegrationResult result = outputs_loop(h, ud, times, observer, max_steps, calls);
  long steps = 0;
  calls.num_steps(h.mem, &steps);
  result.steps = steps;
  result.rhs_evaluations = ud.rhs_evaluations;
  return result;
}

}  // namespace ferro::vehicle::detail
