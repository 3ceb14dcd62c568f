#pragma once
// Polach's creep-force model with the reduction parameters k_A, k_S.
//
// References: Polach, "A fast wheel-rail forces calculation computer code", VSD 33 Suppl.
// (1999) 728-739; Polach, "Creep forces in simulations of traction vehicles running on adhesion
// limit", Wear 258 (2005) 992-1000.
//   eps = (2/3) C pi a^2 b s / (Q mu),  C = 3 G c_jj / (8 a),  c_jj = sqrt((C11 sx/s)^2 + (C22
//   sy/s)^2) F = (2 Q mu / pi) (k_A eps / (1 + (k_A eps)^2) + atan(k_S eps)),  F_x,y = -F s_x,y / s
//   spin: s_yc = s_y + phi a if |s_y + phi a| > |s_y| else s_y, eps_psi =
//   (8/3) G b sqrt(ab) C23 s_c / (Q mu (1 + 6.3 (1 - exp(-a/b)))), delta =
//   (eps_psi^2-1)/(eps_psi^2+1), K_M = |eps_psi| (delta^3/3 - delta^2/2 + 1/6) - sqrt((1 -
//   delta^2)^3)/3, F_yS = -(9/16) a Q mu K_M (1 + 6.3 (1 - exp(-a/b))) phi / s_c. friction falling
//   with the slip speed w = V s (Polach 2005): mu = mu0 ((1 - A) exp(-B w) + A), mu0 = the
//   problem's friction, A = friction_ratio (mu_inf/mu0), B = friction_decay [s/m].
// With k_A = k_S = 1 the initial slopes equal Kalker's linear theory (times K_ij); in general
// they are (k_A + k_S)/2 of it. The falling branch of traction curves comes from A < 1, B > 0.
// Known deviations: s = sqrt(xi_x^2 + s_yc^2) uses the spin-corrected lateral creepage; M_z (the
// model gives none) is the coupling term of Kalker's linear moment scaled by F/F_linear plus the
// saturated spin moment of saturation_laws.hpp. Guard where the published spin term fails: with
// the spin opposing s_y and |phi a| > |s_y| (s_y + phi a changes sign, s_c becomes small and
// F_yS alone exceeds mu Q: at a/b = 5 it gives F_y = -0.77 mu Q where the full theory gives
// +0.08), the forces and moment are FASTSIM's (10 x 10, three flexibilities, same K_ij, the
// friction of the speed law at the slip speed V |(s_x, s_y)|). The sum of creep and spin forces is
// bounded by mu Q.

#include "ferro/contact/tangential/tangential_model.hpp"

namespace ferro::contact {

struct PolachOptions {
  double k_a = 1.0;             ///< reduction in the adhesion area [-], 0 < k_A <= 1
  double k_s = 1.0;             ///< reduction in the slip area [-], 0 < k_S <= 1
  double friction_ratio = 1.0;  ///< A = mu_inf / mu0 [-], in (0, 1]
  double friction_decay = 0.0;  ///< B [s/m], >= 0 (needs TangentialProblem::rolling_speed if > 0)
  CoefficientSource source = CoefficientSource::kKalkerTable;
  void validate() const;
};

/// The model "polach". Options: "coefficients", "k_a", "k_s" (default 1), "friction_ratio" (A,
/// default 1), "friction_decay" (B [s/m], default 0).
class PolachModel final : public TangentialModel {
 public:
  static std::unique_ptr<TangentialModel> from_options(const ModelOptions& options);
  explicit PolachModel(PolachOptions options);
  [[nodiscard]] std::string_view name() const override { return "polach"; }
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;

 private:
  PolachOptions options_;
};

}  // namespace ferro::contact
