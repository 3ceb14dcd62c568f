// Elasto-plastic rail head under a Hertzian wheel load (GetFEM small-strain J2 brick).
//
// References: see elastoplastic.hpp.
// Known deviations: see elastoplastic.hpp (prescribed Hertz pressure, one load-unload cycle,
// linear hardening, frozen continuum tangent for the yielded rail's compliance).

#include "ferro/fe_contact/elastoplastic.hpp"

#include <fmt/format.h>
#include <getfem/getfem_assembling.h>
#include <getfem/getfem_generic_assembly.h>
#include <getfem/getfem_im_data.h>
#include <getfem/getfem_mesh_fem.h>
#include <getfem/getfem_mesh_im.h>
#include <getfem/getfem_model_solvers.h>
#include <getfem/getfem_models.h>
#include <getfem/getfem_plasticity.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

#include "ferro/fe_contact/fe_body.hpp"
#include "structured_mesh.hpp"

namespace ferro::fe_contact {

void RailSteel::validate(const std::string& where) const {
  elastic.validate(where + ".elastic");
  if (!(yield_stress > 0.0) || !std::isfinite(yield_stress)) {
    throw std::invalid_argument(
        fmt::format("{}.yield_stress: must be finite and > 0 Pa, got {}", where, yield_stress));
  }
  if (!(hardening_modulus >= 0.0) || !std::isfinite(hardening_modulus)) {
    throw std::invalid_argument(fmt::format(
        "{}.hardening_modulus: must be finite and >= 0 Pa, got {}", where, hardening_modulus));
  }
}

void HertzLoadCase::validate(const std::string& where) const {
  for (const auto& [name, v] :
       {std::pair{"semi_axis_x", semi_axis_x}, std::pair{"semi_axis_y", semi_axis_y},
        std::pair{"peak_pressure", peak_pressure}}) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::invalid_argument(
          fmt::format("{}.{}: must be finite and > 0, got {}", where, name, v));
    }
  }
  if (elements_per_semi_axis < 2 || elements_per_semi_axis > 40) {
    throw std::invalid_argument(fmt::format("{}.elements_per_semi_axis: must be in [2, 40], got {}",
                                            where, elements_per_semi_axis));
  }
  if (!(growth >= 1.0 && growth <= 3.0)) {
    throw std::invalid_argument(fmt::format("{}.growth: must be in [1, 3], got {}", where, growth));
  }
  if (!(extent >= 3.0 && extent <= 1000.0)) {
    throw std::invalid_argument(
        fmt::format("{}.extent: must be in [3, 1000], got {}", where, extent));
  }
  if (load_steps < 1 || load_steps > 100) {
    throw std::invalid_argument(
        fmt::format("{}.load_steps: must be in [1, 100], got {}", where, load_steps));
  }
  if (unload_steps < 0 || unload_steps > 100) {
    throw std::invalid_argument(
        fmt::format("{}.unload_steps: must be in [0, 100], got {}", where, unload_steps));
  }
  if (dent_grid.nx != 0) dent_grid.validate(where + ".dent_grid");
  if (compliance_grid.nx != 0) {
    const contact::mim::Grid& g = compliance_grid;
    g.validate(where + ".compliance_grid");
    const bool centred = std::abs(g.x(0) + 0.5 * (g.nx - 1) * g.dx) <= 1e-9 * g.dx &&
                         std::abs(g.y(0) + 0.5 * (g.ny - 1) * g.dy) <= 1e-9 * g.dy;
    if (g.nx % 2 != 0 || g.ny % 2 != 0 || !centred) {
      throw std::invalid_argument(fmt::format(
          "{}.compliance_grid: must be centred with even nx, ny (the patch centre a node), got "
          "{} x {}",
          where, g.nx, g.ny));
    }
    if (0.5 * g.nx * g.dx < semi_axis_x || 0.5 * g.ny * g.dy < semi_axis_y) {
      throw std::invalid_argument(
          fmt::format("{}.compliance_grid: {} x {} elements of {} x {} m do not cover the patch "
                      "a = {} m, b = {} m",
                      where, g.nx, g.ny, g.dx, g.dy, semi_axis_x, semi_axis_y));
    }
  }
}

contact::mim::Grid elastoplastic_grid(double semi_axis_x, double semi_axis_y,
                                      int elements_per_semi_axis) {
  if (!(semi_axis_x > 0.0) || !(semi_axis_y > 0.0) || elements_per_semi_axis < 2) {
    throw std::invalid_argument(fmt::format(
        "elastoplastic_grid: needs a, b > 0 and >= 2 elements per semi-axis, got {}, {}, {}",
        semi_axis_x, semi_axis_y, elements_per_semi_axis));
  }
  const double h = std::min(semi_axis_x, semi_axis_y) / elements_per_semi_axis;
  auto count = [h](double semi) { return 2 * static_cast<int>(std::ceil(1.25 * semi / h - 1e-9)); };
  return contact::mim::Grid::centred(count(semi_axis_x), count(semi_axis_y), h, h);
}

double HertzLoadCase::normal_force() const {
  return 2.0 * M_PI * semi_axis_x * semi_axis_y * peak_pressure / 3.0;
}

AxisVonMisesPeak hertz_circular_axis_von_mises_peak(double poisson) {
  // sigma_r = sigma_theta = p0 [-(1 + nu)(1 - z atan(a / z) / a) + 1 / (2 (1 + z^2 / a^2))],
  // sigma_z = -p0 / (1 + z^2 / a^2); von Mises on the axis = |sigma_z - sigma_r|.
  auto ratio = [poisson](double zeta) {
    const double sr =
        -(1.0 + poisson) * (1.0 - zeta * std::atan(1.0 / zeta)) + 0.5 / (1.0 + zeta * zeta);
    const double sz = -1.0 / (1.0 + zeta * zeta);
    return std::abs(sz - sr);
  };
  // Dense scan, then golden-section refinement of the bracket.
  double best = 1e-3;
  for (double zeta = 1e-3; zeta <= 3.0; zeta += 1e-3)
    if (ratio(zeta) > ratio(best)) best = zeta;
  double lo = best - 1e-3, hi = best + 1e-3;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 60; ++i) {
    const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    if (ratio(x1) > ratio(x2))
      hi = x2;
    else
      lo = x1;
  }
  const double zeta = 0.5 * (lo + hi);
  return {ratio(zeta), zeta};
}

namespace {

// Values of a trilinear displacement field on the top surface (w = 0) of a structured mesh:
// bilinear interpolation of the top nodes' DOFs (mm units).
class SurfaceSampler {
 public:
  SurfaceSampler() = default;
  SurfaceSampler(const getfem::mesh_fem& mf, const std::vector<double>& s,
                 const std::vector<double>& t)
      : s_(s), t_(t), dof_(s.size() * t.size(), kNone) {
    const double tol = 1e-9 * (s.back() - s.front());
    for (std::size_t i = 0; i < mf.nb_basic_dof(); i += 3) {
      const bgeot::base_node p = mf.point_of_basic_dof(i);
      if (std::abs(p[2]) > tol) continue;
      const std::size_t is = nearest(s_, p[0]), it = nearest(t_, p[1]);
      if (std::abs(s_[is] - p[0]) <= tol && std::abs(t_[it] - p[1]) <= tol)
        dof_[it * s_.size() + is] = i;
    }
  }
  // Component c of u at (x, y, 0) [mm].
  [[nodiscard]] double value(const getfem::model_real_plain_vector& u, double x, double y,
                             int c) const {
    const auto [i, xi] = cell_of(s_, x);
    const auto [j, eta] = cell_of(t_, y);
    double v = 0.0;
    for (int q = 0; q < 4; ++q) {
      const std::size_t ii = i + (q & 1), jj = j + (q >> 1);
      const std::size_t d = dof_[jj * s_.size() + ii];
      if (d == kNone) throw std::logic_error("SurfaceSampler: no top node");
      const double w = ((q & 1) ? xi : 1.0 - xi) * ((q >> 1) ? eta : 1.0 - eta);
      v += w * u[d + static_cast<std::size_t>(c)];
    }
    return v;
  }
  // Index of the line closest to v.
  static std::size_t nearest(const std::vector<double>& lines, double v) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < lines.size(); ++i)
      if (std::abs(lines[i] - v) < std::abs(lines[best] - v)) best = i;
    return best;
  }

 private:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  static std::pair<std::size_t, double> cell_of(const std::vector<double>& lines, double v) {
    std::size_t i = static_cast<std::size_t>(std::upper_bound(lines.begin(), lines.end(), v) -
                                             lines.begin());
    i = std::min(std::max<std::size_t>(i, 1), lines.size() - 1) - 1;
    return {i, (v - lines[i]) / (lines[i + 1] - lines[i])};
  }
  std::vector<double> s_, t_;
  std::vector<std::size_t> dof_;
};

struct TangentInput {
  const getfem::mesh* m;
  const getfem::mesh_fem* mf;
  const getfem::mesh_im* im;
  const getfem::im_data* im_tensor;
  const getfem::im_data* im_scalar;
  const std::vector<std::size_t>* cell;
  const StructuredBody* body;
  const contact::mim::Grid* grid;
  const RailSteel* steel;
};

// Tangential compliance of the rail at the converged peak load with the continuum
// elasto-plastic tangent at the points that flowed in the last load step, minus the elastic
// compliance of the same mesh (single body, contact frame, m/Pa).
SurfaceCompliance tangent_correction(const TangentInput& in, const getfem::model& md,
                                     const getfem::model_real_plain_vector& ep_before,
                                     const SurfaceSampler& sampler, getfem::size_type bottom,
                                     int& flowing) {
  const getfem::mesh_fem& mf = *in.mf;
  const contact::mim::Grid& g = *in.grid;
  const double G = in.steel->elastic.shear_modulus * 1e-6, nu = in.steel->elastic.poisson;
  const double H = in.steel->hardening_modulus * 1e-6;
  // Unit stress deviator and the flowing points (plastic strain changed in the last step).
  const getfem::model_real_plain_vector& ep = md.real_variable("Previous_Ep");
  getfem::base_vector dev;
  getfem::ga_interpolation_im_data(md, "Deviator(Sym(Grad_u)-Previous_Ep)", *in.im_tensor, dev);
  const std::size_t npts = ep.size() / 9;
  getfem::model_real_plain_vector nd(ep.size(), 0.0), beta(npts, 0.0), no_beta(npts, 0.0);
  flowing = 0;
  for (std::size_t q = 0; q < npts; ++q) {
    double inc = 0.0, n2 = 0.0;
    for (std::size_t c = 0; c < 9; ++c) {
      inc = std::max(inc, std::abs(ep[9 * q + c] - ep_before[9 * q + c]));
      n2 += dev[9 * q + c] * dev[9 * q + c];
    }
    if (inc == 0.0 || n2 == 0.0) continue;
    const double inv = 1.0 / std::sqrt(n2);
    for (std::size_t c = 0; c < 9; ++c) nd[9 * q + c] = dev[9 * q + c] * inv;
    beta[q] = 6.0 * G * G / (3.0 * G + H);
    ++flowing;
  }
  const std::size_t ndof = mf.nb_dof();
  // The workspace keeps references: every vector it is given outlives the assembly.
  const getfem::model_real_plain_vector lambda(1, 2.0 * G * nu / (1.0 - 2.0 * nu)), mu(1, G);
  auto assemble = [&](const getfem::model_real_plain_vector& b) {
    getfem::ga_workspace ws;
    const getfem::model_real_plain_vector U(ndof, 0.0);
    ws.add_fem_variable("u", mf, gmm::sub_interval(0, ndof), U);
    ws.add_fixed_size_constant("lambda", lambda);
    ws.add_fixed_size_constant("mu", mu);
    ws.add_im_data("Nd", *in.im_tensor, nd);
    ws.add_im_data("beta", *in.im_scalar, b);
    ws.add_expression(
        "lambda*Div_u*Div_Test_u + 2*mu*(Sym(Grad_u):Grad_Test_u)"
        " - beta*(Nd:Grad_u)*(Nd:Grad_Test_u)",
        *in.im);
    getfem::model_real_sparse_matrix K(ndof, ndof);
    ws.set_assembled_matrix(K);
    ws.assembly(2);
    return K;
  };

  // Free DOFs: all but the clamped bottom.
  std::vector<long> free_index(ndof, 0);
  const dal::bit_vector clamped = mf.basic_dof_on_region(bottom);
  long nfree = 0;
  for (std::size_t i = 0; i < ndof; ++i) free_index[i] = clamped.is_in(i) ? -1 : nfree++;

  // Right-hand sides: unit traction (1 MPa) along x and y on each grid element's top face.
  const StructuredBody& body = *in.body;
  const std::size_t ns = body.s.size(), nt = body.t.size(), nw = body.w.size();
  const std::size_t n = g.size();
  const bgeot::short_type top_face = detail::hexahedron_w_face(*in.m, (*in.cell)[((nw - 2) * nt) * ns], 1);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(nfree, 2 * static_cast<Eigen::Index>(n));
  std::vector<double> rhs(ndof);
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t i = SurfaceSampler::nearest(body.s, g.x(ix) * 1e3);
      const std::size_t j = SurfaceSampler::nearest(body.t, g.y(iy) * 1e3);
      // The element centre lies inside the cell (i or i - 1, j or j - 1).
      const std::size_t ci = body.s[i] > g.x(ix) * 1e3 ? i - 1 : i;
      const std::size_t cj = body.t[j] > g.y(iy) * 1e3 ? j - 1 : j;
      getfem::mesh_region face;
      face.add((*in.cell)[((nw - 2) * nt + cj) * ns + ci], top_face);
      for (int d = 0; d < 2; ++d) {
        std::fill(rhs.begin(), rhs.end(), 0.0);
        std::vector<double> traction(3, 0.0);
        traction[static_cast<std::size_t>(d)] = 1.0;
        getfem::asm_homogeneous_source_term(rhs, *in.im, mf, traction, face);
        for (std::size_t k = 0; k < ndof; ++k)
          if (free_index[k] >= 0)
            B(free_index[k], 2 * static_cast<Eigen::Index>(g.index(ix, iy)) + d) = rhs[k];
      }
    }
  const Eigen::MatrixXd X_ep =
      detail::solve_clamped(assemble(beta), free_index, nfree, B, "hertz_load_cycle (tangent)");
  const Eigen::MatrixXd X_el =
      detail::solve_clamped(assemble(no_beta), free_index, nfree, B, "hertz_load_cycle (elastic)");

  // Observations at the element centres, one column beyond the grid along +x.
  SurfaceCompliance c = SurfaceCompliance::zeros(g);
  constexpr double kMmPerMpaToMPerPa = 1e-9;
  getfem::model_real_plain_vector u(ndof, 0.0);
  for (std::size_t src = 0; src < n; ++src)
    for (int d = 0; d < 2; ++d) {
      const Eigen::Index col = 2 * static_cast<Eigen::Index>(src) + d;
      for (std::size_t k = 0; k < ndof; ++k)
        u[k] = free_index[k] >= 0 ? X_ep(free_index[k], col) - X_el(free_index[k], col) : 0.0;
      for (int iy = 0; iy < g.ny; ++iy)
        for (int ix = 0; ix <= g.nx; ++ix) {
          const double x = (g.x0 + ix * g.dx) * 1e3, y = g.y(iy) * 1e3;
          const double ux = sampler.value(u, x, y, 0) * kMmPerMpaToMPerPa;
          const double uy = sampler.value(u, x, y, 1) * kMmPerMpaToMPerPa;
          const std::size_t k = c.index(ix, iy, src);
          (d == 0 ? c.xx : c.xy)[k] = ux;
          (d == 0 ? c.yx : c.yy)[k] = uy;
        }
    }
  return c;
}

}  // namespace

ElastoplasticResult hertz_load_cycle(const RailSteel& steel, const HertzLoadCase& load) {
  steel.validate("hertz_load_cycle.steel");
  load.validate("hertz_load_cycle.load");
  const std::clock_t cpu0 = std::clock();
  gmm::set_traces_level(0);  // GetFEM's assembly traces would go to stderr
  // Internal units: mm, N, MPa (the Newton residual is then in N).
  const double a = load.semi_axis_x * 1e3, b = load.semi_axis_y * 1e3;
  const contact::mim::Grid& grid = load.compliance_grid;
  const bool with_compliance = grid.nx != 0;
  const double h = with_compliance ? std::min(grid.dx, grid.dy) * 1e3
                                   : std::min(a, b) / load.elements_per_semi_axis;
  const double size = load.extent * std::max(a, b);
  StructuredBody body;
  if (with_compliance) {
    // Cells are the grid's elements, one column more towards +x (the rolling difference
    // observes the displacement one element beyond the leading edge).
    const double gx = 0.5 * grid.nx * grid.dx * 1e3, gy = 0.5 * grid.ny * grid.dy * 1e3;
    body.s = graded_lines(-gx, gx + grid.dx * 1e3, grid.dx * 1e3, load.growth, -size, size);
    body.t = graded_lines(-gy, gy, grid.dy * 1e3, load.growth, -size, size);
  } else {
    body.s = graded_lines(-1.25 * a, 1.25 * a, h, load.growth, -size, size);
    body.t = graded_lines(-1.25 * b, 1.25 * b, h, load.growth, -size, size);
  }
  body.w = graded_lines(-1.5 * std::max(a, b), 0.0, h, load.growth, -size, 0.0);
  getfem::mesh m;
  const std::vector<std::size_t> cell = detail::build_structured_mesh(body, m);
  const std::size_t ns = body.s.size(), nt = body.t.size(), nw = body.w.size();
  constexpr getfem::size_type kTop = 1, kBottom = 2;
  for (std::size_t j = 0; j + 1 < nt; ++j)
    for (std::size_t i = 0; i + 1 < ns; ++i) {
      const std::size_t top = cell[((nw - 2) * nt + j) * ns + i], bottom = cell[j * ns + i];
      m.region(kTop).add(top, detail::hexahedron_w_face(m, top, 1));
      m.region(kBottom).add(bottom, detail::hexahedron_w_face(m, bottom, 0));
    }

  getfem::mesh_fem mf(m, bgeot::dim_type(3));
  mf.set_finite_element(m.convex_index(), getfem::fem_descriptor("FEM_QK(3,1)"));
  getfem::mesh_im im(m);
  im.set_integration_method(m.convex_index(),
                            getfem::int_method_descriptor("IM_GAUSS_PARALLELEPIPED(3,2)"));
  getfem::im_data im_tensor(im, bgeot::multi_index(3, 3)), im_scalar(im);

  const double G = steel.elastic.shear_modulus * 1e-6, nu = steel.elastic.poisson;
  getfem::model md;
  md.add_fem_variable("u", mf);
  md.add_fem_data("Previous_u", mf);
  md.add_im_data("xi", im_scalar);
  md.add_im_data("Previous_xi", im_scalar);
  md.add_im_data("Previous_Ep", im_tensor);
  md.add_im_data("Previous_alpha", im_scalar);
  md.add_initialized_scalar_data("lambda", 2.0 * G * nu / (1.0 - 2.0 * nu));
  md.add_initialized_scalar_data("mu", G);
  md.add_initialized_scalar_data("sigma_y", steel.yield_stress * 1e-6);
  md.add_initialized_scalar_data("Hk", 0.0);
  md.add_initialized_scalar_data("Hi", steel.hardening_modulus * 1e-6);
  const std::string law = "Prandtl Reuss linear hardening";
  const std::vector<std::string> vars{"u", "xi", "Previous_Ep", "Previous_alpha"};
  const std::vector<std::string> params{"lambda", "mu", "sigma_y", "Hk", "Hi"};
  getfem::add_small_strain_elastoplasticity_brick(md, im, law, getfem::DISPLACEMENT_ONLY, vars,
                                                  params);
  getfem::add_Dirichlet_condition_with_simplification(md, "u", kBottom);
  md.add_initialized_scalar_data("load_factor", 0.0);
  md.add_initialized_scalar_data("p0", load.peak_pressure * 1e-6);
  md.add_initialized_scalar_data("ax", a);
  md.add_initialized_scalar_data("by", b);
  getfem::add_source_term(
      md, im, "(-load_factor*p0)*sqrt(pos_part(1-sqr(X(1)/ax)-sqr(X(2)/by)))*Test_u(3)", kTop);

  // Surface centre: the node at the origin, its u_z (positive into the rail: -u_z).
  std::size_t centre_dof = mf.nb_dof();
  for (std::size_t i = 2; i < mf.nb_dof(); i += 3) {
    const bgeot::base_node p = mf.point_of_basic_dof(i);
    if (std::abs(p[0]) < 1e-9 * a && std::abs(p[1]) < 1e-9 * a && std::abs(p[2]) < 1e-9 * a) {
      centre_dof = i;
      break;
    }
  }
  if (centre_dof == mf.nb_dof()) throw std::logic_error("hertz_load_cycle: no node at the origin");

  ElastoplasticResult out;
  out.peak_pressure = load.peak_pressure;
  out.dofs = static_cast<long>(mf.nb_dof());
  // GetFEM's Newton residual is relative to the external load, and absolute (N) without one.
  const double force_scale = load.normal_force();  // N
  constexpr double kRelativeResidual = 1e-7;
  auto solve_at = [&](double factor) {
    md.set_real_variable("load_factor")[0] = factor;
    gmm::iteration iter(factor > 0.0 ? kRelativeResidual : kRelativeResidual * force_scale, 0, 40);
    getfem::standard_solve(md, iter);
    if (!iter.converged()) {
      throw std::runtime_error(
          fmt::format("hertz_load_cycle: Newton did not converge at load factor {} (residual {})",
                      factor, iter.get_res()));
    }
    out.newton_iterations += static_cast<int>(iter.get_iteration());
    getfem::small_strain_elastoplasticity_next_iter(md, im, law, getfem::DISPLACEMENT_ONLY, vars,
                                                    params);
  };
  // Loading and unloading in equal steps.
  getfem::model_real_plain_vector ep_before_last;
  for (int step = 1; step <= load.load_steps; ++step) {
    if (step == load.load_steps) ep_before_last = md.real_variable("Previous_Ep");
    solve_at(static_cast<double>(step) / load.load_steps);
  }
  out.displacement_loaded = -md.real_variable("u")[centre_dof] * 1e-3;
  const contact::mim::Grid& dent_grid = load.dent_grid.nx != 0 ? load.dent_grid : grid;
  SurfaceSampler sampler;
  if (dent_grid.nx != 0) sampler = SurfaceSampler(mf, body.s, body.t);
  if (with_compliance) {
    const TangentInput in{&m, &mf, &im, &im_tensor, &im_scalar, &cell, &body, &grid, &steel};
    out.tangent_correction =
        tangent_correction(in, md, ep_before_last, sampler, kBottom, out.flowing_points);
  }
  const getfem::model_real_plain_vector ep_peak = md.real_variable("Previous_Ep");
  const int unload = load.unload_steps > 0 ? load.unload_steps : load.load_steps;
  for (int step = unload - 1; step >= 0; --step) solve_at(static_cast<double>(step) / unload);
  {
    const getfem::model_real_plain_vector& ep_end = md.real_variable("Previous_Ep");
    for (std::size_t q = 0; q < ep_end.size() / 9; ++q)
      for (std::size_t c = 0; c < 9; ++c)
        if (ep_end[9 * q + c] != ep_peak[9 * q + c]) {
          ++out.reverse_flowing_points;
          break;
        }
  }
  out.displacement_residual = -md.real_variable("u")[centre_dof] * 1e-3;
  if (dent_grid.nx != 0) {
    const getfem::model_real_plain_vector& u = md.real_variable("u");
    out.residual_dent = contact::mim::sample(dent_grid, [&](double x, double y) {
      return -sampler.value(u, x * 1e3, y * 1e3, 2) * 1e-3;
    });
  }

  // Equivalent plastic strain sqrt(2/3) |eps_p| at every integration point.
  const getfem::model_real_plain_vector& ep = md.real_variable("Previous_Ep");
  for (dal::bv_visitor cv(m.convex_index()); !cv.finished(); ++cv) {
    const std::size_t nq = im.int_method_of_element(cv)->approx_method()->nb_points_on_convex();
    double zc = 0.0;
    for (const auto& p : m.points_of_convex(cv)) zc += p[2] / 8.0;
    for (std::size_t q = 0; q < nq; ++q) {
      const std::size_t idx = im_tensor.index_of_point(cv, q);
      if (idx == getfem::size_type(-1)) continue;
      double n2 = 0.0;
      for (std::size_t c = 0; c < 9; ++c) n2 += ep[9 * idx + c] * ep[9 * idx + c];
      const double eq = std::sqrt(2.0 / 3.0 * n2);
      if (eq > out.max_plastic_strain) {
        out.max_plastic_strain = eq;
        out.depth_max_plastic_strain = -zc * 1e-3;
      }
    }
  }
  out.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return out;
}

}  // namespace ferro::fe_contact
