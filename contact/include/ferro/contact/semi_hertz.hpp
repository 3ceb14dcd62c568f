#pragma once
// Semi-Hertzian normal contact (Ayasse & Chollet): strips parallel to the rolling direction
// cut from a virtual interpenetration of the undeformed gap z(y), with the longitudinal
// curvature compensated so that a quadratic gap reproduces the Hertz ellipse.
//
// References: Ayasse & Chollet, Vehicle System Dynamics 43 (2005) 161-172; Toumi (2016)
// eqs. (17)-(23).
// Known deviations: (1) the compensated curvature A_c = B_ref (b/a)^2 (eqs. 18-19) and the
// pressure-to-half-length ratio p0_i / a_i = p_max / a are those of the reference Hertz ellipse
// built on one transverse curvature B_ref of the gap: a least-squares parabola over the deepest
// lobe (option curvature = fit, default) or the 3-point parabola at the deepest sample
// (three_point); a local (per strip) compensation is not implemented. (2) The virtual penetration
// h0 is found from the load, F_n = (pi/2) sum p0_i a_i dy, rather than from delta through eq. (21);
// for a quadratic gap both give h0 = b^2 B exactly. (3) Disconnected lobes are returned as separate
// patches, each with an equivalent ellipse a = max a_i, b = half its lateral extent.

#include "ferro/contact/normal_model.hpp"

namespace ferro::contact {

struct SemiHertzOptions {
  /// How the reference transverse curvature B_ref is taken from the gap samples: "fit" (default)
  /// = least-squares parabola over the deepest lobe (robust to sampling noise), "three_point" =
  /// second divided difference at the deepest sample.
  enum class Curvature { kFit, kThreePoint };
  int strips = 200;  ///< number of strips across the penetrated region [-]
  Curvature curvature = Curvature::kFit;
  void validate() const;
};

[[nodiscard]] NormalSolution semi_hertz_solve(const NormalProblem& problem,
                                              const SemiHertzOptions& options);

}  // namespace ferro::contact
