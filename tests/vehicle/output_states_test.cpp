// Output states (OdeSystem::output_states): a damped oscillator whose position drives a
// second-order low-pass that nothing depends on, integrated by the implicit SUNDIALS methods with
// the output states left out of the error test and solved by block substitution, against the
// closed-form solution of the linear system (its eigen-decomposition).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cstdio>
#include <cmath>
#include <complex>

#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/ode_system.hpp"

namespace ferro::vehicle {
namespace {

// x'' + 2 z w x' + w^2 x = 0; the filter y'' + (wf/q) y' + wf^2 y = wf^2 x (states 2, 3).
constexpr double kW = 2.0 * M_PI * 3.0, kZ = 0.05, kWf = 2.0 * M_PI * 10.0, kQ = 0.7071;

Eigen::Matrix4d system_matrix() {
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  a(0, 1) = 1.0;
  a(1, 0) = -kW * kW;
  a(1, 1) = -2.0 * kZ * kW;
  a(2, 3) = 1.0;
  a(3, 0) = kWf * kWf;
  a(3, 2) = -kWf * kWf;
  a(3, 3) = -kWf / kQ;
  return a;
}

class FilteredOscillator final : public OdeSystem {
 public:
  explicit FilteredOscillator(bool declare) : declare_(declare) {}
  [[nodiscard]] std::size_t size() const override { return 4; }
  int rhs(double, std::span<const double> x, std::span<double> xdot) const override {
    const Eigen::Matrix4d a = system_matrix();
    for (int i = 0; i < 4; ++i) {
      xdot[static_cast<std::size_t>(i)] = 0.0;
      for (int j = 0; j < 4; ++j) xdot[static_cast<std::size_t>(i)] += a(i, j) * x[static_cast<std::size_t>(j)];
    }
    return kRhsOk;
  }
  [[nodiscard]] std::vector<SignalInfo> state_info() const override {
    return {{"x", "m", ""}, {"x_dot", "m/s", ""}, {"y", "m", ""}, {"y_dot", "m/s", ""}};
  }
  [[nodiscard]] std::vector<std::size_t> output_states() const override {
    return declare_ ? std::vector<std::size_t>{2, 3} : std::vector<std::size_t>{};
  }
  /// Column j: the rates that depend on state j (the filter reads x, nothing reads the filter).
  [[nodiscard]] std::vector<std::vector<int>> jacobian_pattern() const override {
    return {{1, 3}, {0, 1}, {3}, {2, 3}};
  }

 private:
  bool declare_;
};

Eigen::Vector4d exact(double t, const Eigen::Vector4d& x0) {
  const Eigen::EigenSolver<Eigen::Matrix4d> es(system_matrix());
  const Eigen::Matrix4cd v = es.eigenvectors();
  const Eigen::Vector4cd lambda = es.eigenvalues();
  const Eigen::Vector4cd c = v.fullPivLu().solve(x0.cast<std::complex<double>>());
  Eigen::Vector4cd x = Eigen::Vector4cd::Zero();
  for (int k = 0; k < 4; ++k) x += c[k] * std::exp(lambda[k] * t) * v.col(k);
  return x.real();
}

TEST(OutputStates, ImplicitMethodsFollowTheClosedFormWithOutputsSolvedBySubstitution) {
  const Eigen::Vector4d x0(0.01, 0.0, 0.01, 0.0);  // the filter starts at its input's steady state
  const auto times = output_grid(0.0, 2.0, 0.01);
  for (const std::string method : {"cvode_bdf", "arkode_dirk"}) {
    for (bool declare : {false, true}) {
      IntegratorSettings s;
      s.method = method;
      s.rtol = 1e-8;
      s.atol = 1e-12;
      const FilteredOscillator sys(declare);
      double worst_x = 0.0, worst_y = 0.0;
      auto r = make_integrator(s)->integrate(
          sys, std::vector<double>{x0[0], x0[1], x0[2], x0[3]}, times,
          [&](double t, std::span<const double> x) {
            const Eigen::Vector4d e = exact(t, x0);
            worst_x = std::max(worst_x, std::abs(x[0] - e[0]));
            worst_y = std::max(worst_y, std::abs(x[2] - e[2]));
            return true;
          });
      ASSERT_EQ(r.status, IntegrationResult::Status::kCompleted) << method << " " << r.message;
      std::printf("%s, outputs %s: largest error x %.2e m, y %.2e m\n", method.c_str(),
                  declare ? "declared" : "plain", worst_x, worst_y);
      // rtol 1e-8 on a 1 cm amplitude: 1e-8 m allows the global error's growth over 2 s.
      EXPECT_LT(worst_x, 1e-8) << method;
      // Out of the error test the filter is only as accurate as the steps the oscillator
      // chooses: the filter's slower dynamics keep it within 1e-7 m (1e-5 of the amplitude).
      EXPECT_LT(worst_y, declare ? 1e-7 : 1e-8) << method;
    }
  }
}

// bdf2 at a fixed step: with the outputs declared, the Newton matrix is solved by blocks (the
// oscillator's, then the filter's from it) instead of whole. Both are the same BDF2 solution up
// to the Newton iteration's tolerance, against which the two are compared; both follow the
// closed form to BDF2's global error at this step.
TEST(OutputStates, Bdf2SolvesTheOutputsByBlocksAsTheWholeMatrixDoes) {
  const Eigen::Vector4d x0(0.01, 0.0, 0.01, 0.0);
  const auto times = output_grid(0.0, 2.0, 0.01);
  std::vector<std::vector<double>> runs;
  for (bool declare : {false, true}) {
    IntegratorSettings s;
    s.method = "bdf2";
    s.fixed_step = 1e-3;
    s.rtol = 1e-8;
    s.atol = 1e-12;
    const FilteredOscillator sys(declare);
    std::vector<double> ys;
    double worst = 0.0;
    auto r = make_integrator(s)->integrate(
        sys, std::vector<double>{x0[0], x0[1], x0[2], x0[3]}, times,
        [&](double t, std::span<const double> x) {
          ys.push_back(x[2]);
          worst = std::max(worst, std::abs(x[2] - exact(t, x0)[2]));
          return true;
        });
    ASSERT_EQ(r.status, IntegrationResult::Status::kCompleted) << r.message;
    // BDF2's phase error on the oscillator: its frequency is low by dw = w (w h)^2 / 3, so the
    // error A0 exp(-z w t) dw t peaks at t = 1 / (z w) at A0 dw / (e z w) = 8.7e-6 m; the filter
    // passes 3 Hz at a gain of 1.0. Bound: that peak plus 25 %.
    const double dw = kW * std::pow(kW * s.fixed_step, 2) / 3.0;
    EXPECT_LT(worst, 1.25 * x0[0] * dw / (std::exp(1.0) * kZ * kW)) << (declare ? "declared" : "plain");
    runs.push_back(ys);
  }
  double diff = 0.0;
  for (std::size_t k = 0; k < runs[0].size(); ++k) diff = std::max(diff, std::abs(runs[0][k] - runs[1][k]));
  std::printf("bdf2: block against whole Newton matrix: largest difference %.2e m\n", diff);
  // The Newton iterations of the two stop within rtol 1e-8 of the 1 cm state (on this linear
  // system both converge in one iteration, to the same rounding).
  EXPECT_LT(diff, 1e-10);
}


// A chain of masses between two walls, each coupled to its neighbours by a spring and a damper,
// states body by body (x_i, x_i'), the last mass read by the filter above. With its Jacobian
// pattern declared, bdf2 factors the Newton matrix as a sparse matrix of that pattern; without
// it, dense.
class MassChain final : public OdeSystem {
 public:
  static constexpr int kMasses = 6;
  static constexpr double kK = 4.0e4, kC = 20.0, kM = 10.0;  // N/m, N s/m, kg
  explicit MassChain(bool declare) : declare_(declare) {}
  [[nodiscard]] std::size_t size() const override { return 2 * kMasses + 2; }
  int rhs(double, std::span<const double> x, std::span<double> xdot) const override {
    const auto pos = [&](int i) { return i < 0 || i >= kMasses ? 0.0 : x[static_cast<std::size_t>(2 * i)]; };
    const auto vel = [&](int i) { return i < 0 || i >= kMasses ? 0.0 : x[static_cast<std::size_t>(2 * i + 1)]; };
    for (int i = 0; i < kMasses; ++i) {
      const double force = kK * (pos(i - 1) - 2.0 * pos(i) + pos(i + 1)) +
                           kC * (vel(i - 1) - 2.0 * vel(i) + vel(i + 1));
      xdot[static_cast<std::size_t>(2 * i)] = vel(i);
      xdot[static_cast<std::size_t>(2 * i + 1)] = force / kM;
    }
    const std::size_t f = 2 * kMasses;
    xdot[f] = x[f + 1];
    xdot[f + 1] = kWf * kWf * (pos(kMasses - 1) - x[f]) - kWf / kQ * x[f + 1];
    return kRhsOk;
  }
  [[nodiscard]] std::vector<SignalInfo> state_info() const override {
    return std::vector<SignalInfo>(size(), SignalInfo{"s", "-", ""});
  }
  [[nodiscard]] std::vector<std::size_t> output_states() const override {
    return {2 * kMasses, 2 * kMasses + 1};
  }
  [[nodiscard]] std::vector<std::vector<int>> jacobian_pattern() const override {
    if (!declare_) return {};
    std::vector<std::vector<int>> p(size());
    for (int i = 0; i < kMasses; ++i) {
      for (int k = std::max(0, i - 1); k <= std::min(kMasses - 1, i + 1); ++k) {
        p[static_cast<std::size_t>(2 * i)].push_back(2 * k + 1);  // the forces on i and its neighbours
        p[static_cast<std::size_t>(2 * i + 1)].push_back(2 * k + 1);
      }
      p[static_cast<std::size_t>(2 * i + 1)].push_back(2 * i);  // x_i' = v_i
    }
    p[2 * kMasses - 2].push_back(2 * kMasses + 1);  // the filter reads the last mass
    p[2 * kMasses] = {2 * kMasses + 1};
    p[2 * kMasses + 1] = {2 * kMasses, 2 * kMasses + 1};
    return p;
  }

 private:
  bool declare_;
};

TEST(OutputStates, Bdf2SparseNewtonMatrixAnswersAsTheDenseOne) {
  const auto times = output_grid(0.0, 0.5, 0.005);
  std::vector<std::vector<double>> runs;
  for (bool declare : {true, false}) {
    IntegratorSettings s;
    s.method = "bdf2";
    s.fixed_step = 1e-4;
    s.rtol = 1e-8;
    s.atol = 1e-12;
    const MassChain sys(declare);
    std::vector<double> x0(sys.size(), 0.0);
    x0[0] = 0.01;  // the first mass displaced by 1 cm, the rest at rest
    std::vector<double> xs;
    auto r = make_integrator(s)->integrate(sys, x0, times, [&](double, std::span<const double> x) {
      xs.insert(xs.end(), x.begin(), x.end());
      return true;
    });
    ASSERT_EQ(r.status, IntegrationResult::Status::kCompleted) << r.message;
    runs.push_back(xs);
  }
  ASSERT_EQ(runs[0].size(), runs[1].size());
  double diff = 0.0, peak = 0.0;
  for (std::size_t k = 0; k < runs[0].size(); k += 1) {
    if (k % MassChain{true}.size() % 2 != 0) continue;  // positions and the filter's output
    diff = std::max(diff, std::abs(runs[0][k] - runs[1][k]));
    peak = std::max(peak, std::abs(runs[1][k]));
  }
  std::printf("bdf2: sparse against dense Newton matrix: largest difference %.2e m (peak %.3g m)\n",
              diff, peak);
  EXPECT_GT(peak, 1e-3);  // the motion reached the chain
  // On a linear system the Newton iterations of both stop within rtol 1e-8 of the solution of
  // the same step equation (they differ in the order of the LU's operations and, the pattern
  // grouping the Jacobian's columns, in its rounding): 1e-8 of the 1 cm displacement.
  EXPECT_LT(diff, 1e-10);
}

}  // namespace
}  // namespace ferro::vehicle
