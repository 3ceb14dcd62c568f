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
// Options: bound = parabolic (the simplified theory's, default) | elliptic (Hertz: the traction
// bound mu p0 sqrt(1 - x^2/a^2 - y^2/b^2)); flexibility = three (L1, L2, L3, default) | weighted
// (one L) | adaptive (L1, L2, L3 divided by 1 + c tau^2, tau = |F_linear| / (mu F_n) the reduced
// creepage of the linear theory with spin, capped at tau = 3, c = kAdaptiveStiffening = 0.05).
// The adaptive flexibility keeps the linear slopes (d/dtau of the factor is 0 at tau = 0) and the
// full-slip limit, and stiffens the transition, where under the parabolic bound every strip
// follows 1 - (1 - u)^3 while the full theory is closer to Carter's 1 - (1 - u)^2.
// Discrete load: the element pressures are scaled so that their midpoint sum equals F_n exactly
// (strip by strip along x, over the strips across y), so the full-slip force is mu F_n and never
// above it (the unscaled midpoint sum exceeds F_n by about 1/(2 mx^2) + 1/(2 my^2)).
// Known deviations: tractions are evaluated at element centres, the rigid-slip increment between
// two centres being integrated exactly (so adhesion tractions are exact in x and the linear
// slopes F_x/xi_x, F_y/xi_y, F_y/phi converge as 1/(2 my^2)); the moment M_z is FASTSIM's own
// (it does not reproduce C33 or the C23 in M_z, a property of the simplified theory); for
// semi-Hertz strips the flexibilities come from the patch's equivalent ellipse. The adaptive
// flexibility is a one-parameter fit of this library to converged MIM (pure creepage at a/b = 1,
// nu = 0.28), not the published modified FASTSIM (Vollebregt & Wilders 2011) or FaStrip (Sichani,
// Enblom & Berg 2016); it does not correct FASTSIM's spin force in the transition (too large by
// up to ~0.08 mu F_n at a/b = 1). The elliptic bound stiffens the micro-slip range and softens
// the approach to full slip (worse than the parabola against the full theory; kept for study).

#include "ferro/contact/tangential/tangential_model.hpp"

namespace ferro::contact {

/// kThree: L1, L2, L3 of eq. (44); kWeighted: one creepage-weighted L; kAdaptive: L1, L2, L3
/// divided by 1 + kAdaptiveStiffening tau^2, tau = |F_linear| / (mu F_n) the reduced creepage
/// (see the file comment).
enum class Flexibility { kThree, kWeighted, kAdaptive };

/// Stiffening of the adaptive flexibility, fitted to converged MIM (pure creepage, a/b = 1,
/// nu = 0.28; `ferrodyn bench contact`): FASTSIM's transition, 1 - (1 - u)^3 per strip under the
/// parabolic bound, is softer than the full theory's.
inline constexpr double kAdaptiveStiffening = 0.05;

/// Traction bound mu p along each strip: the simplified theory's parabola (Kalker 1982) or the
/// Hertzian half-ellipse p0 sqrt(1 - x^2/a^2 - y^2/b^2).
enum class TractionBound { kParabolic, kElliptic };

/// Sums of a strip-by-strip traction integration (FASTSIM and its strip-theory relatives).
struct StripSums {
  double fx = 0.0, fy = 0.0, mz = 0.0;     ///< [N], [N], [N m]
  double area = 0.0, adhesion_area = 0.0;  ///< [m^2]
  /// Adds one strip: element sums of the tractions (and of x p_y - y p_x), its element count and
  /// adhering elements, times the element area da.
  void add_strip(double sum_px, double sum_py, double sum_moment, double elements, double adhering,
                 double da) {
    fx += sum_px * da;
    fy += sum_py * da;
    mz += sum_moment * da;
    area += elements * da;
    adhesion_area += adhering * da;
  }
  [[nodiscard]] TangentialSolution solution() const {
    TangentialSolution out;
    out.force_x = fx;
    out.force_y = fy;
    out.moment_z = mz;
    out.adhesion_fraction = area > 0.0 ? adhesion_area / area : ContactPatch::kNaN;
    return out;
  }
};

/// Checks a strip grid (mx elements along each of my strips, both in [1, 10000]); the message
/// names `model`.mx / `model`.my.
void validate_strip_grid(const char* model, int mx, int my);

struct FastsimOptions {
  int mx = 20;  ///< elements along each strip [-]
  int my = 20;  ///< strips across the ellipse (semi-Hertz patches keep their strips) [-]
  Flexibility flexibility = Flexibility::kThree;
  TractionBound bound = TractionBound::kParabolic;
  double stiffening = kAdaptiveStiffening;  ///< kAdaptive only: c in L / (1 + c tau^2) [-]
  CoefficientSource source = CoefficientSource::kKalkerTable;
  void validate() const;
};

/// The model "fastsim". Options: "coefficients", "mx", "my" (default 20, 20), "flexibility" =
/// three (default) | weighted | adaptive, "stiffening" (adaptive, default 0.05, in [0, 1]),
/// "bound" = parabolic (default) | elliptic.
class FastsimModel final : public TangentialModel {
 public:
  static std::unique_ptr<TangentialModel> from_options(const ModelOptions& options);
  explicit FastsimModel(FastsimOptions options);
  [[nodiscard]] std::string_view name() const override { return "fastsim"; }
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;

 private:
  FastsimOptions options_;
};

}  // namespace ferro::contact
