// Saturation laws on Kalker's linear forces. See saturation_laws.hpp for references and
// known deviations.
#include "ferro/contact/tangential/saturation_laws.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ferro/contact/normal/elliptic.hpp"

namespace ferro::contact {

double saturation_ratio(SaturationLaw law, double t) {
  switch (law) {
    case SaturationLaw::kNone:
      return t;
    case SaturationLaw::kLinear:
      return t < 1.0 ? t : 1.0;
    case SaturationLaw::kVermeulenJohnson:
    case SaturationLaw::kShenHedrickElkins: {
      if (t >= 3.0) return 1.0;
      // 1 - (1 - t/3)^3 expanded, free of cancellation at small t.
      return t * (1.0 - t / 3.0 + t * t / 27.0);
    }
    case SaturationLaw::kChopaya:
      return -std::expm1(-t);
  }
  return t;
}

double full_slip_spin_moment(double a, double b, double mu_fn) {
  const double major = std::max(a, b), minor = std::min(a, b);
  const double k = std::sqrt(std::max(0.0, 1.0 - (minor * minor) / (major * major)));
  const double perimeter =
      4.0 * major * complete_elliptic_integrals(std::min(k, 1.0 - 1e-16)).second;
  return mu_fn * 3.0 / 32.0 * perimeter;
}

double saturated_spin_moment(const LinearCreepStiffness& k, const Creepage& cr, double force_factor,
                             double mu_fn, double creep_utilisation) {
  const double ab = k.a * k.b;
  const double coupling = k.shear_modulus * ab * std::sqrt(ab) * k.c.c23 * cr.lateral;
  const double spin_lin = -k.shear_modulus * ab * ab * k.c.c33 * cr.spin;
  const double full = full_slip_spin_moment(k.a, k.b, mu_fn);
  double spin = spin_lin;
  if (full > 0.0 && spin_lin != 0.0) {
    const double t = std::abs(spin_lin) / full;
    spin = spin_lin * saturation_ratio(SaturationLaw::kShenHedrickElkins, t) / t;
  } else if (!(full > 0.0)) {
    spin = 0.0;
  }
  const double u = std::clamp(creep_utilisation, 0.0, 1.0);
  return force_factor * coupling + spin * std::sqrt(1.0 - u * u);
}

std::string_view SaturatedCreepModel::name() const {
  switch (law_) {
    case SaturationLaw::kNone:
      return "kalker_linear";
    case SaturationLaw::kLinear:
      return "linear_saturated";
    case SaturationLaw::kVermeulenJohnson:
      return "vermeulen_johnson";
    case SaturationLaw::kShenHedrickElkins:
      return "shen_hedrick_elkins";
    case SaturationLaw::kChopaya:
      return "chopaya";
  }
  return "unknown";
}

TangentialSolution SaturatedCreepModel::solve(const TangentialProblem& problem) const {
  problem.validate();
  const LinearCreepStiffness k = linear_creep_stiffness(problem, source_);
  Creepage cr = problem.creepage;
  TangentialSolution lin = k.forces(cr);
  if (law_ == SaturationLaw::kVermeulenJohnson) {
    // Spin ignored (eq. 51): forces and moment from xi_x, xi_y only.
    Creepage no_spin = cr;
    no_spin.spin = 0.0;
    lin = k.forces(no_spin);
  }
  const double limit = problem.friction * problem.patch->normal_force;
  const double ft = std::hypot(lin.force_x, lin.force_y);
  TangentialSolution out;
  if (!(limit > 0.0)) return out;  // no friction or no load: no tangential force
  const double t = ft / limit;     // reduced creepage xi_t (eq. 50)
  const double factor = t > 1e-300 ? saturation_ratio(law_, t) / t : 1.0;
  out.force_x = factor * lin.force_x;
  out.force_y = factor * lin.force_y;
  if (law_ == SaturationLaw::kVermeulenJohnson || law_ == SaturationLaw::kNone) {
    out.moment_z = factor * lin.moment_z;  // spin ignored (coupling term only) or linear
  } else {
    // Creepage-only utilisation: the law at the linear force of (xi_x, xi_y).
    const TangentialSolution creep = k.forces({cr.longitudinal, cr.lateral, 0.0});
    const double u = saturation_ratio(law_, std::hypot(creep.force_x, creep.force_y) / limit);
    out.moment_z = saturated_spin_moment(k, cr, factor, limit, u);
  }
  if (!spin_moment_) out.moment_z = 0.0;
  return out;
}

std::unique_ptr<TangentialModel> SaturatedCreepModel::from_options(SaturationLaw law,
                                                                   const ModelOptions& options) {
  const SaturatedCreepModel probe(law, CoefficientSource::kKalkerTable);
  check_option_keys(probe.name(), options, {"coefficients", "spin_moment"});
  const std::string spin = option_string(options, "spin_moment", "true");
  if (spin != "true" && spin != "false") {
    throw std::invalid_argument(fmt::format(
        "{} option 'spin_moment': unknown value '{}'; allowed: true, false", probe.name(), spin));
  }
  return std::make_unique<SaturatedCreepModel>(law, coefficients_option(options), spin == "true");
}

}  // namespace ferro::contact
