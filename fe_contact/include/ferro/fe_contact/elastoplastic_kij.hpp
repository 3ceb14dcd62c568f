#pragma once
// K_ij of a wheel on an elasto-plastic rail as a range, first pass to shaken down, each the ratio
// of initial creep-curve slopes against the half-space pair on the same MIM grid:
// - first pass: the rail under the peak load of its first cycle, its tangential compliance that
//   of the yielded rail (hertz_load_cycle's frozen elasto-plastic tangent, as a correction to the
//   half-space: the FE tangent minus the same mesh elastic, so the FE discretisation cancels);
// - shaken down: after unloading the rail responds elastically about its residual state (checked:
//   no plastic flow during unloading, so reloading retraces the unloading path), its compliance
//   is the elastic one and only its geometry has changed: the residual groove is added to the gap.
//   A rolling pass leaves a groove invariant along the rail; we take the cross-section of the
//   stationary cycle's residual dent through the patch centre as its profile. This run needs no
//   FE coefficients, so it takes the contact case's finer grid (HertzCase::elements_minor,
//   margin; widened by rows of the same size while the grooved patch reaches its boundary), on
//   which the FE dent is interpolated: a groove of a few um changes the patch by less than one
//   element of the FE-cell grid.
// The wheel is an elastic half-space in both. Why this method: the initial creep slope is that of
// full adhesion at vanishing creepage, i.e. an incremental problem about the loaded state, so the
// only compliance that enters is the rail's tangent compliance there; freezing the plastic state
// and taking every flowing point as loading gives the softest first-pass response (a lower
// bound of the first-pass K); once the cycle has shaken down the increments about the residual
// state are elastic (Melan), so only the changed geometry remains.
//
// References: Toumi (2016) section 3.3 (elasto-plastic rail, K11ep = 0.63, K22ep = 0.46 against
// Kalker's C_ij with the elastic FE model at 0.72 / 0.56; R900A, 350HT; Table 3.9), eqs. (146)-
// (147); Johnson, "Contact Mechanics" (1985) sections 9.2-9.3 (first pass, residual stresses,
// elastic shakedown of a repeated stationary or rolling load); Melan's static shakedown theorem.
// Known deviations: the normal problem of both bounds uses the elastic half-space compliance (the
// pressure does not redistribute as the rail yields: the thesis's p_max is 5-18 % below the
// elastic Hertz peak at 7.5-15 t); the first
// pass takes the stationary load's yielded zone and every flowing point as loading (see
// elastoplastic.hpp), not the asymmetric zone of a rolling load; the wheel stays elastic (in the
// thesis both are R900A); the groove's depth is that of the stationary cycle (a rolling pass
// ratchets more); hardening as in elastoplastic.hpp.

#include "ferro/contact/mim/grid.hpp"
#include "ferro/fe_contact/creep_slopes.hpp"
#include "ferro/fe_contact/elastoplastic.hpp"
#include "ferro/fe_contact/hertz_case.hpp"

namespace ferro::fe_contact {

struct ElastoplasticKijSpec {
  /// Load, Hertz patch (scaled from its reference), wheel and rail steel elasticity, friction;
  /// elements_minor and margin give the shaken-down run's grid (the first pass runs on the FE
  /// mesh's surface cells).
  HertzCase contact;
  double yield_stress = kNaN;      ///< rail sigma_y [Pa]
  double hardening_modulus = 0.0;  ///< rail H [Pa] (see RailSteel)
  int elements_per_semi_axis = 4;  ///< FE cells and grid elements across min(a, b) [-]
  int load_steps = 6;              ///< equal load increments up to p0 [-]
  int unload_steps = 0;            ///< equal decrements to zero (0: load_steps) [-]
  double growth = 1.6;             ///< FE cell growth outside the grid [-]
  double extent = 12.0;            ///< FE block half-size over max(a, b) [-]
  void validate(const std::string& where = "ElastoplasticKijSpec") const;
};

struct ElastoplasticKij {
  ElastoplasticResult cycle;  ///< the load-unload cycle (Table 3.9 quantities)
  contact::mim::Grid grid;       ///< first-pass grid (the FE surface cells)
  contact::mim::Grid fine_grid;  ///< shaken-down grid (the contact case's, widened if needed)
  SlopeResult first_pass;   ///< yielded rail under load (frozen tangent) vs half-space
  SlopeResult shaken_down;  ///< elastic rail with the residual dent vs half-space (same F_n)
  double cpu_seconds = 0.0;  ///< whole computation [s]
};

/// Runs the cycle and the four MIM slope computations. Throws std::invalid_argument for bad
/// input and std::runtime_error when the FE Newton iterations do not converge.
[[nodiscard]] ElastoplasticKij elastoplastic_reduction_factors(const ElastoplasticKijSpec& spec,
                                                               const SlopeOptions& options = {});

}  // namespace ferro::fe_contact
