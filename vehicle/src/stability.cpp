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
std::vector<Mode> modes_at(const LinearisationAtSpeed& family, double speed) {
  const Linearisation lin = family(speed);
  auto modes = linear_modes(*lin.system, 0.0, lin.x_eq);
  if (modes.empty())
    throw std::runtime_error(fmt::format("no non-neutral mode at V = {} m/s", speed));
  return modes;
}

Mode least_damped_at(const LinearisationAtSpeed& family, double speed) {
  const auto modes = modes_at(family, speed);
  for (const Mode& m : modes) {  // sorted by increasing damping ratio
    if (std::abs(m.damping_ratio) >= kNeutralDamping) return m;
  }
  return modes.front();  // every mode neutral
}

std::complex<double> upper(std::complex<double> l) {
  return {l.real(), std::abs(l.imag())};
}

/// Eigenvalues (upper half plane) of the modes that are neutral at every speed: within
/// kNeutralDamping of zero damping at `speed` and at `v_ref`, with the same eigenvalue (within
/// kNeutralDamping |lambda|) at both. A structural mode without damping stays put; a hunting
/// mode passing zero damping moves with the speed.
std::vector<std::complex<double>> neutral_modes(const LinearisationAtSpeed& family, double speed,
                                                double v_ref) {
  const auto at = modes_at(family, speed), ref = modes_at(family, v_ref);
  std::vector<std::complex<double>> out;
  for (const Mode& m : at) {
    if (std::abs(m.damping_ratio) >= kNeutralDamping) continue;
    const double tol = kNeutralDamping * std::abs(m.eigenvalue);
    for (const Mode& r : ref) {
      if (std::abs(upper(r.eigenvalue) - upper(m.eigenvalue)) < tol) {
        out.push_back(upper(m.eigenvalue));
        break;
      }
    }
  }
  return out;
}

/// The largest real part among the modes that are not in `neutral` [1/s]: continuous in the
/// speed (no mode has to be followed, which fails when two hunting modes, e.g. the two
/// bogies', lie close together), it changes sign where the first mode crosses.
double largest_real_part(const LinearisationAtSpeed& family, double speed,
                         const std::vector<std::complex<double>>& neutral) {
  double largest = -INFINITY;
  for (const Mode& m : modes_at(family, speed)) {
    bool is_neutral = false;
    for (const auto& n : neutral)
      is_neutral |= std::abs(upper(m.eigenvalue) - n) < kNeutralDamping * std::abs(n);
    if (!is_neutral) largest = std::max(largest, m.eigenvalue.real());
  }
  return largest;
}

LinearisationAtSpeed about(const SystemAtSpeed& factory, std::span<const double> x_eq) {
  return [&factory, x = std::vector<double>(x_eq.begin(), x_eq.end())](double v) {
    return Linearisation{factory(v), x};
  };
}
}  // namespace

std::vector<SweepPoint> damping_sweep(const LinearisationAtSpeed& family,
                                      const std::vector<double>& speeds) {
  std::vector<SweepPoint> out;
  out.reserve(speeds.size());
  for (double v : speeds) out.push_back(SweepPoint{v, least_damped_at(family, v)});
  return out;
}

std::vector<SweepPoint> damping_sweep(const SystemAtSpeed& factory,
                                      const std::vector<double>& speeds,
                                      std::span<const double> x_eq) {
  return damping_sweep(about(factory, x_eq), speeds);
}

std::optional<double> critical_speed(const SystemAtSpeed& factory, double v_min, double v_max,
                                     std::span<const double> x_eq, int scan_points,
                                     double rel_tol) {
  return critical_speed(about(factory, x_eq), v_min, v_max, scan_points, rel_tol);
}

std::optional<double> critical_speed(const LinearisationAtSpeed& family, double v_min, double v_max,
                                     int scan_points, double rel_tol) {
  if (!(v_min > 0.0) || !(v_max > v_min) || scan_points < 2) {
    throw std::invalid_argument(
        fmt::format("critical_speed: need 0 < v_min < v_max and scan_points >= 2, got {}, {}, {}",
                    v_min, v_max, scan_points));
  }
  if (least_damped_at(family, v_min).damping_ratio < 0.0) return v_min;
  double v_prev = v_min;
  for (int i = 1; i < scan_points; ++i) {
    const double v = v_min + (v_max - v_min) * i / (scan_points - 1);
    const Mode m = least_damped_at(family, v);
    if (m.damping_ratio < 0.0) {
      // Bisection on the largest real part among the modes that are not neutral at every
      // speed. The mode the scan saw may have crossed before it passed -kNeutralDamping: step
      // back to a speed where every such mode is damped.
      const double dv = (v_max - v_min) / (scan_points - 1);
      double lo = v_prev, hi = v;
      const auto neutral = neutral_modes(family, v, v_min);
      while (largest_real_part(family, lo, neutral) >= 0.0) {
        hi = lo;
        if (lo <= v_min) return v_min;
        lo = std::max(v_min, lo - dv);
      }
      while (hi - lo > rel_tol * hi) {
        const double mid = 0.5 * (lo + hi);
        (largest_real_part(family, mid, neutral) < 0.0 ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    v_prev = v;
  }
  return std::nullopt;
}

}  // namespace ferro::vehicle
