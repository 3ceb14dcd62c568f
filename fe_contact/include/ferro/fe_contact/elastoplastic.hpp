#pragma once
// Elasto-plastic rail head under a Hertzian wheel load: a J2 (von Mises) finite-element model of
// the rail steel (small strain, linear isotropic hardening, backward-Euler return mapping;
// GetFEM's small-strain elastoplasticity brick, Newton iterations) loaded on its top face by
// the Hertz pressure p = p0 sqrt(1 - x^2/a^2 - y^2/b^2) in load steps and unloaded again:
// plastic strain, the surface displacement under load and the residual displacement. On request
// (a MIM grid whose elements are the mesh's surface cells), the tangential surface compliance of
// the loaded, yielded rail (continuum elasto-plastic tangent with the plastic state of the peak
// load frozen: D_ep = D - 6 G^2 / (3 G + H) n (x) n at the points flowing in the last load
// step, n the unit stress deviator) minus that of the same mesh elastic, and the residual dent
// at the grid-element centres.
//
// References: Toumi (2016) section 3.3 (elasto-plastic rail, R900A sigma_y = 489 MPa, 350HT
// 750.7 MPa, Table 3.9 loads 7.5 / 11.25 / 15 t); Johnson, "Contact Mechanics" (1985) eq. (3.45)
// (Hertz stresses on the axis of a circular contact) and section 6.2 (first yield
// p0 = 1.60 sigma_y for nu = 0.3); Simo & Hughes, "Computational Inelasticity" (1998) ch. 3
// (radial return); Renard & Poulios, GetFEM, ACM TOMS 47 (2021).
// Known deviations: the load is the prescribed elastic Hertz pressure of a stationary wheel
// (no contact solve: the pressure does not redistribute as the rail yields, and the moving load
// of a first pass is replaced by one load-unload cycle); the rail head is a large block (the
// half-space of the Hertz theory) with a clamped bottom; hardening is linear (the thesis's
// nonlinear tensile curves of its annex C are not tabulated in its text); the tangential
// compliance of the yielded rail is the continuum tangent at the peak of the stationary load
// with every flowing point taken as loading (no elastic unloading of points the tangential
// increment relieves: the softest first-pass response); the tangent's hardening term takes H as
// GetFEM's isotropic modulus Hi (exact for perfect plasticity, H = 0, the runs of Table 3.9);
// trilinear hexahedra with full integration (prone to volumetric locking under isochoric
// plastic flow: a stiffer plastic response).

#include <string>

#include "ferro/contact/material.hpp"
#include "ferro/contact/mim/grid.hpp"
#include "ferro/fe_contact/creep_slopes.hpp"
#include "ferro/fe_contact/matrix_operator.hpp"

namespace ferro::fe_contact {

/// Rail steel: elasticity, von Mises yield stress and linear isotropic hardening.
struct RailSteel {
  contact::Material elastic;
  double yield_stress = kNaN;      ///< sigma_y (uniaxial) [Pa]
  double hardening_modulus = 0.0;  ///< H, d sigma_y / d(equivalent plastic strain) [Pa]
  void validate(const std::string& where = "RailSteel") const;
};

/// Hertzian pressure on the rail and the mesh of the block that carries it.
struct HertzLoadCase {
  double semi_axis_x = kNaN;       ///< a (rolling direction) [m]
  double semi_axis_y = kNaN;       ///< b [m]
  double peak_pressure = kNaN;     ///< p0 [Pa]
  int elements_per_semi_axis = 6;  ///< trilinear cells across min(a, b) [-]
  double growth = 1.6;             ///< size ratio of successive cells outside the patch [-]
  double extent = 12.0;            ///< block half-size in units of max(a, b) [-]
  int load_steps = 4;              ///< equal load increments up to p0 [-]
  /// Equal decrements back to zero; 0: as many as load_steps. One is exact when the unloading
  /// is elastic (ElastoplasticResult::reverse_flowing_points == 0) [-].
  int unload_steps = 0;
  /// Grid of the rail compliance: its elements are the mesh's surface cells (centred, even nx
  /// and ny so that the patch centre is a node); nx == 0: no compliance, the mesh has cells of
  /// min(a, b) / elements_per_semi_axis over 1.25 a x 1.25 b.
  contact::mim::Grid compliance_grid;
  /// Grid on whose element centres the residual dent is sampled (any grid inside the mesh's
  /// surface; the FE field is interpolated); nx == 0: the compliance grid.
  contact::mim::Grid dent_grid;
  void validate(const std::string& where = "HertzLoadCase") const;
  /// Normal force of the Hertz pressure, 2 pi a b p0 / 3 [N].
  [[nodiscard]] double normal_force() const;
};

struct ElastoplasticResult {
  double peak_pressure = kNaN;          ///< p0 applied [Pa]
  double displacement_loaded = kNaN;    ///< u_z at the patch centre under p0, into the rail [m]
  double displacement_residual = kNaN;  ///< u_z at the patch centre after unloading [m]
  double max_plastic_strain = 0.0;      ///< max over integration points of |eps_p| (equivalent) [-]
  double depth_max_plastic_strain = kNaN;  ///< depth below the surface of that point [m]
  long dofs = 0;
  int newton_iterations = 0;
  double cpu_seconds = 0.0;
  /// With a compliance grid: tangential compliance of the rail under p0 (frozen elasto-plastic
  /// tangent) minus that of the same mesh elastic, single body in the contact frame (x rolling,
  /// y lateral, z outward; zz left zero) [m/Pa].
  SurfaceCompliance tangent_correction;
  /// With a compliance or dent grid: residual u_z into the rail at the dent grid's element
  /// centres [m].
  contact::mim::Field residual_dent;
  int flowing_points = 0;  ///< integration points flowing in the last load step [-]
  /// Integration points whose plastic strain changed during unloading (0: the unloading was
  /// elastic, so reloading to p0 retraces it elastically: the cycle has shaken down) [-].
  int reverse_flowing_points = 0;
};

/// Grid for HertzLoadCase::compliance_grid: square elements of min(a, b) / elements_per_semi_axis
/// covering 1.25 a x 1.25 b (even counts, centred on the patch).
[[nodiscard]] contact::mim::Grid elastoplastic_grid(double semi_axis_x, double semi_axis_y,
                                                    int elements_per_semi_axis);

/// Load-unload cycle of the rail head under the Hertz pressure. Throws std::invalid_argument
/// for bad input and std::runtime_error when Newton's method does not converge.
[[nodiscard]] ElastoplasticResult hertz_load_cycle(const RailSteel& steel,
                                                   const HertzLoadCase& load);

/// Peak of the von Mises stress over p0 on the axis of a circular Hertz contact (Johnson eq.
/// 3.45), maximised over the depth, and that depth over a; first yield at
/// p0 = sigma_y / (peak ratio).
struct AxisVonMisesPeak {
  double ratio = kNaN;         ///< max sigma_vm / p0 [-]
  double depth_over_a = kNaN;  ///< z / a of the maximum [-]
};
[[nodiscard]] AxisVonMisesPeak hertz_circular_axis_von_mises_peak(double poisson);

}  // namespace ferro::fe_contact
