// Normal contact by the Polonsky-Keer constrained conjugate gradient method, FFT products.
//
// References: Toumi (2016) eqs. (77)-(87); Polonsky & Keer, Wear 231 (1999) 206-219.
// Known deviations: see normal_solver.hpp (algorithm differs from the thesis's LU/CG active-set
// loop, same discrete equations and solution).

#include "ferro/contact/mim/normal_solver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ferro::contact::mim {

void NormalSolverOptions::validate(const std::string& where) const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw std::invalid_argument(
        fmt::format("{}.tolerance: must lie in (0, 1), got {}", where, tolerance));
  }
  if (max_iterations < 1) {
    throw std::invalid_argument(
        fmt::format("{}.max_iterations: must be >= 1, got {}", where, max_iterations));
  }
}

namespace {

NormalGridSolution solve(ComplianceOperator& op, const Field& gap, double target,
                         bool force_control, const NormalSolverOptions& options) {
  options.validate();
  const Grid& grid = op.grid();
  const std::size_t n = grid.size();
  if (gap.size() != n) {
    throw std::invalid_argument(fmt::format(
        "gap: has {} values, the grid has {} x {} = {} elements", gap.size(), grid.nx, grid.ny, n));
  }
  for (double z : gap) {
    if (!std::isfinite(z)) throw std::invalid_argument("gap: contains a non-finite value");
  }
  const double area = grid.element_area();

  NormalGridSolution out;
  Field& p = out.pressure;
  p.assign(n, 0.0);
  Field u(n), g(n), t(n, 0.0), r(n);

  // Start: pressure proportional to the initial interpenetration (uniform if none).
  const double zmin = *std::min_element(gap.begin(), gap.end());
  if (force_control) {
    const double zref = zmin + 0.25 * (*std::max_element(gap.begin(), gap.end()) - zmin);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      p[i] = std::max(zref - gap[i], 0.0);
      sum += p[i];
    }
    if (!(sum > 0.0)) std::fill(p.begin(), p.end(), 1.0), sum = static_cast<double>(n);
    const double scale = target / (area * sum);
    for (double& v : p) v *= scale;
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      p[i] = std::max(target - gap[i], 0.0) / (op.normal_self() * std::max(grid.nx, grid.ny));
    }
  }

  double g_old = 1.0;
  bool conjugate = false;
  double approach = target;
  for (int it = 0; it < options.max_iterations; ++it) {
    op.normal(p.data(), u.data());
    // Gap on the current contact set; under load control the approach is the mean of u + z
    // over that set (Polonsky-Keer's mean-gap removal enforces sum p = F_n).
    std::size_t nc = 0;
    double mean = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      g[i] = u[i] + gap[i];
      if (p[i] > 0.0) {
        mean += g[i];
        ++nc;
      }
    }
    if (force_control) {
      approach = nc > 0 ? mean / static_cast<double>(nc) : zmin;
    }
    double umax = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      g[i] -= approach;
      umax = std::max(umax, std::abs(u[i]));
    }

    // Complementarity residuals of the current iterate.
    double gap_res = 0.0, pen_res = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0.0)
        gap_res = std::max(gap_res, std::abs(g[i]));
      else
        pen_res = std::max(pen_res, -g[i]);
    }
    const double scale = umax > 0.0 ? umax : 1.0;
    out.gap_residual = gap_res / scale;
    out.penetration_residual = pen_res / scale;
    out.iterations = it;
    if (umax == 0.0 && pen_res == 0.0) {  // separated bodies: no load, nothing to solve
      out.gap_residual = 0.0;
      out.penetration_residual = 0.0;
      out.converged = true;
      break;
    }
    if (umax > 0.0 && out.gap_residual <= options.tolerance &&
        out.penetration_residual <= options.tolerance) {
      out.converged = true;
      break;
    }

    // Conjugate direction on the contact set.
    double gnorm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0.0) gnorm += g[i] * g[i];
    }
    const double beta = conjugate ? gnorm / g_old : 0.0;
    for (std::size_t i = 0; i < n; ++i) t[i] = p[i] > 0.0 ? g[i] + beta * t[i] : 0.0;
    g_old = gnorm;

    op.normal(t.data(), r.data());
    if (force_control) {
      double rmean = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        if (p[i] > 0.0) rmean += r[i];
      }
      rmean = nc > 0 ? rmean / static_cast<double>(nc) : 0.0;
      for (double& v : r) v -= rmean;
    }
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0.0) {
        num += g[i] * t[i];
        den += r[i] * t[i];
      }
    }
    const double step = den != 0.0 ? num / den : 0.0;

    // Update, project on p >= 0, re-activate penetrating elements.
    bool overlap = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (p[i] > 0.0)
        p[i] = std::max(p[i] - step * t[i], 0.0);
      else if (g[i] < 0.0) {
        p[i] = -step * g[i];
        if (p[i] < 0.0) p[i] = 0.0;
        overlap = true;
      }
    }
    conjugate = !overlap;
    if (force_control) {
      double sum = 0.0;
      for (double v : p) sum += v;
      if (sum > 0.0) {
        const double s = target / (area * sum);
        for (double& v : p) v *= s;
      }
    }
  }

  out.deformed_gap = g;
  out.approach = approach;
  double sum = 0.0;
  int nc = 0;
  for (double v : p) {
    sum += v;
    if (v > 0.0) ++nc;
  }
  out.normal_force = sum * area;
  out.contact_elements = nc;
  for (int iy = 0; iy < grid.ny; ++iy) {
    for (int ix = 0; ix < grid.nx; ++ix) {
      const bool edge = ix == 0 || iy == 0 || ix == grid.nx - 1 || iy == grid.ny - 1;
      if (edge && p[grid.index(ix, iy)] > 0.0) ++out.boundary_contact_elements;
    }
  }
  return out;
}

}  // namespace

NormalGridSolution solve_normal_approach(ComplianceOperator& op, const Field& gap, double approach,
                                         const NormalSolverOptions& options) {
  if (!std::isfinite(approach)) {
    throw std::invalid_argument(fmt::format("approach: must be finite (m), got {}", approach));
  }
  return solve(op, gap, approach, false, options);
}

NormalGridSolution solve_normal_force(ComplianceOperator& op, const Field& gap, double normal_force,
                                      const NormalSolverOptions& options) {
  if (!(normal_force > 0.0) || !std::isfinite(normal_force)) {
    throw std::invalid_argument(
        fmt::format("normal_force: must be finite and > 0 N, got {}", normal_force));
  }
  return solve(op, gap, normal_force, true, options);
}

}  // namespace ferro::contact::mim
