#include "ferro/vehicle/stability.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ferro::vehicle {

std::vector<Mode> linear_modes(const OdeSystem& system, double t, std::span<const double> x_eq) {
  const auto n = static_cast<Eigen::Index>(system.size());
  const auto rows = numerical_jacobian(system, t, x_eq);
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(
      rows.data(), n, n);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(J, /*computeEigenvectors=*/false);
  if (solver.info() != Eigen::Success) {
    throw std::runtime_error("linear_modes: eigenvalue computation did not converge");
  }
  std::vector<Mode> modes;
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::complex<double> lambda = solver.eigenvalues()[i];
    const double mag = std::abs(lambda);
    if (mag < 1e-9) continue;
    modes.push_back(
        Mode{lambda, -lambda.real() / mag, std::abs(lambda.imag()) / (2.0 * std::numbers::pi)});
  }
  std::sort(modes.begin(), modes.end(),
            [](const Mode& a, const Mode& b) { return a.damping_ratio < b.damping_ratio; });
  return modes;
}

namespace {
Mode least_damped_at(const SystemAtSpeed& factory, double speed, std::span<const double> x_eq) {
  const auto system = factory(speed);
  const auto modes = linear_modes(*system, 0.0, x_eq);
  if (modes.empty())
    throw std::runtime_error(fmt::format("no non-neutral mode at V = {} m/s", speed));
  return modes.front();
}
}  // namespace

std::vector<SweepPoint> damping_sweep(const SystemAtSpeed& factory,
                                      const std::vector<double>& speeds,
                                      std::span<const double> x_eq) {
  std::vector<SweepPoint> out;
  out.reserve(speeds.size());
  for (double v : speeds) out.push_back(SweepPoint{v, least_damped_at(factory, v, x_eq)});
  return out;
}

std::optional<double> critical_speed(const SystemAtSpeed& factory, double v_min, double v_max,
                                     std::span<const double> x_eq, int scan_points,
                                     double rel_tol) {
  if (!(v_min > 0.0) || !(v_max > v_min) || scan_points < 2) {
    throw std::invalid_argument(
        fmt::format("critical_speed: need 0 < v_min < v_max and scan_points >= 2, got {}, {}, {}",
                    v_min, v_max, scan_points));
  }
  auto zeta = [&](double v) { return least_damped_at(factory, v, x_eq).damping_ratio; };
  double v_prev = v_min, z_prev = zeta(v_min);
  if (z_prev <= 0.0) return v_min;
  for (int i = 1; i < scan_points; ++i) {
    const double v = v_min + (v_max - v_min) * i / (scan_points - 1);
    const double z = zeta(v);
    if (z <= 0.0) {
      double lo = v_prev, hi = v;
      while (hi - lo > rel_tol * hi) {
        const double mid = 0.5 * (lo + hi);
        (zeta(mid) > 0.0 ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    v_prev = v;
    z_prev = z;
  }
  return std::nullopt;
}

}  // namespace ferro::vehicle
