#include "ferro/vehicle/ode_system.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ferro::vehicle {

std::vector<std::vector<int>> jacobian_column_groups(const std::vector<std::vector<int>>& pattern,
                                                     std::size_t n) {
  std::vector<std::vector<int>> groups;
  if (pattern.size() != n) {
    for (std::size_t j = 0; j < n; ++j) groups.push_back({static_cast<int>(j)});
    return groups;
  }
  std::vector<std::vector<char>> used;  // rows touched by each group
  std::vector<std::size_t> order(n);
  for (std::size_t j = 0; j < n; ++j) order[j] = j;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return pattern[a].size() > pattern[b].size();
  });
  for (const std::size_t j : order) {
    std::size_t g = 0;
    for (; g < groups.size(); ++g) {
      const bool clash = std::any_of(pattern[j].begin(), pattern[j].end(), [&](int i) {
        return used[g][static_cast<std::size_t>(i)] != 0;
      });
      if (!clash) break;
    }
    if (g == groups.size()) {
      groups.emplace_back();
      used.emplace_back(n, 0);
    }
    groups[g].push_back(static_cast<int>(j));
    for (int i : pattern[j]) used[g][static_cast<std::size_t>(i)] = 1;
  }
  for (std::vector<int>& group : groups) std::sort(group.begin(), group.end());
  return groups;
}

std::vector<double> numerical_jacobian(const OdeSystem& system, double t, std::span<const double> x,
                                       double rel_step, std::span<const double> scale) {
  const std::size_t n = system.size();
  std::vector<double> jac(n * n), xp(x.begin(), x.end()), fp(n), fm(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double s = scale.empty() ? 1.0 : scale[j];
    const double h = rel_step * std::max(std::abs(x[j]), s);
    xp[j] = x[j] + h;
    const int rc_plus = system.rhs(t, xp, fp);
    xp[j] = x[j] - h;
    const int rc_minus = system.rhs(t, xp, fm);
    xp[j] = x[j];
    if (rc_plus != kRhsOk || rc_minus != kRhsOk) {
      throw std::runtime_error(fmt::format(
          "numerical_jacobian: right-hand side failed (codes {}, {}) perturbing state {}", rc_plus,
          rc_minus, j));
    }
    for (std::size_t i = 0; i < n; ++i) jac[i * n + j] = (fp[i] - fm[i]) / (2.0 * h);
  }
  return jac;
}

}  // namespace ferro::vehicle
