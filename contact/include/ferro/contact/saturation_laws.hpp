#pragma once
// Kalker's linear theory and the saturation laws applied to its forces.
//
// References: Kalker (1967) linear theory, Toumi (2016) eqs. (38)-(40), (49)-(52), (155);
// Vermeulen & Johnson, J. Appl. Mech. 31 (1964) 338-340; Shen, Hedrick & Elkins, VSD 12 (1983)
// 79-83; CHOPAYA: Ayasse, Chollet & Maupu, INRETS report 225 (2000), Toumi eq. (155).
// Reduced creepages (eq. 50) xi_bar = F_linear / (mu F_n), xi_t = |xi_bar|:
//   linear_saturated   F_t/(mu F_n) = min(xi_t, 1)                          (eq. 49)
//   vermeulen_johnson  F_t/(mu F_n) = 1 - (1 - xi_t/3)^3 for xi_t < 3, else 1, spin ignored (51)
//   shen_hedrick_elkins  the same cubic on the linear force including spin
//   chopaya            F_t/(mu F_n) = 1 - exp(-xi_t)                        (eqs. 52/155)
// The saturated force keeps the direction of the linear force.
// Known deviations: M_z is the linear-theory moment scaled by the same factor F_t/F_t,linear
// (none of these laws defines a spin moment); vermeulen_johnson ignores spin altogether, so its
// moment is only the C23 xi_y coupling term, scaled. For non-elliptic patches the equivalent
// ellipse a, b is used.

#include "ferro/contact/tangential_model.hpp"

namespace ferro::contact {

enum class SaturationLaw { kNone, kLinear, kVermeulenJohnson, kShenHedrickElkins, kChopaya };

/// F_t/(mu F_n) as a function of the reduced creepage xi_t >= 0.
[[nodiscard]] double saturation_ratio(SaturationLaw law, double reduced_creepage);

class SaturatedCreepModel final : public TangentialModel {
 public:
  SaturatedCreepModel(SaturationLaw law, CoefficientSource source) : law_(law), source_(source) {}
  [[nodiscard]] std::string_view name() const override;
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;

 private:
  SaturationLaw law_;
  CoefficientSource source_;
};

}  // namespace ferro::contact
