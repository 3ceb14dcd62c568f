// FE influence coefficients of a structured elastic body (GetFEM assembly, CHOLMOD).
//
// References: see fe_body.hpp.
// Known deviations: see fe_body.hpp (trilinear mapped mesh, one contact frame per column).

#include "ferro/fe_contact/fe_body.hpp"

#include "structured_mesh.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <fmt/format.h>
#include <getfem/getfem_assembling.h>
#include <getfem/getfem_mesh.h>
#include <getfem/getfem_mesh_fem.h>
#include <getfem/getfem_mesh_im.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <stdexcept>

namespace ferro::fe_contact {

namespace mim = contact::mim;

void FeMeshLevel::validate(const std::string& where) const {
  if (degree != 1 && degree != 2) {
    throw std::invalid_argument(fmt::format("{}.degree: must be 1 or 2, got {}", where, degree));
  }
  if (subdivisions < 1 || subdivisions > 8) {
    throw std::invalid_argument(
        fmt::format("{}.subdivisions: must be in [1, 8], got {}", where, subdivisions));
  }
  if (!(growth >= 1.0 && growth <= 3.0)) {
    throw std::invalid_argument(fmt::format("{}.growth: must be in [1, 3], got {}", where, growth));
  }
  if (near_columns < 0 || near_columns > 50) {
    throw std::invalid_argument(
        fmt::format("{}.near_columns: must be in [0, 50], got {}", where, near_columns));
  }
}

std::vector<double> graded_lines(double a, double b, double h, double growth, double lo,
                                 double hi, const std::vector<double>& required) {
  const int n = std::max(1, static_cast<int>(std::ceil((b - a) / h - 1e-9)));
  std::vector<double> right, left;
  for (int i = 0; i <= n; ++i) right.push_back(a + (b - a) * i / n);
  const double step0 = (b - a) / n;
  for (double s = step0 * growth, x = b; x < hi;) {
    x = (x + 1.5 * s >= hi) ? hi : x + s;
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
  for (double r : required) {
    if (!(r > lo && r < hi)) continue;
    const auto it = std::lower_bound(left.begin(), left.end(), r);
    const std::size_t i = static_cast<std::size_t>(it - left.begin());
    const double step = left[std::min(i, left.size() - 1)] - left[i == 0 ? 0 : i - 1];
    std::vector<double> kept;
    for (double x : left)
      if (std::abs(x - r) >= step / 3.0 || x == lo || x == hi || (x >= a && x <= b))
        kept.push_back(x);
    kept.push_back(r);
    std::sort(kept.begin(), kept.end());
    kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
    left = std::move(kept);
  }
  return left;
}

namespace detail {

std::vector<std::size_t> build_structured_mesh(const StructuredBody& body, getfem::mesh& m) {
  const std::size_t ns = body.s.size(), nt = body.t.size(), nw = body.w.size();
  auto active = [&](std::size_t i, std::size_t j, std::size_t k) {
    return !body.active || body.active(i, j, k);
  };
  auto place = [&](double s, double t, double w) {
    return body.map ? body.map(s, t, w) : Point3{s, t, w};
  };
  // Nodes used by active cells, then the hexahedra (GetFEM vertex order: s fastest, then t, w).
  const bgeot::pgeometric_trans pgt = bgeot::parallelepiped_geotrans(3, 1);
  const std::size_t ns_nodes = body.periodic_s ? ns - 1 : ns;
  std::vector<std::size_t> node(ns_nodes * nt * nw, kNoCell);
  auto node_id = [&](std::size_t i, std::size_t j, std::size_t k) -> std::size_t& {
    return node[(k * nt + j) * ns_nodes + (i % ns_nodes)];
  };
  std::vector<std::size_t> cell(ns * nt * nw, kNoCell);
  std::array<bgeot::size_type, 8> v{};
  for (std::size_t k = 0; k + 1 < nw; ++k)
    for (std::size_t j = 0; j + 1 < nt; ++j)
      for (std::size_t i = 0; i + 1 < ns; ++i) {
        if (!active(i, j, k)) continue;
        for (std::size_t c = 0; c < 8; ++c) {
          const std::size_t ii = i + (c & 1), jj = j + ((c >> 1) & 1), kk = k + (c >> 2);
          std::size_t& id = node_id(ii, jj, kk);
          if (id == kNoCell) {
            const Point3 p = place(body.s[ii], body.t[jj], body.w[kk]);
            id = m.add_point(bgeot::base_node(p[0], p[1], p[2]), -1.0);
          }
          v[c] = id;
        }
        cell[(k * nt + j) * ns + i] = m.add_convex(pgt, v.begin());
      }
  return cell;
}

bgeot::short_type hexahedron_w_face(const getfem::mesh& m, std::size_t convex, int top) {
  const bgeot::pconvex_structure cs = m.structure_of_convex(convex);
  for (bgeot::short_type f = 0; f < cs->nb_faces(); ++f) {
    bool all = true;
    for (auto c : cs->ind_points_of_face(f)) all = all && static_cast<int>(c >> 2) == top;
    if (all) return f;
  }
  throw std::logic_error("hexahedron_w_face: no such face");
}

Eigen::MatrixXd solve_clamped(const getfem::model_real_sparse_matrix& K,
                              const std::vector<long>& free_index, long nfree,
                              const Eigen::MatrixXd& B, const char* where) {
  const std::size_t ndof = free_index.size();
  gmm::csc_matrix<double> Kc;
  gmm::copy(K, Kc);
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(Kc.pr.size() / 2 + ndof);
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
  trip = {};
  Kc = gmm::csc_matrix<double>();
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  llt.compute(A);
  if (llt.info() != Eigen::Success) {
    throw std::runtime_error(fmt::format("{}: CHOLMOD factorisation failed", where));
  }
  return llt.solve(B);
}

}  // namespace detail

namespace {

// Index of line value v in lines (within tol), or throws.
std::size_t line_index(const std::vector<double>& lines, double v, double tol, const char* what) {
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (std::abs(lines[i] - v) <= tol) return i;
  throw std::invalid_argument(
      fmt::format("surface_influence: {} {} m is not a node line of the mesh", what, v));
}

// Cell index i with lines[i] <= v <= lines[i + 1] and the reference coordinate in it.
std::pair<std::size_t, double> locate(const std::vector<double>& lines, double v) {
  if (v < lines.front() || v > lines.back()) {
    throw std::invalid_argument(
        fmt::format("surface_influence: sample coordinate {} m outside the mesh", v));
  }
  std::size_t i = static_cast<std::size_t>(std::upper_bound(lines.begin(), lines.end(), v) -
                                           lines.begin());
  i = std::min(std::max<std::size_t>(i, 1), lines.size() - 1) - 1;
  return {i, (v - lines[i]) / (lines[i + 1] - lines[i])};
}

double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

FeInfluence surface_influence(const StructuredBody& body, const mim::Grid& g,
                              const contact::Material& material, int degree) {
  g.validate("surface_influence.grid");
  material.validate("surface_influence.material");
  if (degree != 1 && degree != 2) {
    throw std::invalid_argument(fmt::format("surface_influence: degree must be 1 or 2, got {}",
                                            degree));
  }
  if (body.s.size() < 2 || body.t.size() < 2 || body.w.size() < 2 || body.w.back() != 0.0 ||
      !body.clamped) {
    throw std::invalid_argument(
        "surface_influence: the body needs >= 2 lines per axis, w ending at 0 and a clamp");
  }
  const std::clock_t cpu0 = std::clock();
  const std::size_t ns = body.s.size(), nt = body.t.size(), nw = body.w.size();
  getfem::mesh m;
  const std::vector<std::size_t> cell = detail::build_structured_mesh(body, m);
  constexpr std::size_t kNone = detail::kNoCell;
  const bgeot::pgeometric_trans pgt = bgeot::parallelepiped_geotrans(3, 1);
  if (m.nb_convex() == 0) throw std::invalid_argument("surface_influence: no active cell");

  getfem::mesh_fem mf(m, bgeot::dim_type(3));
  const getfem::pfem pf = getfem::fem_descriptor(fmt::format("FEM_QK(3,{})", degree));
  mf.set_finite_element(m.convex_index(), pf);
  getfem::mesh_im im(m);
  im.set_integration_method(m.convex_index(), getfem::int_method_descriptor(fmt::format(
                                                  "IM_GAUSS_PARALLELEPIPED(3,{})", 2 * degree)));
  const std::size_t ndof = mf.nb_dof();
  // Cells grouped by material (the body's unless cell_material names another), one assembly each.
  std::vector<const contact::Material*> materials{&material};
  std::vector<getfem::mesh_region> regions(1);
  for (std::size_t k = 0; k + 1 < nw; ++k)
    for (std::size_t j = 0; j + 1 < nt; ++j)
      for (std::size_t i = 0; i + 1 < ns; ++i) {
        const std::size_t cv = cell[(k * nt + j) * ns + i];
        if (cv == kNone) continue;
        const contact::Material* mat = body.cell_material ? body.cell_material(i, j, k) : nullptr;
        if (mat == nullptr) mat = &material;
        const auto it = std::find(materials.begin(), materials.end(), mat);
        const std::size_t r = static_cast<std::size_t>(it - materials.begin());
        if (it == materials.end()) {
          mat->validate("surface_influence.cell_material");
          materials.push_back(mat);
          regions.emplace_back();
        }
        regions[r].add(cv);
      }
  getfem::model_real_sparse_matrix K(ndof, ndof);
  for (std::size_t r = 0; r < materials.size(); ++r) {
    if (regions[r].is_empty()) continue;
    const double G = materials[r]->shear_modulus, nu = materials[r]->poisson;
    getfem::model_real_plain_vector lambda(1, 2.0 * G * nu / (1.0 - 2.0 * nu)), mu(1, G);
    getfem::model_real_sparse_matrix Kr(ndof, ndof);
    getfem::asm_stiffness_matrix_for_homogeneous_linear_elasticity(Kr, im, mf, lambda, mu,
                                                                   regions[r]);
    gmm::add(Kr, K);
  }

  // Free DOFs (clamped nodes removed).
  std::vector<long> free_index(ndof, -1);
  long nfree = 0;
  for (std::size_t i = 0; i < ndof; i += 3) {
    const bgeot::base_node p = mf.point_of_basic_dof(i);
    if (body.clamped(Point3{p[0], p[1], p[2]})) continue;
    for (std::size_t c = 0; c < 3; ++c) free_index[i + c] = nfree++;
  }
  if (nfree == static_cast<long>(ndof)) {
    throw std::invalid_argument("surface_influence: no clamped node (rigid-body motion)");
  }
  const bgeot::short_type top_face =
      detail::hexahedron_w_face(m, m.convex_index().first_true(), 1);

  // Right-hand sides: unit traction over grid element (column s = 0, row is), integrated over
  // the top faces of the cells it covers, along the rolling, lateral and inward directions.
  const double tol = 1e-9 * std::min(g.dx, g.dy);
  const std::size_t i_lo = line_index(body.s, -0.5 * g.dx, tol, "s =");
  const std::size_t i_hi = line_index(body.s, 0.5 * g.dx, tol, "s =");
  const std::size_t k_top = nw - 2;
  const Point3 inward{-body.normal[0], -body.normal[1], -body.normal[2]};
  const std::array<Point3, 3> dirs{body.rolling, body.lateral, inward};
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(nfree, 3 * g.ny);
  std::vector<double> rhs(ndof);
  for (int is = 0; is < g.ny; ++is) {
    const std::size_t j_lo = line_index(body.t, g.y(is) - 0.5 * g.dy, tol, "row edge t =");
    const std::size_t j_hi = line_index(body.t, g.y(is) + 0.5 * g.dy, tol, "row edge t =");
    getfem::mesh_region faces;
    for (std::size_t j = j_lo; j < j_hi; ++j)
      for (std::size_t i = i_lo; i < i_hi; ++i) {
        const std::size_t cv = cell[(k_top * nt + j) * ns + i];
        if (cv == kNone) {
          throw std::invalid_argument(
              fmt::format("surface_influence: grid row {} is not on the body's surface", is));
        }
        faces.add(cv, top_face);
      }
    for (int d = 0; d < 3; ++d) {
      std::fill(rhs.begin(), rhs.end(), 0.0);
      const std::vector<double> traction(dirs[d].begin(), dirs[d].end());
      getfem::asm_homogeneous_source_term(rhs, im, mf, traction, faces);
      for (std::size_t i = 0; i < ndof; ++i)
        if (free_index[i] >= 0) B(free_index[i], 3 * is + d) = rhs[i];
    }
  }
  const Eigen::MatrixXd X = detail::solve_clamped(K, free_index, nfree, B, "surface_influence");

  // Sampling: FE interpolation at the grid-element centres (w = 0) of every column offset.
  FeInfluence out;
  out.single_body = mim::ColumnInfluence::zeros(g.nx, g.ny);
  mim::ColumnInfluence& c = out.single_body;
  bgeot::base_matrix Gm;
  Eigen::VectorXd u(3);
  for (int ox = -g.nx; ox <= g.nx; ++ox)
    for (int io = 0; io < g.ny; ++io) {
      const auto [i, xi] = locate(body.s, ox * g.dx);
      const auto [j, eta] = locate(body.t, g.y(io));
      const std::size_t cv = cell[(k_top * nt + j) * ns + i];
      if (cv == kNone) {
        throw std::invalid_argument(fmt::format(
            "surface_influence: sample ({}, {}) is not on the body's surface", ox, io));
      }
      if (pf->need_G()) bgeot::vectors_to_base_matrix(Gm, m.points_of_convex(cv));
      getfem::fem_interpolation_context ctx(pgt, pf, bgeot::base_node(xi, eta, 1.0), Gm, cv);
      const auto& dofs = mf.ind_basic_dof_of_element(cv);
      bgeot::base_matrix Mloc(3, dofs.size());
      pf->interpolation(ctx, Mloc, 3);
      for (int is = 0; is < g.ny; ++is) {
        Eigen::Matrix3d U;  // column d: displacement under the load along dirs[d]
        for (int d = 0; d < 3; ++d) {
          u.setZero();
          for (std::size_t q = 0; q < dofs.size(); ++q) {
            const long f = free_index[dofs[q]];
            if (f < 0) continue;
            for (int r = 0; r < 3; ++r) u[r] += Mloc(r, q) * X(f, 3 * is + d);
          }
          const Point3 up{u[0], u[1], u[2]};
          U(0, d) = dot(up, body.rolling);
          U(1, d) = dot(up, body.lateral);
          U(2, d) = dot(up, inward);
        }
        const std::size_t k = c.index(ox, io, is);
        c.xx[k] = U(0, 0);
        c.yx[k] = U(1, 0);
        c.xy[k] = U(0, 1);
        c.yy[k] = U(1, 1);
        c.zz[k] = U(2, 2);
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

mim::ColumnInfluence pair_of_bodies(const mim::ColumnInfluence& lower,
                                    const mim::ColumnInfluence& upper_turned) {
  if (lower.nx != upper_turned.nx || lower.ny != upper_turned.ny) {
    throw std::invalid_argument("pair_of_bodies: the two bodies' grids differ");
  }
  mim::ColumnInfluence p = lower;
  const int ny = lower.ny;
  for (int ox = -lower.nx; ox <= lower.nx; ++ox)
    for (int io = 0; io < ny; ++io)
      for (int is = 0; is < ny; ++is) {
        const std::size_t k = p.index(ox, io, is);
        const std::size_t kt = upper_turned.index(ox, ny - 1 - io, ny - 1 - is);
        p.zz[k] += upper_turned.zz[kt];
        p.xx[k] += upper_turned.xx[kt];
        p.yy[k] += upper_turned.yy[kt];
        p.xy[k] -= upper_turned.xy[kt];
        p.yx[k] -= upper_turned.yx[kt];
      }
  return p;
}

}  // namespace ferro::fe_contact
