#pragma once
// FaStrip: strip theory for the creepages, with Kalker's linear coefficients fixing its creepage
// scale, and FASTSIM's spin traction, on an elliptic patch (mx x my) or on the strips of a
// semi-Hertz patch.
//
// References: Sichani, Enblom & Berg, "An alternative to FASTSIM for tangential solution of the
// wheel-rail contact", Vehicle System Dynamics 54 (2016) 748-764, and "A fast wheel-rail contact
// model for application to damage analysis in vehicle dynamics simulation", Wear 366-367 (2016)
// 123-130 (FaStrip); Haines & Ollerton, Proc. IMechE 177 (1963) 95-114 and Kalker (1967) (strip
// theory: each strip y is Carter's two-dimensional rolling problem under the Hertzian traction
// bound mu p0(y) sqrt(1 - x^2/a(y)^2)); Carter, Proc. R. Soc. A 112 (1926) 151-157; Kalker (1982)
// and Toumi (2016) eq. (44) for the spin flexibility L3 = pi a^2 / (4 G sqrt(ab) C23).
// Model: per strip the creepage traction is Carter's: the Hertzian traction bound minus the
// ellipse over the adhesion zone of half-length a'(y) = a(y) (1 - tau(y)) at the leading edge,
// along w(y) = G a b (C11 (xi_x - phi y), C22 xi_y) / (2 mu F_n). Carter's saturation creepage is
// proportional to the strip's own peak pressure, so tau(y) = |w(y)| T / p0(y), with T fixed so
// that the strips' linear forces 2 mu P(y) tau(y) sum to 2 mu F_n |w|: the slopes at zero
// creepage are Kalker's G a b C11 and G a b C22 exactly (FaStrip's use of Kalker's coefficients).
// The lateral spin slip phi x enters as FASTSIM's traction increment (phi / L3) x dx; past the
// creepages' adhesion zone the creepage increments are FASTSIM's rigid-slip ones with one
// flexibility for both components (option slip_flexibility: longitudinal = L1, the default;
// weighted = Kalker's creepage-weighted L; three = L1 and L2), which turn the traction towards
// the rigid slip (xi_x - phi y, xi_y + phi x); the sum is bounded by mu p element by element
// (FASTSIM's cap), so |F| <= mu F_n always. The first element past the adhesion zone blends
// Carter's value (the bound) into that update by how close the zone's end lies to its leading
// edge, so the forces are continuous in the creepages.
// Discretisation: pressures and Carter's adhesion-zone tractions are exact element averages (the
// ellipse integrals in closed form); across the strips the loads, the Carter scale T and the
// spin flexibility are normalised on the midpoint sums over y, so F_n and Kalker's C11, C22 and
// C23 slopes are exact at any grid.
// Known deviations: the combination of the strip-theory creepage traction with FASTSIM's spin
// traction, and the single slip-zone flexibility, are this library's reading of FaStrip (not a
// transcription of the published algorithm); the default slip_flexibility = longitudinal was
// chosen among the three by comparison with converged MIM (`ferrodyn bench contact`; see
// docs/PERFORMANCE.md), so that comparison is not fully independent. Without spin the model is
// Carter's strip solution only where a strip's slip zone lies under a falling bound (tau <= 1/2,
// and to O(dx) after the element that ends the adhesion zone): elsewhere FASTSIM's update lags
// the rising bound, which lowers the transition force (closer to converged MIM than strip
// theory itself: 0.009 against 0.010 mu F_n mean without spin at 12 x 12). The moment M_z is the
// model's own (it does not reproduce C33). On semi-Hertz strips the Carter scale comes from each
// strip's own p0_i and the spin flexibility from the equivalent ellipse, without the y correction.

#include <vector>

#include "ferro/contact/tangential/tangential_model.hpp"

namespace ferro::contact {

/// Flexibility of the creepage increments past Carter's adhesion zone (see the file comment).
enum class SlipFlexibility { kLongitudinal, kWeighted, kThree };

struct FastripOptions {
  int mx = 12;  ///< elements along each strip [-]
  int my = 12;  ///< strips across the ellipse (semi-Hertz patches keep their strips) [-]
  SlipFlexibility slip_flexibility = SlipFlexibility::kLongitudinal;
  CoefficientSource source = CoefficientSource::kKalkerTable;
  void validate() const;
};

/// The model "fastrip". Options: "coefficients", "mx", "my" (default 12, 12),
/// "slip_flexibility" = longitudinal (default) | weighted | three.
class FastripModel final : public TangentialModel {
 public:
  static std::unique_ptr<TangentialModel> from_options(const ModelOptions& options);
  explicit FastripModel(FastripOptions options);
  [[nodiscard]] std::string_view name() const override { return "fastrip"; }
  [[nodiscard]] TangentialSolution solve(const TangentialProblem& problem) const override;

 private:
  FastripOptions options_;
  std::vector<double> shape_;  ///< mean of sqrt(1 - s^2) over each element of [-1, 1]
};

}  // namespace ferro::contact
