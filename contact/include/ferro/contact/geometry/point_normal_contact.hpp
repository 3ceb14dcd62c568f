#pragma once
// Normal contact of one point of a contact geometry source: the Hertz patch from the point's
// penetration (through the one Hertz implementation of hertz.hpp or, for imported tables, the
// point's reference Hertz state), or the semi-Hertz patches of the profiles' gap around a point
// of a source with profiles (table, search).
//
// References: Toumi (2016) eqs. (5)-(13) (Hertz), (17)-(23) (semi-Hertz); Johnson, "Contact
// Mechanics" (1985) eqs. (3.64)-(3.72); Ayasse & Chollet, Vehicle System Dynamics 43 (2005)
// 161-172.
// Known deviations: see each function.

#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/contact/material.hpp"
#include "ferro/contact/normal/contact_patch.hpp"
#include "ferro/contact/normal/normal_model.hpp"
#include "ferro/contact/normal/semi_hertz.hpp"

namespace ferro::contact {

/// Normal contact of one point from its penetration (WheelRailContact::penetration [m]):
/// - with a reference state (imported tables): F_n = F0 (d/d0)^1.5, a = a0 (F_n/F0)^(1/3),
///   b = b0 (F_n/F0)^(1/3), p0 = 3 F_n / (2 pi a b); contact_modulus is not used;
/// - otherwise from the curvatures A, B through hertz_solve_from_approach() (exact Hertz,
///   conformal/negative curvature treated as hertz_curvatures() documents), E* = contact_modulus
///   [Pa].
/// penetration <= 0 (wheel lift): F_n = 0, a = b = p0 = 0 (no tangential model must be called).
/// The patch carries approach = penetration and the curvatures used (NaN for reference states).
/// No allocation; about 0.1 us. Throws std::invalid_argument on NaN input (field named).
[[nodiscard]] ContactPatch hertz_patch_from_penetration(const WheelRailContact& contact,
                                                        double contact_modulus);

/// Buffers of semi_hertz_patches_from_penetration(), reused from call to call (one per thread).
struct SemiHertzScratch {
  NormalProblem problem;
  SemiHertzWorkspace work;
  NormalSolution solution;
  std::vector<double> left, right;  ///< gap samples either side of the point [m]
};

/// Semi-Hertz normal contact of one point of a profile-based source (pair, pose: the ones the
/// source answered for). The undeformed gap along the normal of the point's contact plane
/// (inclined by its contact angle; ContactPlaneGap, in the wheel section through the point) is
/// sampled outwards from the point every b/16 (b: the point's Hertz semi-axis, step kept in
/// [2 um, 0.25 mm]) until, on each side, the gap exceeds its lowest value by 1.1 penetrations,
/// a profile ends, or the gap rises and falls again by more than 1 um (a barrier: the next local
/// minimum is another point of the source, so each point keeps its own basin and a joined run is
/// split at its barrier). semi_hertz_solve_from_approach() then gives the patches (usually one;
/// strips, equivalent ellipse, load) at the point's penetration, with A = the point's
/// curvature_a and its curvature_b as the caller's first estimate of B_ref; each patch carries
/// approach = penetration. Returns scratch.solution (no patch
/// when penetration <= 0). No allocation once the scratch buffers have grown. Throws
/// std::invalid_argument on NaN penetration and where semi_hertz_solve() does (e.g. the basin's
/// minimum on a profile end), std::runtime_error where a profile ends at the point.
/// Known deviations: the gap is that of the wheel section through the point (x = 0; the
/// longitudinal curvature is the point's A, eq. 17); the point keeps the position, normal and
/// creepages the source gives (the patch centre's offset from the point, y_center, is not
/// applied).
[[nodiscard]] NormalSolution& semi_hertz_patches_from_penetration(
    const WheelRailPair& pair, const WheelsetPose& pose, const WheelRailContact& contact,
    const Material& material, const SemiHertzOptions& options, SemiHertzScratch& scratch);

}  // namespace ferro::contact
