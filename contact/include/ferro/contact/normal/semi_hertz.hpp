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
// semi_hertz_solve_from_approach() is driven by the rigid approach delta instead (the dynamics,
// where the penetration is known): h0 = delta n^2 / (r (1 + lambda)), eq. (21) read the other way,
// and the load is what the strips carry; for the same B_ref the two entry points are inverse to
// each other, and on a quadratic gap both give Hertz.

#include "ferro/contact/normal/normal_model.hpp"

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

/// Buffers of semi_hertz_solve_from_approach(), reused from call to call.
struct SemiHertzWorkspace {
  std::vector<double> strip_gap;  ///< relative gap at the strip centres [m]
  std::vector<double> weight;     ///< weights of the lobe fit [-]
};

/// Semi-Hertz patches for a rigid approach delta = `approach` [m] (>= 0) instead of a load;
/// problem.normal_force is not read. The reference Hertz ellipse is the one of (A, B_ref) at that
/// approach, h0 = delta n^2 / (r (1 + lambda)) (eq. 21), and each patch's normal_force is the load
/// its strips carry. B_ref (curvature = fit): starts from the larger of problem.curvature_y (when
/// given) and the curvature of the samples around the minimum (so that it stays continuous where
/// a caller's curvature passes through zero, a nearly conformal point), then two passes of a least-squares parabola over
/// the lobe at h0 weighted by (h0 - z) / h0, so that B_ref and the load are continuous in the
/// approach and the gap (the unweighted lobe fit of semi_hertz_solve() jumps as samples enter
/// the lobe, which an integrator's right-hand side must not do); on a quadratic gap both fits
/// give its B exactly. Writes `out` (out.approach = delta; no patch when delta = 0), reusing the
/// storage of its patches and strips and of `work`: no allocation once they have grown. Throws
/// std::invalid_argument as semi_hertz_solve() does.
void semi_hertz_solve_from_approach(const NormalProblem& problem, double approach,
                                    const SemiHertzOptions& options, SemiHertzWorkspace& work,
                                    NormalSolution& out);

}  // namespace ferro::contact
