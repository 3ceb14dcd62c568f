// K_ij range of a wheel on an elasto-plastic rail (first pass, shaken down).
//
// References: see elastoplastic_kij.hpp.
// Known deviations: see elastoplastic_kij.hpp (elastic normal compliance, stationary yielded
// zone, elastic wheel).

#include "ferro/fe_contact/elastoplastic_kij.hpp"

#include <fmt/format.h>

#include <cmath>
#include <ctime>
#include <stdexcept>

#include "ferro/contact/mim/influence_operator.hpp"
#include "ferro/contact/mim/normal_solver.hpp"
#include "ferro/fe_contact/matrix_operator.hpp"

namespace ferro::fe_contact {

namespace mim = contact::mim;

void ElastoplasticKijSpec::validate(const std::string& where) const {
  contact.validate(where + ".contact");
  RailSteel steel;
  steel.elastic = contact.body;
  steel.yield_stress = yield_stress;
  steel.hardening_modulus = hardening_modulus;
  steel.validate(where);
  HertzLoadCase load;
  load.semi_axis_x = contact.semi_axis_x();
  load.semi_axis_y = contact.semi_axis_y();
  load.peak_pressure = 1.0;
  load.elements_per_semi_axis = elements_per_semi_axis;
  load.load_steps = load_steps;
  load.unload_steps = unload_steps;
  load.growth = growth;
  load.extent = extent;
  load.validate(where);
}

ElastoplasticKij elastoplastic_reduction_factors(const ElastoplasticKijSpec& spec,
                                                 const SlopeOptions& options) {
  spec.validate();
  options.validate();
  const std::clock_t cpu0 = std::clock();
  const double a = spec.contact.semi_axis_x(), b = spec.contact.semi_axis_y();
  RailSteel steel;
  steel.elastic = spec.contact.body;
  steel.yield_stress = spec.yield_stress;
  steel.hardening_modulus = spec.hardening_modulus;
  HertzLoadCase load;
  load.semi_axis_x = a;
  load.semi_axis_y = b;
  load.peak_pressure = 3.0 * spec.contact.normal_force / (2.0 * M_PI * a * b);
  load.elements_per_semi_axis = spec.elements_per_semi_axis;
  load.load_steps = spec.load_steps;
  load.unload_steps = spec.unload_steps;
  load.growth = spec.growth;
  load.extent = spec.extent;
  load.compliance_grid = elastoplastic_grid(a, b, spec.elements_per_semi_axis);
  // The shaken-down rail is elastic (half-space compliance): its run needs no FE coefficients and
  // takes the finer grid of the contact case. A rolling pass leaves a groove invariant along the
  // rail: the stationary dent's cross-section through the patch centre (x = 0), sampled on one
  // column three times the fine grid's width (a deep groove widens the patch).
  const mim::Grid fine = spec.contact.grid();
  const int extra = fine.ny;  // rows added each side of the sampled column
  load.dent_grid = fine;
  load.dent_grid.nx = 2;  // the smallest grid; column 0 is x = 0
  load.dent_grid.x0 = 0.0;
  load.dent_grid.ny = fine.ny + 2 * extra;
  load.dent_grid.y0 = fine.y0 - extra * fine.dy;

  ElastoplasticKij out;
  out.grid = load.compliance_grid;
  out.cycle = hertz_load_cycle(steel, load);

  const contact::CombinedMaterial pair = contact::combine(spec.contact.body, spec.contact.body);
  const mim::Field gap = spec.contact.gap(out.grid);
  SlopeCase sc;
  sc.normal_force = spec.contact.normal_force;
  sc.friction = spec.contact.friction;
  sc.semi_axis_x = a;
  mim::InfluenceOperator half_space(out.grid, pair);

  // First pass: half-space pair plus the yielded rail's tangential correction.
  SurfaceCompliance loaded = SurfaceCompliance::half_space(out.grid, pair);
  loaded.add_tangential(out.cycle.tangent_correction);
  MatrixComplianceOperator first_pass(std::move(loaded), pair);
  out.first_pass = reduction_factors(first_pass, half_space, gap, sc, options);

  // Shaken down: elastic compliance, the residual groove deepens the gap (fine grid, widened by
  // rows of the same size, same row lattice, until the dented patch stays off its boundary).
  for (int widen = 0;; widen += fine.ny / 2) {
    if (widen > extra) {
      throw std::runtime_error(fmt::format(
          "elastoplastic_reduction_factors: the patch on the grooved rail is wider than {} "
          "elements",
          fine.ny + 2 * extra));
    }
    mim::Grid g = fine;
    g.ny = fine.ny + 2 * widen;
    g.y0 = fine.y0 - widen * fine.dy;
    const mim::Field g_gap = spec.contact.gap(g);
    mim::Field dented = g_gap;
    for (int iy = 0; iy < g.ny; ++iy)
      for (int ix = 0; ix < g.nx; ++ix)
        dented[g.index(ix, iy)] +=
            out.cycle.residual_dent[load.dent_grid.index(0, iy + extra - widen)];
    mim::InfluenceOperator g_half_space(g, pair);
    const mim::NormalGridSolution n =
        mim::solve_normal_force(g_half_space, dented, sc.normal_force, options.mim.normal);
    if (n.boundary_contact_elements > 0) continue;
    out.shaken_down.half_space = creep_stiffness(g_half_space, g_gap, sc, options);
    out.shaken_down.modified = creep_stiffness(g_half_space, dented, sc, options);
    out.shaken_down.update_ratios();
    out.fine_grid = g;
    break;
  }
  out.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return out;
}

}  // namespace ferro::fe_contact
