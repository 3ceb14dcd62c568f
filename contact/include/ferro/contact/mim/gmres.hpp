#pragma once
// Restarted right-preconditioned GMRES for the linear systems of the MIM tangential solver
// (matrix-free: FFT influence products), with a budget of operator products shared across the
// Newton steps of one solve.
//
// References: Saad & Schultz, "GMRES: a generalized minimal residual algorithm for solving
// nonsymmetric linear systems", SIAM J. Sci. Stat. Comput. 7 (1986) 856-869; Saad, "Iterative
// methods for sparse linear systems" (2003) sec. 6.5 (modified Gram-Schmidt, Givens rotations)
// and 9.3.2 (right preconditioning: the residual tested is the true residual b - K x).
// Known deviations: none. Measured against SUNDIALS SPGMR and Eigen's GMRES on the MIM systems
// in bench/gmres.cpp (docs/PERFORMANCE.md).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ferro::contact::mim {

namespace detail {
// Vectorised reductions and updates (Eigen; a plain loop's reduction is not vectorised).
inline double dot(const std::vector<double>& a, const std::vector<double>& b) {
  using MapCV = Eigen::Map<const Eigen::VectorXd>;
  return MapCV(a.data(), static_cast<Eigen::Index>(a.size()))
      .dot(MapCV(b.data(), static_cast<Eigen::Index>(b.size())));
}
// y += alpha x
inline void axpy(double alpha, const std::vector<double>& x, std::vector<double>& y) {
  using MapV = Eigen::Map<Eigen::VectorXd>;
  using MapCV = Eigen::Map<const Eigen::VectorXd>;
  MapV(y.data(), static_cast<Eigen::Index>(y.size())) +=
      alpha * MapCV(x.data(), static_cast<Eigen::Index>(x.size()));
}
inline double norm(const std::vector<double>& a) {
  return std::sqrt(dot(a, a));
}
}  // namespace detail

// Work vectors of GMRES, kept across the Newton steps of one solve (no page faults per call).
struct GmresWorkspace {
  using Vec = std::vector<double>;
  Vec r, w, z;
  std::vector<Vec> v;
  std::vector<double> h, cs, sn, g, y;
  void resize(std::size_t n, int restart) {
    r.resize(n);
    w.resize(n);
    z.resize(n);
    v.resize(static_cast<std::size_t>(restart) + 1);
    for (Vec& vi : v) vi.resize(n);
    h.assign((static_cast<std::size_t>(restart) + 1) * static_cast<std::size_t>(restart), 0.0);
    cs.assign(restart, 0.0);
    sn.assign(restart, 0.0);
    g.assign(restart + 1, 0.0);
    y.assign(restart, 0.0);
  }
};

// Restarted right-preconditioned GMRES (Saad & Schultz 1986) for K x = b, matrix-free, with
// modified Gram-Schmidt. Stops when ||b - K x||_2 <= target or when the product budget is
// spent. Returns the final residual norm.
template <class MatVec, class Precond>
double gmres(MatVec&& matvec, Precond&& precond, const std::vector<double>& b,
             std::vector<double>& x, double target, int restart,
             int& budget, GmresWorkspace& ws, bool zero_start = false) {
  using Vec = std::vector<double>;
  using detail::axpy;
  using detail::dot;
  using detail::norm;
  const std::size_t n = b.size();
  ws.resize(n, restart);
  Vec& r = ws.r;
  Vec& w = ws.w;
  Vec& z = ws.z;
  std::vector<Vec>& v = ws.v;
  auto hess = [&](int i, int j) -> double& {
    return ws.h[static_cast<std::size_t>(i) * restart + j];
  };
  std::vector<double>& cs = ws.cs;
  std::vector<double>& sn = ws.sn;
  std::vector<double>& g = ws.g;
  double res = 0.0;
  bool first = true;
  while (true) {
    if (first && zero_start) {  // x = 0: the residual is b, no product needed
      r = b;
    } else {
      matvec(x, r);
      --budget;
      for (std::size_t i = 0; i < n; ++i) r[i] = b[i] - r[i];
    }
    first = false;
    res = norm(r);
    if (res <= target || budget <= 0) return res;
    for (std::size_t i = 0; i < n; ++i) v[0][i] = r[i] / res;
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = res;
    int k = 0;
    for (; k < restart && budget > 0; ++k) {
      precond(v[k], z);
      matvec(z, w);
      --budget;
      for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
        const double hik = dot(w, v[i]);
        hess(i, k) = hik;
        axpy(-hik, v[i], w);
      }
      hess(k + 1, k) = norm(w);
      if (hess(k + 1, k) > 0.0) {
        const double inv = 1.0 / hess(k + 1, k);
        for (std::size_t j = 0; j < n; ++j) v[k + 1][j] = w[j] * inv;
      }
      for (int i = 0; i < k; ++i) {  // previous Givens rotations
        const double t = cs[i] * hess(i, k) + sn[i] * hess(i + 1, k);
        hess(i + 1, k) = -sn[i] * hess(i, k) + cs[i] * hess(i + 1, k);
        hess(i, k) = t;
      }
      const double d = std::hypot(hess(k, k), hess(k + 1, k));
      cs[k] = d > 0.0 ? hess(k, k) / d : 1.0;
      sn[k] = d > 0.0 ? hess(k + 1, k) / d : 0.0;
      hess(k, k) = d;
      hess(k + 1, k) = 0.0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      if (std::abs(g[k + 1]) <= target) {
        ++k;
        break;
      }
    }
    // Back substitution and update x += P (V y).
    std::vector<double>& y = ws.y;
    for (int i = k - 1; i >= 0; --i) {
      double s = g[i];
      for (int j = i + 1; j < k; ++j) s -= hess(i, j) * y[j];
      y[i] = hess(i, i) != 0.0 ? s / hess(i, i) : 0.0;
    }
    std::fill(w.begin(), w.end(), 0.0);
    for (int i = 0; i < k; ++i) axpy(y[i], v[i], w);
    precond(w, z);
    for (std::size_t j = 0; j < n; ++j) x[j] += z[j];
    if (k == 0) return res;
  }
}

}  // namespace ferro::contact::mim
