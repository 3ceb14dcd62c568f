// Output states (OdeSystem::output_states): a damped oscillator whose position drives a
// second-order low-pass that nothing depends on, integrated by the implicit SUNDIALS methods with
// the output states left out of the error test and solved by block substitution, against the
// closed-form solution of the linear system (its eigen-decomposition).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
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

}  // namespace
}  // namespace ferro::vehicle
