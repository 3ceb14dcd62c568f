#pragma once
// Kalker reduction factors K_ij as ratios of initial creep-curve slopes of two steady-rolling MIM
// runs on the same grid: one with a modified surface compliance (finite bodies, interfacial
// layer), one with the half-space influence coefficients, so that the discretisation error of
// the grid cancels in the ratio. Creep curves and their derivative curves A_x, A_y.
//
// References: Toumi (2016) section 3.1.3.4 (K_ij from initial slopes, eqs. 146-147), eq. (156);
// Kalker, "Three-dimensional elastic bodies in rolling contact" (1990) (linear theory, C_ij);
// Vollebregt, CONTACT user guide (numerical influence coefficients, interfacial layer).
// Known deviations: the initial slope is the secant at a probe creepage small enough that the
// patch is in full adhesion apart from its trailing-edge elements (the discrete full-stick
// solution is linear in the creepage); the thesis differentiates an FE creep curve instead.
// A perfectly plastic interfacial layer is modelled by capping the traction bound at
// min(mu p, tau_c), the layer's elastic compliance being that of the elastic layer.

#include <limits>
#include <string>
#include <vector>

#include "ferro/contact/kij/reduction_factors.hpp"
#include "ferro/contact/mim/compliance_operator.hpp"
#include "ferro/contact/mim/mim.hpp"

namespace ferro::fe_contact {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Probe creepages of the initial-slope runs and the solver settings.
struct SlopeOptions {
  double probe_creepage = 1.0e-6;  ///< xi_x, xi_y of the K11, K22 runs [-]
  /// phi a of the K23, K33 run (phi = probe_spin_times_a / a) [-]
  double probe_spin_times_a = 1.0e-6;
  contact::mim::MimOptions mim;
  void validate(const std::string& where = "SlopeOptions") const;
};

/// One contact under test: the normal load, friction and an optional traction cap tau_c.
struct SlopeCase {
  double normal_force = kNaN;  ///< F_n [N]
  double friction = kNaN;      ///< mu [-]
  /// Shear strength of a perfectly plastic interfacial layer tau_c [Pa]: the traction bound
  /// becomes min(mu p, tau_c). Infinity: no cap.
  double yield_shear = std::numeric_limits<double>::infinity();
  /// Length scale of the spin probe, normally the semi-axis a along x [m].
  double semi_axis_x = kNaN;
  void validate(const std::string& where = "SlopeCase") const;
};

/// Linear creep stiffnesses of one operator: F_x = -S11 xi_x, F_y = -S22 xi_y - S23 phi,
/// M_z = -S33 phi (S in N, N m, N m^2 ...), from the probe runs.
struct CreepStiffness {
  double s11 = kNaN;  ///< -dF_x/dxi_x [N]
  double s22 = kNaN;  ///< -dF_y/dxi_y [N]
  double s23 = kNaN;  ///< -dF_y/dphi [N m]
  double s33 = kNaN;  ///< -dM_z/dphi [N m^2]
  double normal_force = kNaN;  ///< F_n reached [N]
  int contact_elements = 0;
  bool converged = false;
};

struct SlopeResult {
  CreepStiffness modified;
  CreepStiffness half_space;
  contact::ReductionFactors k;  ///< K_ij = S_ij(modified) / S_ij(half-space)
  bool converged = false;
  /// Sets k and converged from modified and half_space.
  void update_ratios();
};

/// Pressure of a normal solve under F_n, then the probe runs. The gap is the undeformed
/// separation on op.grid() [m].
[[nodiscard]] CreepStiffness creep_stiffness(contact::mim::ComplianceOperator& op,
                                             const contact::mim::Field& gap, const SlopeCase& c,
                                             const SlopeOptions& options = {});

/// K_ij of `modified` against `half_space` (both on the same grid; throws otherwise).
[[nodiscard]] SlopeResult reduction_factors(contact::mim::ComplianceOperator& modified,
                                            contact::mim::ComplianceOperator& half_space,
                                            const contact::mim::Field& gap, const SlopeCase& c,
                                            const SlopeOptions& options = {});

/// Creep curve along x (creepage_x) or y (creepage_y) at zero spin, with the derivative curve of
/// Toumi eqs. (146)-(147): derivative[n] = (F[n] - F[n-1]) / (xi[n] - xi[n-1]) (NaN at n = 0).
struct CreepCurve {
  char direction = 'x';
  std::vector<double> creepage;    ///< xi [-]
  std::vector<double> force;       ///< F_x or F_y [N]
  std::vector<double> derivative;  ///< A_x or A_y [N]
  bool converged = true;
};

/// Runs the normal problem once and the steady-rolling problem at each creepage.
[[nodiscard]] CreepCurve creep_curve(contact::mim::ComplianceOperator& op,
                                     const contact::mim::Field& gap, const SlopeCase& c,
                                     char direction, const std::vector<double>& creepages,
                                     const SlopeOptions& options = {});

/// Traction bound field with the plastic-layer cap: pressure p' = min(p, tau_c / mu) so that the
/// solvers' bound mu p' equals min(mu p, tau_c) [Pa].
[[nodiscard]] contact::mim::Field capped_pressure(const contact::mim::Field& pressure,
                                                  double friction, double yield_shear);

}  // namespace ferro::fe_contact
