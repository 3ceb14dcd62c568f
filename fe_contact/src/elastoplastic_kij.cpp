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
  // rail: the stationary dent's cross-section through the patch centre (x = 0), one column.
  const mim::Grid fine = spec.contact.grid();
  load.dent_grid = fine;
  load.dent_grid.nx = 2;  // the smallest grid; column 0 is x = 0
  load.dent_grid.x0 = 0.0;

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

  // Shaken down: elastic compliance, the residual groove deepens the gap (fine grid).
  const mim::Field fine_gap = spec.contact.gap(fine);
  mim::Field dented = fine_gap;
  for (int iy = 0; iy < fine.ny; ++iy)
    for (int ix = 0; ix < fine.nx; ++ix)
      dented[fine.index(ix, iy)] += out.cycle.residual_dent[load.dent_grid.index(0, iy)];
  mim::InfluenceOperator fine_half_space(fine, pair);
  out.shaken_down.half_space = creep_stiffness(fine_half_space, fine_gap, sc, options);
  out.shaken_down.modified = creep_stiffness(fine_half_space, dented, sc, options);
  out.shaken_down.update_ratios();
  out.fine_grid = fine;
  out.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return out;
}

}  // namespace ferro::fe_contact
