// Sliding and steady-rolling tangential problems: active stick/slip sets, GMRES with FFT
// influence products on the stick set.
//
// References: Toumi (2016) eqs. (97)-(107), (111)-(123); Saad & Schultz, SIAM J. Sci. Stat.
// Comput. 7 (1986) (GMRES); Kalker (1990) ch. 5 for the steady-rolling discretisation.
// Known deviations: see tangential_solver.hpp.

#include "ferro/contact/mim/tangential_solver.hpp"

#include "ferro/contact/mim/gmres.hpp"

#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace ferro::contact::mim {

void SlidingInput::validate(const std::string& where) const {
  if (!std::isfinite(shift_x)) throw std::invalid_argument(where + ".shift_x: must be finite (m)");
  if (!std::isfinite(shift_y)) throw std::invalid_argument(where + ".shift_y: must be finite (m)");
  if (!(friction >= 0.0) || !std::isfinite(friction)) {
    throw std::invalid_argument(
        fmt::format("{}.friction: must be finite and >= 0, got {}", where, friction));
  }
}

void RollingInput::validate(const std::string& where) const {
  if (!std::isfinite(creepage_x))
    throw std::invalid_argument(where + ".creepage_x: must be finite");
  if (!std::isfinite(creepage_y))
    throw std::invalid_argument(where + ".creepage_y: must be finite");
  if (!std::isfinite(spin)) throw std::invalid_argument(where + ".spin: must be finite (1/m)");
  if (!(friction >= 0.0) || !std::isfinite(friction)) {
    throw std::invalid_argument(
        fmt::format("{}.friction: must be finite and >= 0, got {}", where, friction));
  }
}

void TangentialSolverOptions::validate(const std::string& where) const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw std::invalid_argument(
        fmt::format("{}.tolerance: must lie in (0, 1), got {}", where, tolerance));
  }
  if (max_outer_iterations < 1 || max_matvecs < 1 || gmres_restart < 2) {
    throw std::invalid_argument(
        where + ": max_outer_iterations, max_matvecs >= 1 and gmres_restart >= 2 required");
  }
  if (!(newton_forcing > 0.0 && newton_forcing < 1.0) ||
      !(linear_factor > 0.0 && linear_factor <= 1.0)) {
    throw std::invalid_argument(fmt::format(
        "{}.newton_forcing must lie in (0, 1) and linear_factor in (0, 1], got {} and {}", where,
        newton_forcing, linear_factor));
  }
}

namespace {

using Vec = std::vector<double>;
using detail::norm;

// The problem v = M tau + q with M = A^tt (sliding) or minus the x-derivative of the
// displacement (rolling). Rolling: the operator's first-order difference D u_i = (u_{i+1} -
// u_i) / h (eq. 113) is combined into the second-order upwind (leading-edge side) difference
// du/dx(x_i) = (-3 u_i + 4 u_{i+1} - u_{i+2}) / (2h) = 1.5 D u_i - 0.5 D u_{i+1}, so that the
// derivative and the rigid slip are both taken at the element centre to O(h^2) (the first-order
// difference is centred at x_i + h/2 and leaves an O(h) error in the spin term). The last column
// (x + 2h outside the grid, in the margin around the patch) keeps the first-order difference.
class Problem {
 public:
  Problem(ComplianceOperator& op, bool rolling)
      : op_(op), rolling_(rolling), n_(op.grid().size()), nx_(op.grid().nx), ny_(op.grid().ny) {}
  // Full-grid product (vx, vy) = M (tx, ty).
  void apply(const double* tx, const double* ty, double* vx, double* vy) {
    ++matvecs;
    if (rolling_) {
      op_.rolling_difference(tx, ty, vx, vy);
      for (int iy = 0; iy < ny_; ++iy) {
        double* rx = vx + static_cast<std::size_t>(iy) * nx_;
        double* ry = vy + static_cast<std::size_t>(iy) * nx_;
        for (int ix = 0; ix + 1 < nx_; ++ix) {  // ascending: D_{i+1} is still unmodified
          rx[ix] = -(1.5 * rx[ix] - 0.5 * rx[ix + 1]);
          ry[ix] = -(1.5 * ry[ix] - 0.5 * ry[ix + 1]);
        }
        rx[nx_ - 1] = -rx[nx_ - 1];
        ry[nx_ - 1] = -ry[nx_ - 1];
      }
    } else {
      op_.tangential(tx, ty, vx, vy);
    }
  }
  [[nodiscard]] bool rolling() const { return rolling_; }
  int matvecs = 0;

 private:
  ComplianceOperator& op_;
  bool rolling_;
  std::size_t n_;
  int nx_, ny_;
};

using RigidSlip = std::function<void(const Grid&, Field&, Field&)>;

// Minimum elements per side for a grid to be solved first on its coarsened grid.
constexpr int kNestedMinElements = 24;

TangentialGridSolution solve(ComplianceOperator& op, const Field& pressure, double friction,
                             const RigidSlip& rigid_slip, bool rolling,
                             const TangentialSolverOptions& options, GmresWorkspace& workspace) {
  options.validate();
  const Grid& grid = op.grid();
  const std::size_t n = grid.size();
  if (pressure.size() != n) {
    throw std::invalid_argument(
        fmt::format("pressure: has {} values, the grid has {}", pressure.size(), n));
  }
  Field qx(n), qy(n);
  rigid_slip(grid, qx, qy);
  if (friction == 0.0) {
    // Frictionless contact: no traction, so no elastic tangential displacement; every loaded
    // element slips with the rigid slip.
    TangentialGridSolution out;
    out.traction_x.assign(n, 0.0);
    out.traction_y.assign(n, 0.0);
    out.slip_x.assign(n, 0.0);
    out.slip_y.assign(n, 0.0);
    out.state.assign(n, ElementState::exterior);
    for (std::size_t i = 0; i < n; ++i) {
      if (!(pressure[i] > 0.0)) continue;
      out.state[i] = ElementState::slip;
      out.slip_x[i] = qx[i];
      out.slip_y[i] = qy[i];
      ++out.slip_elements;
    }
    out.stick_residual = out.direction_residual = out.coulomb_residual = 0.0;
    out.converged = true;
    return out;
  }
  Problem pb(op, rolling);

  // Nested iteration: solve on the grid coarsened by two (pressure averaged over the four
  // children, same force) and start from its tractions and stick/slip sets.
  TangentialGridSolution start;
  const bool nested = options.nested && std::min(grid.nx, grid.ny) >= kNestedMinElements;
  if (nested) {
    ComplianceOperator& cop = op.coarse();
    const Grid& cg = cop.grid();
    Field cp(cg.size(), 0.0);
    const int fy_per = grid.ny > 1 ? 2 : 1;
    for (int iy = 0; iy < grid.ny; ++iy)
      for (int ix = 0; ix < grid.nx; ++ix)
        cp[cg.index(ix / 2, iy / fy_per)] += pressure[grid.index(ix, iy)] / (2.0 * fy_per);
    TangentialSolverOptions copt = options;
    start = solve(cop, cp, friction, rigid_slip, rolling, copt, workspace);
    pb.matvecs += start.matvecs;
  }

  TangentialGridSolution out;
  out.traction_x.assign(n, 0.0);
  out.traction_y.assign(n, 0.0);
  out.slip_x.assign(n, 0.0);
  out.slip_y.assign(n, 0.0);
  out.state.assign(n, ElementState::exterior);
  Field& tx = out.traction_x;
  Field& ty = out.traction_y;
  Field bound(n, 0.0);
  double vscale = 0.0, pmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (pressure[i] > 0.0) {
      out.state[i] = ElementState::stick;
      bound[i] = friction * pressure[i];
      vscale = std::max(vscale, std::hypot(qx[i], qy[i]));
      pmax = std::max(pmax, pressure[i]);
    }
  }
  auto finish = [&]() {
    const double area = grid.element_area();
    out.force_x = out.force_y = out.moment_z = 0.0;
    out.stick_elements = out.slip_elements = 0;
    for (int iy = 0; iy < grid.ny; ++iy)
      for (int ix = 0; ix < grid.nx; ++ix) {
        const std::size_t i = grid.index(ix, iy);
        out.force_x += tx[i] * area;
        out.force_y += ty[i] * area;
        out.moment_z += (grid.x(ix) * ty[i] - grid.y(iy) * tx[i]) * area;
        if (out.state[i] == ElementState::stick) ++out.stick_elements;
        if (out.state[i] == ElementState::slip) ++out.slip_elements;
      }
    out.matvecs = pb.matvecs;
  };
  if (vscale == 0.0 || pmax == 0.0) {  // no patch or no rigid slip: zero tractions
    out.stick_residual = out.direction_residual = 0.0;
    out.coulomb_residual = pmax > 0.0 ? -1.0 : 0.0;
    out.converged = true;
    finish();
    return out;
  }

  Field fx(n), fy(n), vx(n, 0.0), vy(n, 0.0);
  Field ex(n, 0.0), ey(n, 0.0);  // slip direction e = tau / |tau| of slip elements
  Field vnorm(n, 0.0);           // |v| of slip elements at the linearisation point
  if (nested) {
    const Grid& cg = op.coarse().grid();
    const int fy_per = grid.ny > 1 ? 2 : 1;
    for (int iy = 0; iy < grid.ny; ++iy)
      for (int ix = 0; ix < grid.nx; ++ix) {
        const std::size_t i = grid.index(ix, iy);
        if (out.state[i] == ElementState::exterior) continue;
        const std::size_t c = cg.index(ix / 2, iy / fy_per);
        tx[i] = start.traction_x[c];
        ty[i] = start.traction_y[c];
        const double t = std::hypot(tx[i], ty[i]);
        if ((start.state[c] == ElementState::slip || t > bound[i]) && t > 0.0) {
          out.state[i] = ElementState::slip;
          ex[i] = tx[i] / t;
          ey[i] = ty[i] / t;
          tx[i] = bound[i] * ex[i];
          ty[i] = bound[i] * ey[i];
          vnorm[i] = std::hypot(start.slip_x[c], start.slip_y[c]);
        }
      }
  }
  std::vector<std::size_t> active;
  std::vector<std::size_t> offset(n, 0);
  // The Krylov basis is the caller's (TangentialWorkspace): nested solves finish before the
  // parent's first GMRES call, so they share it.
  double inner_factor = options.linear_factor;
  int last_changes = static_cast<int>(n);  // first step: sets unknown, inexact
  // Set changes need a violation above a tenth of the tolerance: elements exactly on the
  // stick/slip boundary (|tau| = mu p and w = 0 both hold to round-off) must not cycle.
  const double hysteresis = 0.1 * options.tolerance;
  double previous_dir_res = std::numeric_limits<double>::infinity();
  int budget = options.max_matvecs;
  const double h = grid.dx;
  // Diagonal of M: A^xx_ii (sliding) or (A^xx(0) - A^xx(h)) / h (rolling).
  const double m_diag = rolling ? op.rolling_self() : op.tangential_self_x();
  const bool fft_preconditioner =
      n >= static_cast<std::size_t>(std::max(0, options.fft_preconditioner_min_elements));

  for (int outer = 0; outer < options.max_outer_iterations && budget > 0; ++outer) {
    out.outer_iterations = outer + 1;
    // Unknowns: (tau_x, tau_y) per stick element; per slip element the component s of
    // tau = mu p e + s t across the current direction e (t = e rotated by +90 deg).
    active.clear();
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (out.state[i] == ElementState::exterior) continue;
      active.push_back(i);
      offset[i] = m;
      m += out.state[i] == ElementState::stick ? 2 : 1;
    }
    auto to_field = [&](const Vec& in, Field& gx, Field& gy) {
      std::fill(gx.begin(), gx.end(), 0.0);
      std::fill(gy.begin(), gy.end(), 0.0);
      for (std::size_t i : active) {
        const std::size_t k = offset[i];
        if (out.state[i] == ElementState::stick) {
          gx[i] = in[k];
          gy[i] = in[k + 1];
        } else {
          gx[i] = -ey[i] * in[k];
          gy[i] = ex[i] * in[k];
        }
      }
    };
    auto from_field = [&](const Field& gx, const Field& gy, Vec& res) {
      for (std::size_t i : active) {
        const std::size_t k = offset[i];
        if (out.state[i] == ElementState::stick) {
          res[k] = gx[i];
          res[k + 1] = gy[i];
        } else {
          res[k] = -ey[i] * gx[i] + ex[i] * gy[i];
        }
      }
    };
    // Linearised equations: stick rows (M tau)_i = -q_i (w = 0, eqs. 104, 121); slip rows
    // t.(M tau + q)_i + |v_i| / (mu p_i) s_i = 0, the Newton linearisation of
    // tau_i = -mu p_i v_i / |v_i| (eqs. 99, 116) with |tau_i| = mu p_i held.
    Field mx(n), my(n);
    auto matvec = [&](const Vec& in, Vec& res) {
      to_field(in, fx, fy);
      pb.apply(fx.data(), fy.data(), mx.data(), my.data());
      from_field(mx, my, res);
      for (std::size_t i : active) {
        if (out.state[i] == ElementState::slip)
          res[offset[i]] += vnorm[i] / bound[i] * in[offset[i]];
      }
    };
    // Right preconditioner P ~ M^-1 on the stick rows: sliding C^-1, rolling h C^-1 (I - S)^-1,
    // with (I - S)^-1 the exact inverse of the x-difference (running sum from the leading edge
    // at +x) and C^-1 the FFT inverse of the circulant extension of A^tt
    // (InfluenceOperator::tangential_inverse); slip rows: inverse of their diagonal.
    auto precond = [&](const Vec& in, Vec& res) {
      // Stick rows: field of their residuals (zero elsewhere).
      std::fill(fx.begin(), fx.end(), 0.0);
      std::fill(fy.begin(), fy.end(), 0.0);
      for (std::size_t i : active) {
        if (out.state[i] == ElementState::stick) {
          fx[i] = in[offset[i]];
          fy[i] = in[offset[i] + 1];
        }
      }
      if (rolling) {  // (I - S)^-1 h: running sum from the leading edge, kept on the stick set
        for (int iy = 0; iy < grid.ny; ++iy) {
          double sx = 0.0, sy = 0.0;
          for (int ix = grid.nx - 1; ix >= 0; --ix) {
            const std::size_t i = grid.index(ix, iy);
            sx += fx[i];
            sy += fy[i];
            const bool keep = out.state[i] == ElementState::stick;
            fx[i] = keep ? h * sx : 0.0;
            fy[i] = keep ? h * sy : 0.0;
          }
        }
      }
      if (fft_preconditioner) {
        op.tangential_inverse(fx.data(), fy.data(), mx.data(), my.data());
      } else {
        const double inv_diag = 1.0 / op.tangential_self_x();
        for (std::size_t i = 0; i < n; ++i) {
          mx[i] = inv_diag * fx[i];
          my[i] = inv_diag * fy[i];
        }
      }
      for (std::size_t i : active) {
        const std::size_t k = offset[i];
        if (out.state[i] == ElementState::stick) {
          res[k] = mx[i];
          res[k + 1] = my[i];
        } else {  // slip rows: inverse of their diagonal (M_ii + |v_i| / mu p_i)
          res[k] = in[k] / (m_diag + vnorm[i] / bound[i]);
        }
      }
    };

    // Newton step as a correction of the current tractions: the right-hand side is the residual
    // of the current iterate, b = -(M tau + q) on the rows (stick: w; slip: its component across
    // e), so GMRES starts from zero without a product of its own.
    pb.apply(tx.data(), ty.data(), mx.data(), my.data());
    --budget;
    Field rx(n), ry(n);
    for (std::size_t i = 0; i < n; ++i) {
      rx[i] = -(qx[i] + mx[i]);
      ry[i] = -(qy[i] + my[i]);
    }
    Vec b(m), x(m, 0.0), bq(m);
    from_field(rx, ry, b);
    from_field(qx, qy, bq);  // rigid-slip scale of the rows, for the inexact steps
    // Linear tolerance: RMS stick-velocity error below the requested max-norm tolerance once the
    // sets have settled; while sets still change, an inexact Newton step (1e-3 relative) suffices.
    const double final_target =
        inner_factor * options.tolerance * vscale * std::sqrt(static_cast<double>(m));
    // Few set changes left: solve this Newton step to the final tolerance.
    const bool tight = last_changes <= static_cast<int>(0.001 * static_cast<double>(m));
    const double target =
        tight ? final_target : std::max(final_target, options.newton_forcing * norm(bq));
    gmres(matvec, precond, b, x, target, options.gmres_restart, budget, workspace, true);

    // New tractions: stick values; slip tractions rotated to the solved direction, norm mu p.
    double dir_change = 0.0;
    for (std::size_t i : active) {
      const std::size_t k = offset[i];
      if (out.state[i] == ElementState::stick) {
        tx[i] += x[k];
        ty[i] += x[k + 1];
      } else {
        const double ux = ex[i] - ey[i] * x[k] / bound[i];
        const double uy = ey[i] + ex[i] * x[k] / bound[i];
        const double un = std::hypot(ux, uy);
        dir_change = std::max(dir_change, std::abs(x[k]) / bound[i]);
        ex[i] = ux / un;
        ey[i] = uy / un;
        tx[i] = bound[i] * ex[i];
        ty[i] = bound[i] * ey[i];
      }
    }

    // Slip velocity v = M tau + q everywhere.
    pb.apply(tx.data(), ty.data(), vx.data(), vy.data());
    --budget;
    for (std::size_t i = 0; i < n; ++i) {
      vx[i] += qx[i];
      vy[i] += qy[i];
    }

    // Residuals and set updates: stick elements above mu p_n become slip along their traction
    // (eq. 107); slip elements whose velocity has turned along their traction return to stick.
    double stick_res = 0.0, dir_res = 0.0;  // sums of squares, then RMS
    std::size_t n_stick = 0, n_slip = 0;
    int changes = 0;
    for (std::size_t i : active) {
      if (out.state[i] == ElementState::stick) {
        stick_res += (vx[i] * vx[i] + vy[i] * vy[i]) / (vscale * vscale);
        ++n_stick;
        const double t = std::hypot(tx[i], ty[i]);
        if (t > bound[i] * (1.0 + hysteresis)) {
          out.state[i] = ElementState::slip;
          ex[i] = tx[i] / t;
          ey[i] = ty[i] / t;
          tx[i] = bound[i] * ex[i];
          ty[i] = bound[i] * ey[i];
          vnorm[i] = std::hypot(vx[i], vy[i]);
          ++changes;
        }
      } else {
        const double along = vx[i] * ex[i] + vy[i] * ey[i];
        if (along > hysteresis * vscale) {
          out.state[i] = ElementState::stick;
          ++changes;
        } else {
          // Direction misfit: velocity component across the traction, in rigid-slip units.
          const double across = (vx[i] * ey[i] - vy[i] * ex[i]) / vscale;
          dir_res += across * across;
          ++n_slip;
          vnorm[i] = std::hypot(vx[i], vy[i]);
        }
      }
    }
    stick_res = n_stick > 0 ? std::sqrt(stick_res / static_cast<double>(n_stick)) : 0.0;
    dir_res = n_slip > 0 ? std::sqrt(dir_res / static_cast<double>(n_slip)) : 0.0;
    out.stick_residual = stick_res;
    out.direction_residual = dir_res;
    last_changes = changes;
    if (changes == 0 && dir_res <= options.tolerance && stick_res <= options.tolerance) {
      out.converged = true;
      break;
    }
    // A tight step that misses the tolerance on the stick residual, or stalls on the direction
    // residual (which the Newton update otherwise reduces quadratically): the linear solve is the
    // limit, tighten it.
    if (changes == 0 && tight &&
        (stick_res > options.tolerance || dir_res > 0.5 * previous_dir_res)) {
      inner_factor *= 0.1;
    }
    previous_dir_res = dir_res;
  }

  // Output slip and Coulomb residual.
  double coulomb = -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (out.state[i] == ElementState::exterior) continue;
    coulomb = std::max(coulomb, (std::hypot(tx[i], ty[i]) - bound[i]) / (friction * pmax));
    if (out.state[i] == ElementState::slip) {
      out.slip_x[i] = vx[i];
      out.slip_y[i] = vy[i];
    }
  }
  out.coulomb_residual = coulomb;
  finish();
  return out;
}

}  // namespace

TangentialGridSolution solve_sliding(ComplianceOperator& op, const Field& pressure,
                                     const SlidingInput& input,
                                     const TangentialSolverOptions& options,
                                     TangentialWorkspace& workspace) {
  input.validate();
  // s = A tau - delta (eq. 103): q = -delta.
  const RigidSlip q = [&](const Grid& g, Field& qx, Field& qy) {
    qx.assign(g.size(), -input.shift_x);
    qy.assign(g.size(), -input.shift_y);
  };
  return solve(op, pressure, input.friction, q, false, options, workspace.gmres);
}

TangentialGridSolution solve_steady_rolling(ComplianceOperator& op, const Field& pressure,
                                            const RollingInput& input,
                                            const TangentialSolverOptions& options,
                                            TangentialWorkspace& workspace) {
  input.validate();
  // w/V = c - (B - A) tau / h with c = (xi_x - y phi, xi_y + x phi) (eqs. 111, 119-120); the
  // difference is taken at second order (Problem::apply).
  const RigidSlip q = [&](const Grid& g, Field& qx, Field& qy) {
    qx = sample(g, [&](double, double y) { return input.creepage_x - y * input.spin; });
    qy = sample(g, [&](double x, double) { return input.creepage_y + x * input.spin; });
  };
  return solve(op, pressure, input.friction, q, true, options, workspace.gmres);
}

TangentialGridSolution solve_steady_rolling(ComplianceOperator& op, const Field& pressure,
                                            const RollingInput& input,
                                            const TangentialSolverOptions& options) {
  TangentialWorkspace workspace;
  return solve_steady_rolling(op, pressure, input, options, workspace);
}

}  // namespace ferro::contact::mim
