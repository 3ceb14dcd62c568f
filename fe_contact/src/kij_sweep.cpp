// K_ij sweep over wheel load and interfacial-layer parameters.
//
// References: see kij_sweep.hpp.
// Known deviations: see kij_sweep.hpp (no finite-body axis; elasto-plastic rail without layer
// or curves).

#include "ferro/fe_contact/kij_sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/contact/mim/influence_operator.hpp"

namespace ferro::fe_contact {

const std::vector<std::string>& sweep_axis_names() {
  static const std::vector<std::string> names{"normal_force", "layer_thickness",
                                              "layer_shear_modulus", "layer_yield_shear",
                                              "yield_stress"};
  return names;
}

bool KijSweepSpec::elastoplastic() const {
  return std::find(axis_names.begin(), axis_names.end(), "yield_stress") != axis_names.end();
}

void KijSweepSpec::validate(const std::string& where) const {
  contact.validate(where + ".contact");
  layer.validate(where + ".layer");
  slope.validate(where + ".slope");
  if (axis_names.empty() || axis_names.size() != axes.size()) {
    throw std::invalid_argument(fmt::format(
        "{}.axes: need >= 1 axis and one name per axis ({} names, {} axes)", where,
        axis_names.size(), axes.size()));
  }
  const auto& allowed = sweep_axis_names();
  for (std::size_t i = 0; i < axis_names.size(); ++i) {
    if (std::find(allowed.begin(), allowed.end(), axis_names[i]) == allowed.end()) {
      throw std::invalid_argument(fmt::format(
          "{}.axes.{}: unknown axis; allowed: normal_force, layer_thickness, "
          "layer_shear_modulus, layer_yield_shear, yield_stress",
          where, axis_names[i]));
    }
    if (std::count(axis_names.begin(), axis_names.end(), axis_names[i]) > 1) {
      throw std::invalid_argument(fmt::format("{}.axes.{}: given twice", where, axis_names[i]));
    }
    const auto& ax = axes[i];
    if (ax.empty()) throw std::invalid_argument(fmt::format("{}.axes.{}: empty", where, axis_names[i]));
    for (std::size_t j = 0; j < ax.size(); ++j) {
      const bool ok_value = std::isfinite(ax[j]) &&
                            (axis_names[i] == "layer_thickness" ? ax[j] >= 0.0 : ax[j] > 0.0);
      if (!ok_value || (j > 0 && !(ax[j] > ax[j - 1]))) {
        throw std::invalid_argument(fmt::format(
            "{}.axes.{}[{}]: values must be strictly increasing and finite (> 0; thickness "
            ">= 0), got {}",
            where, axis_names[i], j, ax[j]));
      }
    }
  }
  if (elastoplastic()) {
    for (const std::string& n : axis_names) {
      if (n.rfind("layer_", 0) == 0) {
        throw std::invalid_argument(fmt::format(
            "{}.axes.{}: the elasto-plastic rail (axis yield_stress) takes no layer axis; "
            "allowed with yield_stress: normal_force",
            where, n));
      }
    }
    if (layer.thickness > 0.0) {
      throw std::invalid_argument(fmt::format(
          "{}.layer.thickness: must be 0 with the yield_stress axis (no layer on the "
          "elasto-plastic rail), got {}",
          where, layer.thickness));
    }
    if (!curve_creepages.empty()) {
      throw std::invalid_argument(fmt::format(
          "{}.curve_creepages: creep curves are not available with the yield_stress axis", where));
    }
    const std::size_t iy = static_cast<std::size_t>(
        std::find(axis_names.begin(), axis_names.end(), "yield_stress") - axis_names.begin());
    for (double v : axes[iy]) {
      ElastoplasticKijSpec p = plastic;
      p.contact = contact;
      p.yield_stress = v;
      p.validate(where + ".plastic");
    }
  }
  for (std::size_t j = 0; j < curve_creepages.size(); ++j) {
    if (!std::isfinite(curve_creepages[j]) || (j > 0 && !(curve_creepages[j] > curve_creepages[j - 1]))) {
      throw std::invalid_argument(fmt::format(
          "{}.curve_creepages[{}]: must be finite and strictly increasing", where, j));
    }
  }
}

std::size_t KijSweepSpec::points() const {
  std::size_t n = 1;
  for (const auto& ax : axes) n *= ax.size();
  return n;
}

std::vector<double> KijSweepSpec::coordinates(std::size_t index) const {
  std::vector<double> c(axes.size());
  for (std::size_t i = axes.size(); i-- > 0;) {
    c[i] = axes[i][index % axes[i].size()];
    index /= axes[i].size();
  }
  return c;
}

void KijSweepSpec::configure(std::size_t index, HertzCase& contact_out,
                             InterfaceLayer& layer_out) const {
  contact_out = contact;
  layer_out = layer;
  const std::vector<double> c = coordinates(index);
  for (std::size_t i = 0; i < c.size(); ++i) {
    const std::string& n = axis_names[i];
    if (n == "normal_force") contact_out.normal_force = c[i];
    if (n == "layer_thickness") layer_out.thickness = c[i];
    if (n == "layer_shear_modulus") layer_out.shear_modulus = c[i];
    if (n == "layer_yield_shear") layer_out.yield_shear = c[i];
  }
}

KijPoint compute_point(const KijSweepSpec& spec, std::size_t index) {
  HertzCase c;
  InterfaceLayer layer;
  spec.configure(index, c, layer);
  KijPoint p;
  if (spec.elastoplastic()) {
    ElastoplasticKijSpec e = spec.plastic;
    e.contact = c;
    const std::vector<double> x = spec.coordinates(index);
    for (std::size_t i = 0; i < x.size(); ++i)
      if (spec.axis_names[i] == "yield_stress") e.yield_stress = x[i];
    const ElastoplasticKij r = elastoplastic_reduction_factors(e, spec.slope);
    p.slopes = r.shaken_down;
    p.has_first_pass = true;
    p.first_pass = r.first_pass;
    p.cycle = r.cycle;
    p.nx = r.grid.nx;
    p.ny = r.grid.ny;
    p.element_size = r.grid.dx;
    return p;
  }
  p.slopes = layer_reduction_factors(c, layer, spec.slope);
  const contact::mim::Grid grid = c.grid();
  p.nx = grid.nx;
  p.ny = grid.ny;
  p.element_size = grid.dx;
  if (!spec.curve_creepages.empty()) {
    const contact::mim::Field gap = c.gap(grid);
    const contact::CombinedMaterial m = contact::combine(c.body, c.body);
    contact::mim::InfluenceOperator half_space(grid, m);
    contact::mim::InfluenceOperator layered(grid, m, layer.compliance());
    SlopeCase sc;
    sc.normal_force = c.normal_force;
    sc.friction = c.friction;
    sc.semi_axis_x = c.semi_axis_x();
    p.reference_curve_x = creep_curve(half_space, gap, sc, 'x', spec.curve_creepages, spec.slope);
    p.reference_curve_y = creep_curve(half_space, gap, sc, 'y', spec.curve_creepages, spec.slope);
    sc.yield_shear = layer.yield_shear;
    p.curve_x = creep_curve(layered, gap, sc, 'x', spec.curve_creepages, spec.slope);
    p.curve_y = creep_curve(layered, gap, sc, 'y', spec.curve_creepages, spec.slope);
  }
  return p;
}

contact::KijTable make_table(const KijSweepSpec& spec,
                             const std::vector<contact::ReductionFactors>& k,
                             std::map<std::string, std::string> provenance,
                             const std::vector<contact::ReductionFactors>& first_pass) {
  if (k.size() != spec.points()) {
    throw std::invalid_argument(fmt::format("make_table: {} results for {} points", k.size(),
                                            spec.points()));
  }
  // The four coefficients of every point, one column each.
  const auto columns = [](const std::vector<contact::ReductionFactors>& v) {
    std::array<std::vector<double>, 4> c;
    for (const contact::ReductionFactors& f : v) {
      c[0].push_back(f.k11);
      c[1].push_back(f.k22);
      c[2].push_back(f.k23);
      c[3].push_back(f.k33);
    }
    return c;
  };
  const auto kc = columns(k);
  contact::KijTable t(spec.axis_names, spec.axes, kc[0], kc[1], kc[2], kc[3]);
  t.set_provenance(std::move(provenance));
  if (!first_pass.empty()) {
    if (first_pass.size() != k.size()) {
      throw std::invalid_argument(fmt::format("make_table: {} first-pass results for {} points",
                                              first_pass.size(), k.size()));
    }
    const auto fc = columns(first_pass);
    t.set_first_pass(fc[0], fc[1], fc[2], fc[3]);
  }
  return t;
}

}  // namespace ferro::fe_contact
