// Saturation laws on Kalker's linear forces. See saturation_laws.hpp for references and
// known deviations.
#include "ferro/contact/saturation_laws.hpp"

#include <cmath>

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
  out.moment_z = factor * lin.moment_z;
  return out;
}

}  // namespace ferro::contact
