#pragma once
// Private parts shared by the SUNDIALS adapters (integrator_sundials.cpp): the user data the
// callbacks see, the owner of one run's SUNDIALS objects, the right-hand-side and error
// callbacks, tolerances, the Newton iteration's direct linear solver (sundials_linear.cpp) and
// the output loop (sundials_run.cpp). SUNDIALS 6.x API.
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nonlinearsolver.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "integrator_impl.hpp"
#include "output_blocks.hpp"

namespace ferro::vehicle::detail {

// A non-zero of the output-state blocks of the Jacobian is a BlockEntry (output_blocks.hpp).
struct UserData {
  const OdeSystem* system = nullptr;
  const StepMonitor* monitor = nullptr;
  long rhs_evaluations = 0;
  bool stopped = false;    // a stop request ended a right-hand side
  std::string method;      // the integrator's name, for messages
  std::string last_error;  // from the SUNDIALS error handler or a caught exception
  // The dynamic and output states when the system has output states feeding nothing back
  // (OutputBlocks::make), else null.
  std::shared_ptr<const OutputBlocks> blocks;
  // The output states' block D of the Jacobian (constant by their contract), once computed.
  std::vector<BlockEntry> output_entries;
};

// Owns the SUNDIALS objects of one run.
struct Handles {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector out = nullptr;  // interpolated output state
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  SUNNonlinearSolver NLS = nullptr;
  void* mem = nullptr;
  bool arkode = false;
  bool arkstep = false;
  Handles() = default;
  Handles(const Handles&) = delete;
  Handles& operator=(const Handles&) = delete;
  ~Handles();
};

// The right-hand side for SUNDIALS (user_data: UserData); a stop request or an exception makes
// it fatal.
int sundials_rhs(realtype t, N_Vector y, N_Vector ydot, void* user_data);
// Keeps the package's message in the UserData.
void error_handler(int error_code, const char* module, const char* function, char* msg,
                   void* user_data);
// SUNDIALS' *GetReturnFlagName functions return a malloc'd string owned by the caller.
std::string owned_flag_name(char* name);
// Throws on a negative setup flag, naming the call.
void check(int flag, const char* what);

// Tolerances: rtol and atol, or atol per state scaled by the system's tolerance_scales() (when
// `scaled`), the output states out of the error test; `scalar` and `vector` are the package's
// SStolerances and SVtolerances functions.
void set_tolerances(Handles& h, const OdeSystem& system, const IntegratorSettings& s,
                    int (*scalar)(void*, realtype, realtype),
                    int (*vector)(void*, realtype, N_Vector), bool scaled = true);

// The Newton iteration's direct linear solver into h.A and h.LS: banded with the system's
// declared half-bandwidths (the whole matrix when it declares none), or dense (Eigen's LU, by
// blocks when ud.blocks is set).
void make_direct_solver(Handles& h, const OdeSystem& system, const std::string& kind,
                        const UserData& ud);
// The dense finite-difference Jacobian of the right-hand side (SUNDIALS' SUNLsJacFn), for the
// dense solver of make_direct_solver.
int dense_dq_jacobian(realtype t, N_Vector y, N_Vector fy, SUNMatrix jac, void* user_data,
                      N_Vector tmp1, N_Vector tmp2, N_Vector tmp3);

// The package's functions the output loop calls.
struct PackageCalls {
  std::function<int(double tout, double* t)> step_one;  // one internal step towards tout
  int (*get_dky)(void*, realtype, int, N_Vector);        // GetDky
  int (*get_time)(void*, realtype*);                     // GetCurrentTime
  int (*num_steps)(void*, long*);                        // GetNumSteps
  char* (*flag_name)(long);                              // GetReturnFlagName
};

// The output loop, shared by CVODE and ARKODE: one step at a time, so that every accepted step
// passes the StepMonitor (stop request, divergence guard); each output is interpolated at its
// time, which gives the same steps and outputs as the packages' own NORMAL mode. The result
// carries the step and right-hand-side counts.
IntegrationResult run_loop(Handles& h, UserData& ud, const std::vector<double>& times,
                           const Observer& observer, long max_steps, const PackageCalls& calls);

}  // namespace ferro::vehicle::detail
