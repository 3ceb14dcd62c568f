// Elasto-plastic rail head under a Hertzian wheel load (GetFEM small-strain J2 brick).
//
// References: see elastoplastic.hpp.
// Known deviations: see elastoplastic.hpp (prescribed Hertz pressure, one load-unload cycle,
// linear hardening, no tangential compliance).

#include "ferro/fe_contact/elastoplastic.hpp"

#include <fmt/format.h>
#include <getfem/getfem_im_data.h>
#include <getfem/getfem_mesh_fem.h>
#include <getfem/getfem_mesh_im.h>
#include <getfem/getfem_model_solvers.h>
#include <getfem/getfem_models.h>
#include <getfem/getfem_plasticity.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>

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

ElastoplasticResult hertz_load_cycle(const RailSteel& steel, const HertzLoadCase& load) {
  steel.validate("hertz_load_cycle.steel");
  load.validate("hertz_load_cycle.load");
  const std::clock_t cpu0 = std::clock();
  gmm::set_traces_level(0);  // GetFEM's assembly traces would go to stderr
  // Internal units: mm, N, MPa (the Newton residual is then in N).
  const double a = load.semi_axis_x * 1e3, b = load.semi_axis_y * 1e3;
  const double h = std::min(a, b) / load.elements_per_semi_axis;
  const double size = load.extent * std::max(a, b);
  StructuredBody body;
  body.s = graded_lines(-1.25 * a, 1.25 * a, h, load.growth, -size, size);
  body.t = graded_lines(-1.25 * b, 1.25 * b, h, load.growth, -size, size);
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
  for (int step = 1; step <= load.load_steps; ++step)
    solve_at(static_cast<double>(step) / load.load_steps);
  out.displacement_loaded = -md.real_variable("u")[centre_dof] * 1e-3;
  for (int step = load.load_steps - 1; step >= 0; --step)
    solve_at(static_cast<double>(step) / load.load_steps);
  out.displacement_residual = -md.real_variable("u")[centre_dof] * 1e-3;

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
