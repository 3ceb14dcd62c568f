// GMRES on the MIM linear systems: the project's restarted GMRES (ferro/contact/mim/gmres.hpp)
// against SUNDIALS SPGMR and Eigen's unsupported GMRES, on the same matrix-free FFT operators,
// the same right preconditioner, zero start, restart 80 (the tangential solver's default) and
// the same stopping test ||b - K x||_2 <= 1e-8 ||b||_2 (Eigen: GMRES on K P y = b, x = P y, so
// that its residual is the true one as well). Each run reports its products, its true relative
// residual and its distance to the project solver's solution.
//
// Systems, on the thesis's sphere case (bench/mim.cpp: R1 = 300 mm, R2 = 460 mm, steel,
// F_n = 517.9 kN), N x N elements over the patch with 5 % margin, restricted to the contact set
// of the normal solution:
//   normal  (arg 0): A^nn p = delta - h (rigid approach minus gap), no preconditioner;
//   sliding (arg 1): A^tt tau = -shift (Cattaneo full stick), FFT circulant inverse of A^tt;
//   rolling (arg 2): -(B^tt - A^tt) tau / dx = -c (Kalker full adhesion, eq. 113, xi_x = 3e-3),
//                    preconditioner dx C^-1 (I - S)^-1 (running sum from the leading edge).
//
// Run: ./build/bench/ferro_bench_gmres --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <unsupported/Eigen/IterativeSolvers>
#include <vector>

#include "ferro/contact/mim/gmres.hpp"
#include "ferro/contact/mim/normal_solver.hpp"

using namespace ferro::contact;
using namespace ferro::contact::mim;

namespace {

constexpr double kRrel = 1.0 / (1.0 / 0.300 + 1.0 / 0.460);
constexpr double kNormalForce = 517925.0;  // delta = 0.4 mm for these spheres [N]
constexpr double kRelTol = 1.0e-8;         // stopping test, relative to ||b||
constexpr int kRestart = 80;               // TangentialSolverOptions::gmres_restart default

enum class Kind { normal = 0, sliding = 1, rolling = 2 };

// One MIM linear system K x = b on the contact set, with its right preconditioner P.
class MimSystem {
 public:
  MimSystem(int n, Kind kind)
      : grid_(make_grid(n)), op_(grid_, steel_pair(), /*measure_plans=*/true), kind_(kind) {
    const Field gap =
        sample(grid_, [](double x, double y) { return (x * x + y * y) / (2.0 * kRrel); });
    const NormalGridSolution s = solve_normal_force(op_, gap, kNormalForce, NormalSolverOptions{});
    for (std::size_t i = 0; i < grid_.size(); ++i)
      if (s.pressure[i] > 0.0) set_.push_back(i);
    in_set_.assign(grid_.size(), false);
    for (std::size_t i : set_) in_set_[i] = true;
    const std::size_t comps = kind_ == Kind::normal ? 1 : 2;
    b_.assign(comps * set_.size(), 0.0);
    for (std::size_t k = 0; k < set_.size(); ++k) {
      if (kind_ == Kind::normal) {
        b_[k] = s.approach - gap[set_[k]];
      } else {  // shift of 1 um along x (sliding) or creepage xi_x (rolling): b = -rigid slip
        b_[2 * k] = kind_ == Kind::sliding ? -1.0e-6 : -3.0e-3;
      }
    }
    fx_.resize(grid_.size());
    fy_.resize(grid_.size());
    gx_.resize(grid_.size());
    gy_.resize(grid_.size());
  }

  [[nodiscard]] std::size_t size() const { return b_.size(); }
  [[nodiscard]] const std::vector<double>& rhs() const { return b_; }

  void apply(const double* in, double* out) {
    ++products;
    scatter(in);
    switch (kind_) {
      case Kind::normal: op_.normal(fx_.data(), gx_.data()); break;
      case Kind::sliding: op_.tangential(fx_.data(), fy_.data(), gx_.data(), gy_.data()); break;
      case Kind::rolling:
        op_.rolling_difference(fx_.data(), fy_.data(), gx_.data(), gy_.data());
        for (std::size_t i = 0; i < grid_.size(); ++i) {
          gx_[i] = -gx_[i];
          gy_[i] = -gy_[i];
        }
        break;
    }
    gather(out);
  }

  void precondition(const double* in, double* out) {
    if (kind_ == Kind::normal) {
      std::copy(in, in + size(), out);
      return;
    }
    scatter(in);
    if (kind_ == Kind::rolling) {  // dx (I - S)^-1: running sum from the leading edge (+x)
      for (int iy = 0; iy < grid_.ny; ++iy) {
        double sx = 0.0, sy = 0.0;
        for (int ix = grid_.nx - 1; ix >= 0; --ix) {
          const std::size_t i = grid_.index(ix, iy);
          sx += fx_[i];
          sy += fy_[i];
          fx_[i] = in_set_[i] ? grid_.dx * sx : 0.0;
          fy_[i] = in_set_[i] ? grid_.dx * sy : 0.0;
        }
      }
    }
    op_.tangential_inverse(fx_.data(), fy_.data(), gx_.data(), gy_.data());
    gather(out);
  }

  // ||b - K x|| / ||b||, one product not counted.
  double relative_residual(const std::vector<double>& x) {
    std::vector<double> r(size());
    apply(x.data(), r.data());
    --products;
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < size(); ++i) {
      num += (b_[i] - r[i]) * (b_[i] - r[i]);
      den += b_[i] * b_[i];
    }
    return std::sqrt(num / den);
  }

  int products = 0;

 private:
  static Grid make_grid(int n) {
    const double a = std::sqrt(kRrel * 0.4e-3);
    const double dx = 2.0 * a * 1.05 / n;
    return Grid::centred(n, n, dx, dx);
  }
  static CombinedMaterial steel_pair() {
    const Material s = Material::from_young(210.0e9, 0.28);
    return combine(s, s);
  }
  void scatter(const double* in) {
    std::fill(fx_.begin(), fx_.end(), 0.0);
    std::fill(fy_.begin(), fy_.end(), 0.0);
    for (std::size_t k = 0; k < set_.size(); ++k) {
      if (kind_ == Kind::normal) {
        fx_[set_[k]] = in[k];
      } else {
        fx_[set_[k]] = in[2 * k];
        fy_[set_[k]] = in[2 * k + 1];
      }
    }
  }
  void gather(double* out) const {
    for (std::size_t k = 0; k < set_.size(); ++k) {
      if (kind_ == Kind::normal) {
        out[k] = gx_[set_[k]];
      } else {
        out[2 * k] = gx_[set_[k]];
        out[2 * k + 1] = gy_[set_[k]];
      }
    }
  }

  Grid grid_;
  InfluenceOperator op_;
  Kind kind_;
  std::vector<std::size_t> set_;
  std::vector<bool> in_set_;
  std::vector<double> b_;
  Field fx_, fy_, gx_, gy_;
};

double norm2(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

// --- the project's GMRES (its work vectors kept across solves, as in the tangential solver) ----
std::vector<double> solve_project(MimSystem& sys, GmresWorkspace& ws) {
  std::vector<double> x(sys.size(), 0.0);
  int budget = 100000;
  gmres([&](const std::vector<double>& in, std::vector<double>& out) { sys.apply(in.data(), out.data()); },
        [&](const std::vector<double>& in, std::vector<double>& out) {
          sys.precondition(in.data(), out.data());
        },
        sys.rhs(), x, kRelTol * norm2(sys.rhs()), kRestart, budget, ws, true);
  return x;
}

// --- SUNDIALS SPGMR (right preconditioning, modified Gram-Schmidt) -----------------------------
class Spgmr {
 public:
  explicit Spgmr(MimSystem& sys) : sys_(sys) {
    if (SUNContext_Create(nullptr, &ctx_) != 0) throw std::runtime_error("SUNContext_Create");
    const auto n = static_cast<sunindextype>(sys.size());
    x_ = N_VNew_Serial(n, ctx_);
    b_ = N_VNew_Serial(n, ctx_);
    ls_ = SUNLinSol_SPGMR(x_, SUN_PREC_RIGHT, kRestart, ctx_);
    SUNLinSol_SPGMRSetGSType(ls_, SUN_MODIFIED_GS);
    SUNLinSol_SPGMRSetMaxRestarts(ls_, 1000);
    SUNLinSolSetATimes(ls_, this, &Spgmr::atimes);
    SUNLinSolSetPreconditioner(ls_, this, nullptr, &Spgmr::psolve);
    SUNLinSolInitialize(ls_);
    SUNLinSolSetup(ls_, nullptr);
    std::copy(sys.rhs().begin(), sys.rhs().end(), N_VGetArrayPointer(b_));
  }
  ~Spgmr() {
    SUNLinSolFree(ls_);
    N_VDestroy(x_);
    N_VDestroy(b_);
    SUNContext_Free(&ctx_);
  }
  Spgmr(const Spgmr&) = delete;
  Spgmr& operator=(const Spgmr&) = delete;

  std::vector<double> solve() {
    N_VConst(0.0, x_);
    SUNLinSolSetZeroGuess(ls_, SUNTRUE);
    const int flag = SUNLinSolSolve(ls_, nullptr, x_, b_, kRelTol * norm2(sys_.rhs()));
    if (flag != SUNLS_SUCCESS) throw std::runtime_error("SPGMR did not converge");
    const double* p = N_VGetArrayPointer(x_);
    return {p, p + sys_.size()};
  }

 private:
  static int atimes(void* self, N_Vector v, N_Vector z) {
    static_cast<Spgmr*>(self)->sys_.apply(N_VGetArrayPointer(v), N_VGetArrayPointer(z));
    return 0;
  }
  static int psolve(void* self, N_Vector r, N_Vector z, realtype, int) {
    static_cast<Spgmr*>(self)->sys_.precondition(N_VGetArrayPointer(r), N_VGetArrayPointer(z));
    return 0;
  }
  MimSystem& sys_;
  SUNContext ctx_ = nullptr;
  N_Vector x_ = nullptr, b_ = nullptr;
  SUNLinearSolver ls_ = nullptr;
};

// --- Eigen GMRES on the right-preconditioned operator K P (Householder Arnoldi) ----------------
class RightPreconditioned;
}  // namespace

namespace Eigen::internal {
template <>
struct traits<RightPreconditioned> : public traits<SparseMatrix<double>> {};
}  // namespace Eigen::internal

namespace {
class RightPreconditioned : public Eigen::EigenBase<RightPreconditioned> {
 public:
  using Scalar = double;
  using RealScalar = double;
  using StorageIndex = int;
  enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic, IsRowMajor = false };
  explicit RightPreconditioned(MimSystem& sys) : sys_(&sys), z_(sys.size()) {}
  [[nodiscard]] Eigen::Index rows() const { return static_cast<Eigen::Index>(sys_->size()); }
  [[nodiscard]] Eigen::Index cols() const { return rows(); }
  template <class Rhs>
  Eigen::Product<RightPreconditioned, Rhs, Eigen::AliasFreeProduct> operator*(
      const Eigen::MatrixBase<Rhs>& x) const {
    return {*this, x.derived()};
  }
  // out = K P in
  void apply(const double* in, double* out) const {
    sys_->precondition(in, z_.data());
    sys_->apply(z_.data(), out);
  }
  MimSystem& system() const { return *sys_; }

 private:
  MimSystem* sys_;
  mutable std::vector<double> z_;
};
}  // namespace

namespace Eigen::internal {
template <class Rhs>
struct generic_product_impl<RightPreconditioned, Rhs, SparseShape, DenseShape, GemvProduct>
    : generic_product_impl_base<RightPreconditioned, Rhs,
                                generic_product_impl<RightPreconditioned, Rhs>> {
  using Scalar = typename Product<RightPreconditioned, Rhs>::Scalar;
  template <class Dest>
  static void scaleAndAddTo(Dest& dst, const RightPreconditioned& lhs, const Rhs& rhs,
                            const Scalar& alpha) {
    const Eigen::VectorXd in = rhs;
    Eigen::VectorXd out(in.size());
    lhs.apply(in.data(), out.data());
    dst += alpha * out;
  }
};
}  // namespace Eigen::internal

namespace {
std::vector<double> solve_eigen(MimSystem& sys) {
  RightPreconditioned kp(sys);
  Eigen::GMRES<RightPreconditioned, Eigen::IdentityPreconditioner> solver;
  solver.compute(kp);
  solver.set_restart(kRestart);
  solver.setTolerance(kRelTol);
  solver.setMaxIterations(100000);
  const Eigen::Map<const Eigen::VectorXd> b(sys.rhs().data(),
                                           static_cast<Eigen::Index>(sys.size()));
  const Eigen::VectorXd y = solver.solve(b);
  if (solver.info() != Eigen::Success) throw std::runtime_error("Eigen GMRES did not converge");
  std::vector<double> x(sys.size());
  sys.precondition(y.data(), x.data());
  return x;
}

enum class Solver { project, sundials, eigen };

template <Solver kSolver>
void BM_Gmres(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  MimSystem sys(n, static_cast<Kind>(state.range(1)));
  GmresWorkspace workspace;
  const std::vector<double> reference = solve_project(sys, workspace);
  std::unique_ptr<Spgmr> spgmr;
  if constexpr (kSolver == Solver::sundials) spgmr = std::make_unique<Spgmr>(sys);
  std::vector<double> x;
  int products = 0;
  for (auto _ : state) {
    sys.products = 0;
    if constexpr (kSolver == Solver::project) x = solve_project(sys, workspace);
    if constexpr (kSolver == Solver::sundials) x = spgmr->solve();
    if constexpr (kSolver == Solver::eigen) x = solve_eigen(sys);
    products = sys.products;
    benchmark::DoNotOptimize(x.data());
  }
  double diff = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) diff += (x[i] - reference[i]) * (x[i] - reference[i]);
  state.counters["unknowns"] = static_cast<double>(sys.size());
  state.counters["products"] = products;
  state.counters["true_rel_res"] = sys.relative_residual(x);
  state.counters["diff_to_project"] = std::sqrt(diff) / norm2(reference);
}

void grids(benchmark::internal::Benchmark* b) {
  for (int kind : {0, 1, 2})
    for (int n : {25, 100}) b->Args({n, kind});
  b->ArgNames({"N", "system"})->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
}
BENCHMARK(BM_Gmres<Solver::project>)->Apply(grids)->Name("GmresProject");
BENCHMARK(BM_Gmres<Solver::sundials>)->Apply(grids)->Name("GmresSundialsSpgmr");
BENCHMARK(BM_Gmres<Solver::eigen>)->Apply(grids)->Name("GmresEigen");

}  // namespace

BENCHMARK_MAIN();
