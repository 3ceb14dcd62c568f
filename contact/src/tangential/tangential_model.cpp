// Tangential problem validation and Kalker's linear theory with K_ij, the model
// "kalker_linear" (the registry is in registry.cpp).
//
// References: Toumi (2016) eqs. (38)-(40), (156).
// Known deviations: none. C11, C22, C23 a contact source gives with the patch (imported tables)
// take the place of the ones computed from a/b.
#include "ferro/contact/tangential/tangential_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ferro::contact {

void TractionMap::clear() {
  x.clear();
  y.clear();
  dx.clear();
  dy.clear();
  pressure.clear();
  traction_x.clear();
  traction_y.clear();
  slip.clear();
}

void TangentialProblem::validate() const {
  if (patch == nullptr) throw std::invalid_argument("tangential problem.patch: must be set");
  patch->validate("tangential problem.patch");
  if (!(friction >= 0.0) || !std::isfinite(friction)) {
    throw std::invalid_argument(
        fmt::format("tangential problem.friction: must be finite and >= 0, got {}", friction));
  }
  if (!std::isfinite(creepage.longitudinal) || !std::isfinite(creepage.lateral) ||
      !std::isfinite(creepage.spin)) {
    throw std::invalid_argument(
        fmt::format("tangential problem.creepage: must be finite, got ({}, {}, {})",
                    creepage.longitudinal, creepage.lateral, creepage.spin));
  }
  // Material::validate builds a std::string: call it only when the quick check fails.
  const auto plausible = [](const Material& m) {
    return m.shear_modulus > 0.0 && std::isfinite(m.shear_modulus) && m.poisson >= 0.0 &&
           m.poisson < 0.5;
  };
  if (!plausible(body1)) body1.validate("tangential problem.body1");
  if (!plausible(body2)) body2.validate("tangential problem.body2");
  reduction.validate("tangential problem.reduction");
}

TangentialSolution LinearCreepStiffness::forces(const Creepage& cr) const {
  const double ab = a * b;
  const double gab = shear_modulus * ab;
  const double gab15 = gab * std::sqrt(ab);
  TangentialSolution s;
  s.force_x = -gab * c.c11 * cr.longitudinal;
  s.force_y = -gab * c.c22 * cr.lateral - gab15 * c.c23 * cr.spin;
  s.moment_z = gab15 * c.c23 * cr.lateral - gab * ab * c.c33 * cr.spin;
  return s;
}

LinearCreepStiffness linear_creep_stiffness(const TangentialProblem& problem,
                                            CoefficientSource source) {
  const CombinedMaterial m = combine(problem.body1, problem.body2);
  const ContactPatch& p = *problem.patch;
  LinearCreepStiffness k;
  k.shear_modulus = m.shear_modulus;
  k.poisson = m.poisson;
  k.a = p.semi_axis_x;
  k.b = p.semi_axis_y;
  const double ratio = p.curvature_x / p.curvature_y;
  if (source == CoefficientSource::kVocoFit && !(ratio > 0.0 && std::isfinite(ratio))) {
    throw std::invalid_argument(
        "coefficients=voco_fit needs the patch curvatures A and B (curvature_x, curvature_y)");
  }
  k.c = kalker_coefficients(source, k.a, k.b, std::min(m.poisson, 0.5), ratio);
  // Coefficients the contact source gives with the patch replace the computed ones.
  if (std::isfinite(p.c11)) k.c.c11 = p.c11;
  if (std::isfinite(p.c22)) k.c.c22 = p.c22;
  if (std::isfinite(p.c23)) k.c.c23 = p.c23;
  k.c.c11 *= problem.reduction.k11;
  k.c.c22 *= problem.reduction.k22;
  k.c.c23 *= problem.reduction.k23;
  k.c.c33 *= problem.reduction.k33;
  return k;
}

CoefficientSource coefficients_option(const ModelOptions& options) {
  return coefficient_source_from_name(option_string(options, "coefficients", "kalker_table"));
}

std::unique_ptr<TangentialModel> KalkerLinearModel::from_options(const ModelOptions& options) {
  check_option_keys("kalker_linear", options, {"coefficients"});
  return std::make_unique<KalkerLinearModel>(coefficients_option(options));
}

TangentialSolution KalkerLinearModel::solve(const TangentialProblem& problem) const {
  problem.validate();
  return linear_creep_stiffness(problem, source_).forces(problem.creepage);
}

}  // namespace ferro::contact
