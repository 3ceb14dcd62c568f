#pragma once
// FASTSIM, Kalker's simplified theory of rolling contact, on an elliptic patch (mx x my grid)
// or on the strips of a semi-Hertz patch.
//
// References: Kalker, "A fast algorithm for the simplified theory of rolling contact", VSD 11
// (1982) 1-13; Toumi (2016) eqs. (41)-(46). Flexibilities L1 = 8a/(3 C11 G),
// L2 = 8a/(3 C22 G), L3 = pi a^2/(4 G sqrt(ab) C23) (eq. 44) with C_ij,r = K_ij C_ij; weighted
// single flexibility L = (|xi_x| L1 + |xi_y| L2 + c |phi| L3)/sqrt(xi_x^2 + xi_y^2 + c^2 phi^2),
// c = sqrt(ab). Parabolic pressure p = 2F/(pi a b) (1 - x^2/a^2 - y^2/b^2) (simplified theory);
// on semi-Hertz strips each strip gets the parabola with its own load,
// p = (3 pi/8) p0_i (1 - (x - xc)^2/a_i^2).
// Rolling: material passes through the patch from the leading edge x = +a(y) to the trailing edge
// x = -a(y) (the wheel rolls towards +x); adhesion is at the leading edge.
// Known deviations: tractions are evaluated at element centres, the rigid-slip increment between
// two centres being integrated exactly (so adhesion tractions are exact in x and the linear
// slopes F_x/xi_x, F_y/xi_y, F_y/phi converge as 1/(2 my^2)); the moment M_z is FASTSIM's own
// (it does not reproduce C33 or the C23 in M_z, a property of the simplified theory); for
// semi-Hertz strips the flexibilities come from the patch's equivalent ellipse.

#include "ferro/contact/tangential_model.hpp"

namespace ferro::contact {

enum class Flexibility { kThree, kWeighted };

struct FastsimOptions {
  int mx = 20;  ///< elements along each strip [-]
  int my = 20;  ///< strips across the ellipse (semi-Hertz patches keep their strips) [-]
  Flexibility flexibility = Flexibility::kThree;
  CoefficientSource source = CoefficientSource::kKalkerTable;
  void validate() const;
};

class FastsimModel final : public TangentialModel {
 public:
  explicit FastsimModel(FastsimOptions options);
  [[nodiscard]] std::string_view name() const override { return "fastsim"; }
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;

 private:
  FastsimOptions options_;
};

}  // namespace ferro::contact
