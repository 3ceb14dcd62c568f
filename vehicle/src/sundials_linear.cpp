// The SUNDIALS adapters' Newton matrix, direct linear solver and finite-difference Jacobian
// (sundials_support.hpp).
//
// Dense LU of the Newton matrix by Eigen's partial-pivoting LU (blocked and vectorised; on the
// 60-70 states of a vehicle it factors and solves several times faster than SUNDIALS' own
// dense and band LU), behind SUNDIALS' generic direct linear-solver interface. With output
// states the matrix is an OutputBlockMatrix behind a custom SUNMatrix and the LU an
// OutputBlockLu (output_blocks.hpp).
#include <sunlinsol/sunlinsol_band.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "sundials_support.hpp"

namespace ferro::vehicle::detail {
namespace {

OutputBlockMatrix& block_of(SUNMatrix m) { return *static_cast<OutputBlockMatrix*>(m->content); }

SUNMatrix new_block_matrix(SUNContext ctx, std::shared_ptr<const OutputBlocks> blocks);

void set_block_ops(SUNMatrix m) {
  m->ops->getid = [](SUNMatrix) { return SUNMATRIX_CUSTOM; };
  m->ops->clone = [](SUNMatrix a) { return new_block_matrix(a->sunctx, block_of(a).blocks); };
  m->ops->destroy = [](SUNMatrix a) {
    if (a == nullptr) return;
    delete static_cast<OutputBlockMatrix*>(a->content);
    a->content = nullptr;
    SUNMatFreeEmpty(a);
  };
  m->ops->zero = [](SUNMatrix a) {
    block_of(a).set_zero();
    return 0;
  };
  m->ops->copy = [](SUNMatrix from, SUNMatrix to) {
    block_of(to) = block_of(from);
    return 0;
  };
  m->ops->scaleaddi = [](realtype g, SUNMatrix a) {  // A = g A + I
    block_of(a).scale_add_identity(g);
    return 0;
  };
}

SUNMatrix new_block_matrix(SUNContext ctx, std::shared_ptr<const OutputBlocks> blocks) {
  SUNMatrix m = SUNMatNewEmpty(ctx);
  if (m == nullptr) throw std::runtime_error("SUNMatNewEmpty failed");
  m->content = new OutputBlockMatrix(std::move(blocks));
  set_block_ops(m);
  return m;
}

// The linear solver's factors: of a dense SUNMatrix, or of an OutputBlockMatrix.
struct EigenDenseLu {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  OutputBlockLu blocks;
};

SUNLinearSolver eigen_dense_lu(SUNContext ctx) {
  SUNLinearSolver s = SUNLinSolNewEmpty(ctx);
  if (s == nullptr) throw std::runtime_error("SUNLinSolNewEmpty failed");
  s->content = new EigenDenseLu();
  s->ops->gettype = [](SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; };
  s->ops->getid = [](SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; };
  s->ops->initialize = [](SUNLinearSolver) { return 0; };
  // A zero pivot: tell the integrator to retry with a smaller step.
  s->ops->setup = [](SUNLinearSolver ls, SUNMatrix a) {
    auto& c = *static_cast<EigenDenseLu*>(ls->content);
    if (SUNMatGetID(a) == SUNMATRIX_CUSTOM) return c.blocks.compute(block_of(a)) ? 0 : 1;
    const auto n = static_cast<Eigen::Index>(SUNDenseMatrix_Rows(a));
    const Eigen::Map<const Eigen::MatrixXd> m(SUNDenseMatrix_Data(a), n, n);  // column-major
    c.lu.compute(m);
    return pivots_ok(c.lu) ? 0 : 1;
  };
  s->ops->solve = [](SUNLinearSolver ls, SUNMatrix a, N_Vector x, N_Vector b, realtype) {
    const auto n = static_cast<Eigen::Index>(N_VGetLength(b));
    const Eigen::Map<const Eigen::VectorXd> rhs(N_VGetArrayPointer(b), n);
    Eigen::Map<Eigen::VectorXd> out(N_VGetArrayPointer(x), n);
    const auto& c = *static_cast<EigenDenseLu*>(ls->content);
    if (SUNMatGetID(a) != SUNMATRIX_CUSTOM) {
      out = c.lu.solve(rhs);
    } else {
      c.blocks.solve(block_of(a), rhs.data(), out.data());
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
constexpr double kUnitRoundoff = 2.220446049250313e-16;
constexpr double kUnitScale = 1e-5;  // RADAU5's floor on |y_j| for the increment

// y_j perturbed by the increment above, f(t, y) into f1; returns the right-hand side's flag and
// the increment actually represented.
int perturbed_rhs(realtype t, N_Vector y, std::size_t j, N_Vector f1, void* user_data,
                  double& inc) {
  double* yd = N_VGetArrayPointer(y);
  const double yj = yd[j];
  yd[j] = yj + std::sqrt(kUnitRoundoff * std::max(kUnitScale, std::abs(yj)));
  inc = yd[j] - yj;
  const int flag = sundials_rhs(t, y, f1, user_data);
  yd[j] = yj;
  return flag;
}

// The same difference quotients into an OutputBlockMatrix: the dynamic columns every time; the
// output states' columns (constant by their contract) once, kept in the user data. Only the
// non-zeros of C and D are kept (D with its diagonal).
int block_dq_jacobian(realtype t, N_Vector y, N_Vector fy, SUNMatrix jac, void* user_data,
                      N_Vector tmp1) {
  auto& ud = *static_cast<UserData*>(user_data);
  auto& m = block_of(jac);
  const OutputBlocks& st = *m.blocks;
  const auto n = static_cast<std::size_t>(N_VGetLength(y));
  const double* f0 = N_VGetArrayPointer(fy);
  const double* f1 = N_VGetArrayPointer(tmp1);
  m.set_zero();
  const bool outputs_known = !ud.output_entries.empty();
  for (std::size_t j = 0; j < n; ++j) {
    const bool output_column = st.is_output[j] != 0;
    if (output_column && outputs_known) continue;
    double inc = 0.0;
    if (const int flag = perturbed_rhs(t, y, j, tmp1, user_data, inc); flag != 0) return flag;
    for (std::size_t i = 0; i < n; ++i) {
      const double v = (f1[i] - f0[i]) / inc;
      if (st.is_output[i] == 0) {
        if (!output_column) m.set(i, j, v);  // an output column feeds no dynamic state
      } else if (v != 0.0 || i == j) {
        m.set(i, j, v);
      }
    }
  }
  if (!outputs_known) ud.output_entries = m.d;
  m.d = ud.output_entries;
  return 0;
}

}  // namespace

int dense_dq_jacobian(realtype t, N_Vector y, N_Vector fy, SUNMatrix jac, void* user_data,
                      N_Vector tmp1, N_Vector, N_Vector) {
  if (SUNMatGetID(jac) == SUNMATRIX_CUSTOM) return block_dq_jacobian(t, y, fy, jac, user_data, tmp1);
  const auto n = static_cast<std::size_t>(N_VGetLength(y));
  const double* f0 = N_VGetArrayPointer(fy);
  const double* f1 = N_VGetArrayPointer(tmp1);
  for (std::size_t j = 0; j < n; ++j) {
    double inc = 0.0;
    if (const int flag = perturbed_rhs(t, y, j, tmp1, user_data, inc); flag != 0) return flag;
    double* col = SUNDenseMatrix_Column(jac, static_cast<sunindextype>(j));
    for (std::size_t i = 0; i < n; ++i) col[i] = (f1[i] - f0[i]) / inc;
  }
  return 0;
}

void make_direct_solver(Handles& h, const OdeSystem& system, const std::string& kind,
                        const UserData& ud) {
  const auto n = static_cast<sunindextype>(system.size());
  auto [upper, lower] = system.jacobian_bandwidth();
  if (kind == "band") {
    if (upper < 0 || lower < 0) upper = lower = static_cast<int>(n) - 1;
    h.A = SUNBandMatrix(n, upper, lower, h.ctx);
    h.LS = SUNLinSol_Band(h.y, h.A, h.ctx);
  } else {
    h.A = ud.blocks == nullptr ? SUNDenseMatrix(n, n, h.ctx) : new_block_matrix(h.ctx, ud.blocks);
    h.LS = eigen_dense_lu(h.ctx);
  }
}

}  // namespace ferro::vehicle::detail
