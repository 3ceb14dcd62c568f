// FE influence coefficients of an elastic block (GetFEM assembly, CHOLMOD factorisation).
//
// References: see fe_block.hpp.
// Known deviations: see fe_block.hpp (block geometry, no normal-tangential coupling).

#include "ferro/fe_contact/fe_block.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <fmt/format.h>
#include <getfem/getfem_assembling.h>
#include <getfem/getfem_mesh.h>
#include <getfem/getfem_mesh_fem.h>
#include <getfem/getfem_mesh_im.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <map>
#include <stdexcept>
#include <vector>

namespace ferro::fe_contact {

namespace mim = contact::mim;

void FeBlockSpec::validate(const std::string& where) const {
  grid.validate(where + ".grid");
  material.validate(where + ".material");
  if (subdivisions < 1 || subdivisions > 8) {
    throw std::invalid_argument(
        fmt::format("{}.subdivisions: must be in [1, 8], got {}", where, subdivisions));
  }
  if (degree != 1 && degree != 2) {
    throw std::invalid_argument(fmt::format("{}.degree: must be 1 or 2, got {}", where, degree));
  }
  if (!(growth >= 1.0 && growth <= 3.0)) {
    throw std::invalid_argument(fmt::format("{}.growth: must be in [1, 3], got {}", where, growth));
  }
  if (!(extent >= 2.0 && extent <= 1000.0)) {
    throw std::invalid_argument(
        fmt::format("{}.extent: must be in [2, 1000], got {}", where, extent));
  }
}

namespace {

// Node coordinates: uniform steps h on [a, b], then steps growing by `growth` out to lo and hi.
std::vector<double> graded(double a, double b, double h, double growth, double lo, double hi) {
  const int n = std::max(1, static_cast<int>(std::lround((b - a) / h)));
  std::vector<double> right, left;
  for (int i = 0; i <= n; ++i) right.push_back(a + (b - a) * i / n);
  const double step0 = (b - a) / n;
  for (double s = step0 * growth, x = b; x < hi;) {
    x = (x + 1.5 * s >= hi) ? hi : x + s;  // last element absorbs a short remainder
    right.push_back(x);
    s *= growth;
  }
  for (double s = step0 * growth, x = a; x > lo;) {
    x = (x - 1.5 * s <= lo) ? lo : x - s;
    left.push_back(x);
    s *= growth;
  }
  std::reverse(left.begin(), left.end());
  left.insert(left.end(), right.begin(), right.end());
  return left;
}

// Integrals of the 1-D Lagrange shape functions of degree d over an element of unit length.
std::vector<double> shape_integrals(int d) {
  return d == 1 ? std::vector<double>{0.5, 0.5} : std::vector<double>{1.0 / 6, 4.0 / 6, 1.0 / 6};
}

// Consistent 1-D nodal weights of a unit uniform load on [c - w/2, c + w/2] split into `sub`
// elements of degree d: node coordinate -> integral of its shape function.
std::map<long long, double> load_weights(double c, double w, int sub, int d, double unit) {
  std::map<long long, double> out;
  const std::vector<double> s = shape_integrals(d);
  const double h = w / sub;
  for (int e = 0; e < sub; ++e)
    for (int t = 0; t <= d; ++t) {
      const double x = c - 0.5 * w + (e + static_cast<double>(t) / d) * h;
      out[std::llround(x / unit)] += s[static_cast<std::size_t>(t)] * h;
    }
  return out;
}

}  // namespace

FeInfluence block_influence(const FeBlockSpec& spec) {
  spec.validate();
  const std::clock_t cpu0 = std::clock();
  const mim::Grid& g = spec.grid;
  const int d = spec.degree;
  const double dx = g.dx, dy = g.dy;
  // Loaded area: columns -nx..nx around x = 0, the grid's rows in y.
  const double ex = (g.nx + 0.5) * dx;
  const double y_lo = g.y0 - 0.5 * dy, y_hi = g.y0 + (g.ny - 0.5) * dy;
  const double ey = 0.5 * (y_hi - y_lo), yc = 0.5 * (y_hi + y_lo);
  const double size = spec.extent * std::max(ex, ey);
  const double hx = dx / spec.subdivisions, hy = dy / spec.subdivisions;
  const std::vector<double> xs = graded(-ex, ex, hx, spec.growth, -size, size);
  const std::vector<double> ys = graded(y_lo, y_hi, hy, spec.growth, yc - size, yc + size);
  // Depth: uniform layers over one grid element, then graded down to the clamped bottom.
  std::vector<double> zs = graded(-std::max(dx, dy), 0.0, std::min(hx, hy), spec.growth, -size, 0.0);

  // Structured hexahedral mesh (vertex order of GetFEM's parallelepiped: x fastest, then y, z).
  getfem::mesh m;
  const bgeot::pgeometric_trans pgt = bgeot::parallelepiped_geotrans(3, 1);
  const std::size_t nx = xs.size(), ny = ys.size(), nz = zs.size();
  std::vector<bgeot::size_type> node(nx * ny * nz);
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i)
        node[(k * ny + j) * nx + i] = m.add_point(bgeot::base_node(xs[i], ys[j], zs[k]));
  std::array<bgeot::size_type, 8> v{};
  for (std::size_t k = 0; k + 1 < nz; ++k)
    for (std::size_t j = 0; j + 1 < ny; ++j)
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        for (std::size_t c = 0; c < 8; ++c)
          v[c] = node[((k + (c >> 2)) * ny + (j + ((c >> 1) & 1))) * nx + (i + (c & 1))];
        m.add_convex(pgt, v.begin());
      }

  getfem::mesh_fem mf(m, bgeot::dim_type(3));
  mf.set_finite_element(m.convex_index(),
                        getfem::fem_descriptor(fmt::format("FEM_QK(3,{})", d)));
  getfem::mesh_im im(m);
  im.set_integration_method(m.convex_index(), getfem::int_method_descriptor(fmt::format(
                                                  "IM_GAUSS_PARALLELEPIPED(3,{})", 2 * d)));
  const std::size_t ndof = mf.nb_dof();
  const double G = spec.material.shear_modulus, nu = spec.material.poisson;
  getfem::model_real_plain_vector lambda(1, 2.0 * G * nu / (1.0 - 2.0 * nu)), mu(1, G);
  getfem::model_real_sparse_matrix K(ndof, ndof);
  getfem::asm_stiffness_matrix_for_homogeneous_linear_elasticity(K, im, mf, lambda, mu);

  // DOF of each node, keyed by rounded coordinates; clamped bottom.
  const double unit = 1.0e-6 * std::min(hx, hy) / d;
  auto key = [&](double x, double y, double z) {
    return std::array<long long, 3>{std::llround(x / unit), std::llround(y / unit),
                                    std::llround(z / unit)};
  };
  std::map<std::array<long long, 3>, std::size_t> dof_at;
  std::vector<long> free_index(ndof, -1);
  long nfree = 0;
  const double z_bottom = zs.front();
  for (std::size_t i = 0; i < ndof; i += 3) {
    const bgeot::base_node p = mf.point_of_basic_dof(i);
    dof_at[key(p[0], p[1], p[2])] = i;
    if (std::abs(p[2] - z_bottom) > unit) {
      for (std::size_t c = 0; c < 3; ++c) free_index[i + c] = nfree++;
    }
  }
  gmm::csc_matrix<double> Kc;
  gmm::copy(K, Kc);
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(Kc.pr.size());
  for (std::size_t col = 0; col < ndof; ++col) {
    if (free_index[col] < 0) continue;
    for (std::size_t p = Kc.jc[col]; p < Kc.jc[col + 1]; ++p) {
      const std::size_t row = Kc.ir[p];
      if (free_index[row] < 0 || free_index[row] < free_index[col]) continue;  // lower triangle
      trip.emplace_back(free_index[row], free_index[col], Kc.pr[p]);
    }
  }
  Eigen::SparseMatrix<double> A(nfree, nfree);
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  llt.compute(A);
  if (llt.info() != Eigen::Success) {
    throw std::runtime_error("block_influence: CHOLMOD factorisation failed");
  }

  // Right-hand sides: unit traction on grid element (column x = 0, row is) along x, y, -z.
  const int nyg = g.ny;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(nfree, 3 * nyg);
  const std::map<long long, double> wx = load_weights(0.0, dx, spec.subdivisions, d, unit);
  for (int is = 0; is < nyg; ++is) {
    const std::map<long long, double> wy = load_weights(g.y(is), dy, spec.subdivisions, d, unit);
    for (const auto& [kx, fx] : wx)
      for (const auto& [ky, fy] : wy) {
        const auto it = dof_at.find({kx, ky, 0});
        if (it == dof_at.end()) throw std::logic_error("block_influence: load node not in mesh");
        const std::size_t base = it->second;
        B(free_index[base + 0], 3 * is + 0) += fx * fy;
        B(free_index[base + 1], 3 * is + 1) += fx * fy;
        B(free_index[base + 2], 3 * is + 2) -= fx * fy;  // pressure pushes into the block
      }
  }
  const Eigen::MatrixXd X = llt.solve(B);

  FeInfluence out;
  out.single_body = mim::ColumnInfluence::zeros(g.nx, g.ny);
  mim::ColumnInfluence& c = out.single_body;
  for (int ox = -g.nx; ox <= g.nx; ++ox)
    for (int io = 0; io < nyg; ++io) {
      const auto it = dof_at.find(key(ox * dx, g.y(io), 0.0));
      if (it == dof_at.end()) throw std::logic_error("block_influence: centre not a mesh node");
      const long ux = free_index[it->second], uy = free_index[it->second + 1],
                 uz = free_index[it->second + 2];
      for (int is = 0; is < nyg; ++is) {
        const std::size_t k = c.index(ox, io, is);
        c.xx[k] = X(ux, 3 * is + 0);
        c.yx[k] = X(uy, 3 * is + 0);
        c.xy[k] = X(ux, 3 * is + 1);
        c.yy[k] = X(uy, 3 * is + 1);
        c.zz[k] = -X(uz, 3 * is + 2);
      }
    }
  out.elements = static_cast<long>(m.nb_convex());
  out.dofs = static_cast<long>(ndof);
  out.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return out;
}

mim::ColumnInfluence pair_of_identical(const mim::ColumnInfluence& single_body) {
  mim::ColumnInfluence p = single_body;
  for (std::vector<double>* v : {&p.zz, &p.xx, &p.xy, &p.yx, &p.yy})
    for (double& x : *v) x *= 2.0;
  return p;
}

}  // namespace ferro::fe_contact
