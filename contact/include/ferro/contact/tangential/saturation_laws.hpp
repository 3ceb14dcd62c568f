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
// Spin moment (none of these laws defines one): M_z = the coupling term G (ab)^1.5 C23 xi_y scaled
// by the force factor F_t/F_t,linear, plus the spin term -G (ab)^2 C33 phi saturated on its own
// full-slip limit (saturated_spin_moment): M_s,full = mu F_n (3/32) P(a, b), P the perimeter of
// the ellipse (the moment of Coulomb tractions mu p circling the centre of a Hertzian patch,
// mu F_n 3 pi a / 16 on a circle), with the cubic 1 - (1 - t/3)^3 of t = |M_s,lin| / M_s,full,
// times sqrt(1 - u^2), u = the law's force fraction for xi_x, xi_y alone (full slip under
// creepage leaves no spin moment).
// Known deviations: the spin-moment saturation is an approximation of this library (no published
// law defines one), checked against MIM in `ferrodyn bench contact` (M_z column); vermeulen_johnson
// ignores spin altogether, so its moment is only the C23 xi_y coupling term, scaled. For
// non-elliptic patches the equivalent ellipse a, b is used.

#include "ferro/contact/tangential/tangential_model.hpp"

namespace ferro::contact {

enum class SaturationLaw { kNone, kLinear, kVermeulenJohnson, kShenHedrickElkins, kChopaya };

/// F_t/(mu F_n) as a function of the reduced creepage xi_t >= 0.
[[nodiscard]] double saturation_ratio(SaturationLaw law, double reduced_creepage);

/// Full-slip spin moment of a Hertzian patch a x b: mu F_n (3/32) x perimeter of the ellipse [N m].
[[nodiscard]] double full_slip_spin_moment(double semi_axis_x, double semi_axis_y, double mu_fn);

/// M_z of the linear theory with its spin term -G (ab)^2 C33 phi saturated on
/// full_slip_spin_moment and reduced by sqrt(1 - u^2), u = creep_utilisation (the model's
/// |F_t| / (mu F_n) for the creepages xi_x, xi_y alone: a patch in full slip under creepage
/// carries no spin moment), and its coupling term G (ab)^1.5 C23 xi_y scaled by force_factor
/// (F_t/F_t,linear of the model) [N m].
[[nodiscard]] double saturated_spin_moment(const LinearCreepStiffness& k, const Creepage& creepage,
                                           double force_factor, double mu_fn,
                                           double creep_utilisation);

/// Kalker's linear theory saturated by a law: the models "linear_saturated",
/// "vermeulen_johnson", "shen_hedrick_elkins", "chopaya". Options: "coefficients", "spin_moment"
/// = true (default) | false.
class SaturatedCreepModel final : public TangentialModel {
 public:
  static std::unique_ptr<TangentialModel> from_options(SaturationLaw law,
                                                       const ModelOptions& options);
  /// `spin_moment` false: no moment about the contact normal (a source model that neglects it,
  /// as DYTSI's Shen-Hedrick-Elkins law does); the forces are unchanged.
  SaturatedCreepModel(SaturationLaw law, CoefficientSource source, bool spin_moment = true)
      : law_(law), source_(source), spin_moment_(spin_moment) {}
  [[nodiscard]] std::string_view name() const override;
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;

 private:
  SaturationLaw law_;
  CoefficientSource source_;
  bool spin_moment_ = true;
};

}  // namespace ferro::contact
