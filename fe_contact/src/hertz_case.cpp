// Hertzian study case, interfacial layer, closed-form layer estimate.
//
// References: see hertz_case.hpp.
// Known deviations: see hertz_case.hpp (local layer compliance).

#include "ferro/fe_contact/hertz_case.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/contact/mim/influence_operator.hpp"

namespace ferro::fe_contact {

namespace mim = contact::mim;

void HertzCase::validate(const std::string& where) const {
  auto positive = [&](const char* name, double v) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::invalid_argument(
          fmt::format("{}.{}: must be finite and > 0, got {}", where, name, v));
    }
  };
  positive("reference_force", reference_force);
  positive("reference_semi_axis_x", reference_semi_axis_x);
  positive("reference_semi_axis_y", reference_semi_axis_y);
  positive("normal_force", normal_force);
  positive("friction", friction);
  body.validate(where + ".body");
  if (elements_minor < 8) {
    throw std::invalid_argument(
        fmt::format("{}.elements_minor: must be >= 8, got {}", where, elements_minor));
  }
  if (!(margin >= 0.05 && margin <= 2.0)) {
    throw std::invalid_argument(
        fmt::format("{}.margin: must be in [0.05, 2], got {}", where, margin));
  }
}

double HertzCase::semi_axis_x() const {
  return reference_semi_axis_x * std::cbrt(normal_force / reference_force);
}
double HertzCase::semi_axis_y() const {
  return reference_semi_axis_y * std::cbrt(normal_force / reference_force);
}

mim::Grid HertzCase::grid() const {
  validate();
  return mim::grid_for_ellipse(semi_axis_x(), semi_axis_y(), elements_minor, margin);
}

mim::Field HertzCase::gap(const mim::Grid& grid) const {
  const contact::CombinedMaterial m = contact::combine(body, body);
  const mim::HertzGap g =
      mim::hertz_gap_for_ellipse(semi_axis_x(), semi_axis_y(), normal_force, m.contact_modulus);
  return mim::quadratic_gap(grid, g.curvature_x, g.curvature_y);
}

void InterfaceLayer::validate(const std::string& where) const {
  if (!(thickness >= 0.0) || !std::isfinite(thickness)) {
    throw std::invalid_argument(
        fmt::format("{}.thickness: must be finite and >= 0 m, got {}", where, thickness));
  }
  if (thickness > 0.0 && (!(shear_modulus > 0.0) || !std::isfinite(shear_modulus))) {
    throw std::invalid_argument(fmt::format(
        "{}.shear_modulus: must be finite and > 0 Pa with a layer, got {}", where, shear_modulus));
  }
  if (!(yield_shear > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{}.yield_shear: must be > 0 Pa (inf: elastic), got {}", where, yield_shear));
  }
}

double InterfaceLayer::compliance() const {
  return thickness > 0.0 ? thickness / shear_modulus : 0.0;
}

double layer_k11_estimate(double shear_modulus, double c11, double semi_axis_x, double thickness,
                          double layer_shear_modulus) {
  return 1.0 /
         (1.0 + 3.0 * shear_modulus * c11 * thickness / (8.0 * semi_axis_x * layer_shear_modulus));
}

SlopeResult layer_reduction_factors(const HertzCase& c, const InterfaceLayer& layer,
                                    const SlopeOptions& options) {
  c.validate();
  layer.validate();
  const mim::Grid grid = c.grid();
  const mim::Field gap = c.gap(grid);
  const contact::CombinedMaterial m = contact::combine(c.body, c.body);
  mim::InfluenceOperator half_space(grid, m);
  mim::InfluenceOperator layered(grid, m, layer.compliance());
  SlopeCase sc;
  sc.normal_force = c.normal_force;
  sc.friction = c.friction;
  sc.semi_axis_x = c.semi_axis_x();
  // The reference run has no cap: tau_c belongs to the layer.
  SlopeResult r = reduction_factors(layered, half_space, gap, sc, options);
  if (std::isfinite(layer.yield_shear)) {
    sc.yield_shear = layer.yield_shear;
    r.modified = creep_stiffness(layered, gap, sc, options);
    r.update_ratios();
  }
  return r;
}

}  // namespace ferro::fe_contact
