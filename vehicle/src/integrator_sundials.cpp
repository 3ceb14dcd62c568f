// SUNDIALS adapters: CVODE (BDF + Newton, dense or banded; Adams + fixed point), ARKODE
// ERKStep (explicit Runge-Kutta) and ARKODE ARKStep with an implicit, L-stable, stiffly
// accurate ESDIRK table (Newton, dense or banded). SUNDIALS 6.x API.
#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <string>

#include "integrator_impl.hpp"

namespace ferro::vehicle::detail {
namespace {

// A non-zero of the output-state blocks of the Jacobian (OutputBlockMatrix below).
struct BlockEntry {
  Eigen::Index row, col;  // C: output slot, dynamic slot; D: output slots
  double value;
};

struct UserData {
  const OdeSystem* system = nullptr;
  long rhs_evaluations = 0;
  std::string last_error;  // from the SUNDIALS error handler or a caught exception
  std::vector<char> is_output;  // per state: an output state (OdeSystem::output_states)
  // The output states' block D of the Jacobian (constant by their contract), once computed.
  std::vector<BlockEntry> output_entries;
};

// The system's output states as a mask (empty when it has none).
std::vector<char> output_mask(const OdeSystem& system) {
  const auto outputs = system.output_states();
  if (outputs.empty()) return {};
  std::vector<char> mask(system.size(), 0);
  for (std::size_t i : outputs) mask.at(i) = 1;
  return mask;
}

// The absolute tolerance of an output state that takes it out of the error test (weight
// 1/(rtol |y| + atol) ~ 1e-30).
constexpr double kOutputAtol = 1e30;

int sundials_rhs(realtype t, N_Vector y, N_Vector ydot, void* user_data) {
  auto* ud = static_cast<UserData*>(user_data);
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

// Owns the SUNDIALS objects of one run.
struct Handles {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  SUNNonlinearSolver NLS = nullptr;
  void* mem = nullptr;
  bool arkode = false;
  bool arkstep = false;
  ~Handles() {
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
    if (y != nullptr) N_VDestroy(y);
    if (ctx != nullptr) SUNContext_Free(&ctx);
  }
};

// SUNDIALS' *GetReturnFlagName functions return a malloc'd string owned by the caller.
std::string owned_flag_name(char* name) {
  std::string out = name != nullptr ? name : "unknown flag";
  std::free(name);
  return out;
}

void check(int flag, const char* what) {
  if (flag < 0)
    throw std::runtime_error(fmt::format("SUNDIALS setup failed in {} (flag {})", what, flag));
}

// Dense LU of the Newton matrix by Eigen's partial-pivoting LU (blocked and vectorised; on the
// 60-70 states of a vehicle it factors and solves several times faster than SUNDIALS' own
// dense and band LU), behind SUNDIALS' generic direct linear-solver interface.
struct EigenDenseLu {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  // With output states (OutputBlockMatrix): one LU per group of output states.
  struct Group {
    std::vector<Eigen::Index> slots;  // output slots
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  };
  std::vector<Group> groups;
};

// The Jacobian and Newton matrix of a system with output states (OdeSystem::output_states):
// block lower triangular, [A 0; C D] with the other ("dynamic") states first, since no dynamic
// derivative depends on an output state. A is dense; C and D are kept by their non-zeros (D
// always with its diagonal), so copying and scaling the matrix, which SUNDIALS does at every
// Newton-matrix update, costs the dynamic block and the few couplings, not the square of the
// whole state count. The solver factors A and each group of output states D connects (one
// filter cascade), and solves A x_d = b_d, then D x_o = b_o - C x_d group by group.
struct BlockStructure {
  std::vector<Eigen::Index> dynamic, output;  // state indices
  std::vector<Eigen::Index> slot;             // per state: its index in dynamic or output
  std::vector<char> is_output;
};
struct OutputBlockMatrix {
  std::shared_ptr<const BlockStructure> s;
  Eigen::MatrixXd a;
  std::vector<BlockEntry> c, d;
};

OutputBlockMatrix& block_of(SUNMatrix m) { return *static_cast<OutputBlockMatrix*>(m->content); }

SUNMatrix new_block_matrix(SUNContext ctx, std::shared_ptr<const BlockStructure> s);

void set_block_ops(SUNMatrix m) {
  m->ops->getid = [](SUNMatrix) { return SUNMATRIX_CUSTOM; };
  m->ops->clone = [](SUNMatrix a) { return new_block_matrix(a->sunctx, block_of(a).s); };
  m->ops->destroy = [](SUNMatrix a) {
    if (a == nullptr) return;
    delete static_cast<OutputBlockMatrix*>(a->content);
    a->content = nullptr;
    SUNMatFreeEmpty(a);
  };
  m->ops->zero = [](SUNMatrix a) {
    auto& b = block_of(a);
    b.a.setZero();
    b.c.clear();
    b.d.clear();
    return 0;
  };
  m->ops->copy = [](SUNMatrix from, SUNMatrix to) {
    const auto& f = block_of(from);
    auto& t = block_of(to);
    t.a = f.a;
    t.c = f.c;
    t.d = f.d;
    return 0;
  };
  m->ops->scaleaddi = [](realtype g, SUNMatrix a) {  // A = g A + I
    auto& b = block_of(a);
    b.a *= g;
    b.a.diagonal().array() += 1.0;
    for (auto& e : b.c) e.value *= g;
    for (auto& e : b.d) e.value = g * e.value + (e.row == e.col ? 1.0 : 0.0);
    return 0;
  };
}

SUNMatrix new_block_matrix(SUNContext ctx, std::shared_ptr<const BlockStructure> s) {
  SUNMatrix m = SUNMatNewEmpty(ctx);
  if (m == nullptr) throw std::runtime_error("SUNMatNewEmpty failed");
  const auto nd = static_cast<Eigen::Index>(s->dynamic.size());
  m->content = new OutputBlockMatrix{std::move(s), Eigen::MatrixXd::Zero(nd, nd), {}, {}};
  set_block_ops(m);
  return m;
}

std::shared_ptr<const BlockStructure> block_structure(const std::vector<char>& is_output) {
  auto s = std::make_shared<BlockStructure>();
  s->is_output = is_output;
  s->slot.resize(is_output.size());
  for (std::size_t i = 0; i < is_output.size(); ++i) {
    auto& list = is_output[i] != 0 ? s->output : s->dynamic;
    s->slot[i] = static_cast<Eigen::Index>(list.size());
    list.push_back(static_cast<Eigen::Index>(i));
  }
  return s;
}

bool pivots_ok(const Eigen::PartialPivLU<Eigen::MatrixXd>& lu) {
  const double min_pivot = lu.matrixLU().diagonal().cwiseAbs().minCoeff();
  return min_pivot > 0.0 && std::isfinite(min_pivot);
}

// LU of the block matrix: A, and each group of output states D's entries connect.
int setup_block(EigenDenseLu& c, const OutputBlockMatrix& m) {
  c.lu.compute(m.a);
  if (!pivots_ok(c.lu)) return 1;
  const auto no = static_cast<Eigen::Index>(m.s->output.size());
  std::vector<Eigen::Index> parent(static_cast<std::size_t>(no));
  for (Eigen::Index i = 0; i < no; ++i) parent[static_cast<std::size_t>(i)] = i;
  const auto root = [&](Eigen::Index i) {
    while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)];
    return i;
  };
  for (const auto& e : m.d) parent[static_cast<std::size_t>(root(e.row))] = root(e.col);
  std::vector<Eigen::Index> group_of(static_cast<std::size_t>(no), -1), index_in(static_cast<std::size_t>(no), 0);
  c.groups.clear();
  for (Eigen::Index i = 0; i < no; ++i) {
    const Eigen::Index r = root(i);
    if (group_of[static_cast<std::size_t>(r)] < 0) {
      group_of[static_cast<std::size_t>(r)] = static_cast<Eigen::Index>(c.groups.size());
      c.groups.emplace_back();
    }
    auto& g = c.groups[static_cast<std::size_t>(group_of[static_cast<std::size_t>(r)])];
    index_in[static_cast<std::size_t>(i)] = static_cast<Eigen::Index>(g.slots.size());
    g.slots.push_back(i);
  }
  std::vector<Eigen::MatrixXd> blocks;
  for (const auto& g : c.groups) {
    const auto k = static_cast<Eigen::Index>(g.slots.size());
    blocks.emplace_back(Eigen::MatrixXd::Zero(k, k));
  }
  for (const auto& e : m.d) {
    const auto gi = static_cast<std::size_t>(group_of[static_cast<std::size_t>(root(e.row))]);
    blocks[gi](index_in[static_cast<std::size_t>(e.row)], index_in[static_cast<std::size_t>(e.col)]) += e.value;
  }
  for (std::size_t gi = 0; gi < c.groups.size(); ++gi) {
    c.groups[gi].lu.compute(blocks[gi]);
    if (!pivots_ok(c.groups[gi].lu)) return 1;
  }
  return 0;
}

SUNLinearSolver eigen_dense_lu(SUNContext ctx) {
  SUNLinearSolver s = SUNLinSolNewEmpty(ctx);
  if (s == nullptr) throw std::runtime_error("SUNLinSolNewEmpty failed");
  s->content = new EigenDenseLu();
  s->ops->gettype = [](SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; };
  s->ops->getid = [](SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; };
  s->ops->initialize = [](SUNLinearSolver) { return 0; };
  s->ops->setup = [](SUNLinearSolver ls, SUNMatrix a) {
    auto& c = *static_cast<EigenDenseLu*>(ls->content);
    if (SUNMatGetID(a) == SUNMATRIX_CUSTOM) return setup_block(c, block_of(a));
    const auto n = static_cast<Eigen::Index>(SUNDenseMatrix_Rows(a));
    const Eigen::Map<const Eigen::MatrixXd> m(SUNDenseMatrix_Data(a), n, n);  // column-major
    c.lu.compute(m);
    // A zero pivot: tell the integrator to retry with a smaller step.
    return pivots_ok(c.lu) ? 0 : 1;
  };
  s->ops->solve = [](SUNLinearSolver ls, SUNMatrix a, N_Vector x, N_Vector b, realtype) {
    const auto n = static_cast<Eigen::Index>(N_VGetLength(b));
    const Eigen::Map<const Eigen::VectorXd> rhs(N_VGetArrayPointer(b), n);
    Eigen::Map<Eigen::VectorXd> out(N_VGetArrayPointer(x), n);
    const auto& c = *static_cast<EigenDenseLu*>(ls->content);
    if (SUNMatGetID(a) != SUNMATRIX_CUSTOM) {
      out = c.lu.solve(rhs);
      return out.allFinite() ? 0 : 1;
    }
    const auto& m = block_of(a);
    const auto& st = *m.s;
    Eigen::VectorXd bd(static_cast<Eigen::Index>(st.dynamic.size()));
    for (std::size_t i = 0; i < st.dynamic.size(); ++i) bd[static_cast<Eigen::Index>(i)] = rhs[st.dynamic[i]];
    const Eigen::VectorXd xd = c.lu.solve(bd);
    Eigen::VectorXd bo(static_cast<Eigen::Index>(st.output.size()));
    for (std::size_t i = 0; i < st.output.size(); ++i) bo[static_cast<Eigen::Index>(i)] = rhs[st.output[i]];
    for (const auto& e : m.c) bo[e.row] -= e.value * xd[e.col];
    for (std::size_t i = 0; i < st.dynamic.size(); ++i) out[st.dynamic[i]] = xd[static_cast<Eigen::Index>(i)];
    for (const auto& g : c.groups) {
      Eigen::VectorXd bg(static_cast<Eigen::Index>(g.slots.size()));
      for (std::size_t i = 0; i < g.slots.size(); ++i) bg[static_cast<Eigen::Index>(i)] = bo[g.slots[i]];
      const Eigen::VectorXd xg = g.lu.solve(bg);
      for (std::size_t i = 0; i < g.slots.size(); ++i)
        out[st.output[static_cast<std::size_t>(g.slots[i])]] = xg[static_cast<Eigen::Index>(i)];
    }
    return out.allFinite() ? 0 : 1;
  };
  s->ops->free = [](SUNLinearSolver ls) {
    if (ls == nullptr) return 0;
    delete static_cast<EigenDenseLu*>(ls->content);
    ls->content = nullptr;
    SUNLinSolFreeEmpty(ls);
    return 0;
  };
  return s;
}

// Dense finite-difference Jacobian of the right-hand side, column j from a forward difference
// with the increment sqrt(u max(1e-5, |y_j|)) (u the unit round-off), as Hairer and Wanner's
// RADAU5 forms it. SUNDIALS' own difference quotient takes sqrt(u) |y_j| for a state away
// from zero, but for a state near zero its minimum increment 1000 |h| u n ||f||_wrms / w_j,
// proportional to the weighted norm of f: once a vehicle has settled on its equilibrium that
// norm falls towards zero, so does the increment, the columns become round-off, and the
// Newton iteration fails at every step even with a fresh Jacobian (ARKODE's ESDIRK on the
// Cooperrider wagon: the step fell from 0.23 s to ~2 ms once the 0.1 mm kick had decayed).
// The same difference quotients into an OutputBlockMatrix: the dynamic columns every time; the
// output states' columns (constant by their contract) once, kept in the user data.
constexpr double kUnitRoundoff = 2.220446049250313e-16;
constexpr double kUnitScale = 1e-5;  // RADAU5's floor on |y_j| for the increment

int block_dq_jacobian(realtype t, N_Vector y, N_Vector fy, SUNMatrix jac, void* user_data,
                      N_Vector tmp1) {
  auto& ud = *static_cast<UserData*>(user_data);
  auto& m = block_of(jac);
  const BlockStructure& st = *m.s;
  const auto n = static_cast<std::size_t>(N_VGetLength(y));
  double* yd = N_VGetArrayPointer(y);
  const double* f0 = N_VGetArrayPointer(fy);
  const double* f1 = N_VGetArrayPointer(tmp1);
  m.a.setZero();
  m.c.clear();
  const bool outputs_known = !ud.output_entries.empty();
  for (std::size_t j = 0; j < n; ++j) {
    const bool output_column = st.is_output[j] != 0;
    if (output_column && outputs_known) continue;
    const double yj = yd[j];
    const double step = std::sqrt(kUnitRoundoff * std::max(kUnitScale, std::abs(yj)));
    yd[j] = yj + step;
    const double inc = yd[j] - yj;
    const int flag = sundials_rhs(t, y, tmp1, user_data);
    yd[j] = yj;
    if (flag != 0) return flag;
    const Eigen::Index col = st.slot[j];
    for (std::size_t i = 0; i < n; ++i) {
      const double v = (f1[i] - f0[i]) / inc;
      const Eigen::Index row = st.slot[i];
      if (output_column) {
        if (st.is_output[i] != 0 && (v != 0.0 || i == j)) ud.output_entries.push_back({row, col, v});
      } else if (st.is_output[i] == 0) {
        m.a(row, col) = v;
      } else if (v != 0.0) {
        m.c.push_back({row, col, v});
      }
    }
  }
  m.d = ud.output_entries;
  return 0;
}

int dense_dq_jacobian(realtype t, N_Vector y, N_Vector fy, SUNMatrix jac, void* user_data,
                      N_Vector tmp1, N_Vector, N_Vector) {
  const auto n = static_cast<std::size_t>(N_VGetLength(y));
  double* yd = N_VGetArrayPointer(y);
  const double* f0 = N_VGetArrayPointer(fy);
  const double* f1 = N_VGetArrayPointer(tmp1);
  if (SUNMatGetID(jac) == SUNMATRIX_CUSTOM) return block_dq_jacobian(t, y, fy, jac, user_data, tmp1);
  for (std::size_t j = 0; j < n; ++j) {
    const double yj = yd[j];
    const double step = std::sqrt(kUnitRoundoff * std::max(kUnitScale, std::abs(yj)));
    yd[j] = yj + step;
    const double inc = yd[j] - yj;  // the increment actually represented
    const int flag = sundials_rhs(t, y, tmp1, user_data);
    yd[j] = yj;
    if (flag != 0) return flag;
    double* col = SUNDenseMatrix_Column(jac, static_cast<sunindextype>(j));
    for (std::size_t i = 0; i < n; ++i) col[i] = (f1[i] - f0[i]) / inc;
  }
  return 0;
}

// The Newton iteration's direct linear solver: banded with the system's declared half-bandwidths
// (the whole matrix when it declares none), or dense (Eigen's LU).
void make_direct_solver(Handles& h, const OdeSystem& system, const std::string& kind,
                        const UserData& ud) {
  const auto n = static_cast<sunindextype>(system.size());
  auto [upper, lower] = system.jacobian_bandwidth();
  if (kind == "band") {
    if (upper < 0 || lower < 0) upper = lower = static_cast<int>(n) - 1;
    h.A = SUNBandMatrix(n, upper, lower, h.ctx);
    h.LS = SUNLinSol_Band(h.y, h.A, h.ctx);
  } else {
    h.A = ud.is_output.empty() ? SUNDenseMatrix(n, n, h.ctx)
                               : new_block_matrix(h.ctx, block_structure(ud.is_output));
    h.LS = eigen_dense_lu(h.ctx);
  }
}

// Tolerances: rtol and atol, or atol per state scaled by the system's tolerance_scales() (when
// `scaled`), the output states out of the error test (kOutputAtol); `scalar` and `vector` are
// the package's SStolerances and SVtolerances functions.
template <class Scalar, class Vector>
void set_tolerances(Handles& h, const OdeSystem& system, const UserData& ud,
                    const IntegratorSettings& s, Scalar scalar, Vector vector, bool scaled = true) {
  const std::vector<double> scales = scaled ? system.tolerance_scales() : std::vector<double>{};
  if (scales.empty() && ud.is_output.empty()) {
    check(scalar(h.mem, s.rtol, s.atol), "SStolerances");
    return;
  }
  N_Vector atol = N_VClone(h.y);
  const auto n = static_cast<std::size_t>(N_VGetLength(h.y));
  for (std::size_t i = 0; i < n; ++i) {
    N_VGetArrayPointer(atol)[i] = !ud.is_output.empty() && ud.is_output[i] != 0
                                      ? kOutputAtol
                                      : s.atol * (scales.empty() ? 1.0 : scales[i]);
  }
  const int flag = vector(h.mem, s.rtol, atol);  // the solver keeps its own copy
  N_VDestroy(atol);
  check(flag, "SVtolerances");
}

// The solver's current time and interpolated state, for failure reports: `get_time` and
// `get_dky` are the package's GetCurrentTime and GetDky functions.
template <class GetTime, class GetDky>
auto state_reader(Handles& h, GetTime get_time, GetDky get_dky) {
  return [&h, get_time, get_dky](double* t, std::vector<double>& y) {
    if (get_time(h.mem, t) < 0) return;
    const sunindextype n = N_VGetLength(h.y);
    N_Vector tmp = N_VNew_Serial(n, h.ctx);
    if (get_dky(h.mem, *t, 0, tmp) >= 0) {
      y.assign(N_VGetArrayPointer(tmp), N_VGetArrayPointer(tmp) + n);
    }
    N_VDestroy(tmp);
  };
}

// Adds the step and right-hand-side counts to a finished run; `num_steps` is the package's
// GetNumSteps function.
template <class NumSteps>
IntegrationResult with_counts(IntegrationResult result, Handles& h, const UserData& ud,
                              NumSteps num_steps) {
  long steps = 0;
  num_steps(h.mem, &steps);
  result.steps = steps;
  result.rhs_evaluations = ud.rhs_evaluations;
  return result;
}

// The output loop, shared by CVODE and ARKODE. `step_to` advances to tout and returns the flag;
// `current` returns the solver's internal time and state for failure reports.
template <class StepTo, class Current, class FlagName>
IntegrationResult run_loop(Handles& h, UserData& ud, const std::vector<double>& times,
                           const Observer& observer, StepTo step_to, Current current,
                           FlagName flag_name) {
  IntegrationResult result;
  const auto n = static_cast<std::size_t>(N_VGetLength(h.y));
  double* yp = N_VGetArrayPointer(h.y);
  result.t_reached = times.front();
  result.state.assign(yp, yp + n);
  if (!observer(times.front(), result.state)) {
    result.status = IntegrationResult::Status::kInterrupted;
    return result;
  }
  for (std::size_t i = 1; i < times.size(); ++i) {
    double t = 0.0;
    const int flag = step_to(times[i], &t);
    if (flag < 0) {
      double t_cur = result.t_reached;
      std::vector<double> y_cur = result.state;
      current(&t_cur, y_cur);
      result.status = IntegrationResult::Status::kSolverFailure;
      result.message =
          fmt::format("{} at t = {:.9g} s (last output t = {:.9g} s): {}", flag_name(flag), t_cur,
                      result.t_reached, ud.last_error.empty() ? "no detail" : ud.last_error);
      result.t_reached = t_cur;
      result.state = std::move(y_cur);
      return result;
    }
    result.t_reached = t;
    result.state.assign(yp, yp + n);
    if (!observer(t, result.state)) {
      result.status = IntegrationResult::Status::kInterrupted;
      return result;
    }
  }
  return result;
}

class CvodeIntegrator final : public Integrator {
 public:
  explicit CvodeIntegrator(IntegratorSettings s) : s_(std::move(s)) {}
  [[nodiscard]] std::string name() const override { return s_.method; }

  IntegrationResult integrate(const OdeSystem& system, std::span<const double> x0,
                              const std::vector<double>& times, const Observer& observer) override {
    Handles h;
    UserData ud{&system, 0, {}, output_mask(system), {}};
    const auto n = static_cast<sunindextype>(system.size());
    check(SUNContext_Create(nullptr, &h.ctx), "SUNContext_Create");
    h.y = N_VNew_Serial(n, h.ctx);
    std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(h.y));
    const bool bdf = s_.method == "cvode_bdf";
    h.mem = CVodeCreate(bdf ? CV_BDF : CV_ADAMS, h.ctx);
    if (h.mem == nullptr) throw std::runtime_error("CVodeCreate failed");
    check(CVodeSetErrHandlerFn(h.mem, error_handler, &ud), "CVodeSetErrHandlerFn");
    check(CVodeInit(h.mem, sundials_rhs, times.front(), h.y), "CVodeInit");
    check(CVodeSetUserData(h.mem, &ud), "CVodeSetUserData");
    set_tolerances(h, system, ud, s_, CVodeSStolerances, CVodeSVtolerances);
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
    return with_counts(
        run_loop(
            h, ud, times, observer,
            [&](double tout, double* t) { return CVode(h.mem, tout, h.y, t, CV_NORMAL); },
            state_reader(h, CVodeGetCurrentTime, CVodeGetDky),
            [](int flag) { return owned_flag_name(CVodeGetReturnFlagName(flag)); }),
        h, ud, CVodeGetNumSteps);
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
    UserData ud{&system, 0, {}, output_mask(system), {}};
    const auto n = static_cast<sunindextype>(system.size());
    check(SUNContext_Create(nullptr, &h.ctx), "SUNContext_Create");
    h.y = N_VNew_Serial(n, h.ctx);
    std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(h.y));
    h.mem = ERKStepCreate(sundials_rhs, times.front(), h.y, h.ctx);
    if (h.mem == nullptr) throw std::runtime_error("ERKStepCreate failed");
    check(ERKStepSetErrHandlerFn(h.mem, error_handler, &ud), "ERKStepSetErrHandlerFn");
    check(ERKStepSetUserData(h.mem, &ud), "ERKStepSetUserData");
    set_tolerances(h, system, ud, s_, ERKStepSStolerances, ERKStepSVtolerances,
                   /*scaled=*/false);
    check(ERKStepSetOrder(h.mem, s_.erk_order), "ERKStepSetOrder");
    if (std::isfinite(s_.max_step))
      check(ERKStepSetMaxStep(h.mem, s_.max_step), "ERKStepSetMaxStep");
    if (s_.initial_step > 0.0)
      check(ERKStepSetInitStep(h.mem, s_.initial_step), "ERKStepSetInitStep");
    check(ERKStepSetMaxNumSteps(h.mem, s_.max_steps), "ERKStepSetMaxNumSteps");
    if (s_.fixed_step > 0.0) check(ERKStepSetFixedStep(h.mem, s_.fixed_step), "ERKStepSetFixedStep");
    return with_counts(
        run_loop(
            h, ud, times, observer,
            [&](double tout, double* t) { return ERKStepEvolve(h.mem, tout, h.y, t, ARK_NORMAL); },
            state_reader(h, ERKStepGetCurrentTime, ERKStepGetDky),
            [](int flag) { return owned_flag_name(ERKStepGetReturnFlagName(flag)); }),
        h, ud, ERKStepGetNumSteps);
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
    UserData ud{&system, 0, {}, output_mask(system), {}};
    const auto n = static_cast<sunindextype>(system.size());
    check(SUNContext_Create(nullptr, &h.ctx), "SUNContext_Create");
    h.y = N_VNew_Serial(n, h.ctx);
    std::copy(x0.begin(), x0.end(), N_VGetArrayPointer(h.y));
    h.mem = ARKStepCreate(nullptr, sundials_rhs, times.front(), h.y, h.ctx);
    if (h.mem == nullptr) throw std::runtime_error("ARKStepCreate failed");
    check(ARKStepSetErrHandlerFn(h.mem, error_handler, &ud), "ARKStepSetErrHandlerFn");
    check(ARKStepSetUserData(h.mem, &ud), "ARKStepSetUserData");
    set_tolerances(h, system, ud, s_, ARKStepSStolerances, ARKStepSVtolerances);
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
    return with_counts(
        run_loop(
            h, ud, times, observer,
            [&](double tout, double* t) { return ARKStepEvolve(h.mem, tout, h.y, t, ARK_NORMAL); },
            state_reader(h, ARKStepGetCurrentTime, ARKStepGetDky),
            [](int flag) { return owned_flag_name(ARKStepGetReturnFlagName(flag)); }),
        h, ud, ARKStepGetNumSteps);
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
