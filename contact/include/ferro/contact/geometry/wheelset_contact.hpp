#pragma once
// Full wheel-rail contact of prescribed wheelset positions (the Manchester contact benchmark
// format): for each position and each wheel, the contact patches found from the rigid
// interpenetration of the profiles, each reported at its penetration-weighted centre (a
// two-lobe, non-Hertzian patch is one patch; the weights are the interpenetration squared and the
// patch's contact angle is the same weighted average of the rail inclination), the normal and
// tangential problem solved by MIM on the undeformed gap sampled from the profiles, creepages from
// the prescribed yaw and rolling, and the wheel's height solved so that the vertical force it puts
// on the rail (the vertical parts of the normal AND tangential forces) equals the prescribed wheel
// load.
//
// References: Shackleton & Iwnicki, "Comparison of wheel-rail contact codes for railway vehicle
// simulation: an introduction to the Manchester Contact Benchmark and initial results", Vehicle
// System Dynamics 46 (2008) 91-120 (case, one wheel load per wheel, one patch reported at
// the weighted centre of the interpenetration); Vollebregt, CONTACT user guide (contact
// reference point and contact angle weighted by the squared interpenetration, patches less than
// 8 mm apart combined);
// Toumi (2016) eqs. (24)-(27) (creepages as rigid slip over the rolling speed), ch. 2 (MIM).
// Known deviations: each wheel is solved on its own (its own height, as the benchmark's
// reference solutions do), not as one rigid wheelset; the undeformed gap of a patch is measured
// along the normal of one plane, the tangent plane at the patch's reference point (a patch
// spanning very different contact angles, e.g. tread and flange at once, would need a curved
// reference surface); the variable-friction variant of the benchmark is not implemented (one
// mu for the whole profile); the rolling speed in the creepages is the forward speed V.
//
// Units: SI throughout.

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/contact/material.hpp"
#include "ferro/contact/tangential/creepage.hpp"

namespace ferro::contact {

/// One prescribed wheelset position (a benchmark case). SI.
struct WheelsetCase {
  int id = 0;
  double lateral = 0.0;     ///< y [m], + to the right
  double roll = 0.0;        ///< [rad], + lowers the right wheel
  double yaw = 0.0;         ///< [rad], + turns the front to the right
  double pitch_rate = 0.0;  ///< rotation speed about the axle [rad/s] (rolling: about -V/r0)
};

/// What every case of a wheelset-contact study shares: load, speed, material, friction and the
/// MIM discretisation. SI.
struct WheelsetContactSpec {
  double load_per_wheel = std::numeric_limits<double>::quiet_NaN();  ///< F_z per wheel [N]
  double forward_speed = std::numeric_limits<double>::quiet_NaN();   ///< V [m/s]
  Material material;                                                 ///< both bodies
  double friction = std::numeric_limits<double>::quiet_NaN();        ///< mu [-]
  double dx = 0.2e-3;  ///< element length along the track [m]
  double ds = 0.2e-3;  ///< element width across, in the contact plane [m]
};

/// One contact patch of one wheel, at its reference point (the penetration-weighted centre of
/// the interpenetration). Forces and moment are exerted BY THE RAIL ON THE WHEEL in the contact
/// frame of the library (tangential_model.hpp): t1 along the track, n the rail's outward normal,
/// t2 = n x t1; creepages in the same frame.
struct PatchContact {
  double x = 0.0;        ///< reference point along the track, track frame [m]
  double rail_y = 0.0;   ///< reference point on the rail profile (file coordinates) [m]
  double wheel_y = 0.0;  ///< reference point on the wheel profile (file coordinates) [m]
  /// [rad], + when the normal leans towards the track centre: the penetration-weighted average
  /// inclination of the rail over the patch, which sets the contact plane (t1, t2) and n.
  double contact_angle = 0.0;
  double rolling_radius = 0.0;                ///< wheel radius at the reference point [m]
  double rail_y_min = 0.0, rail_y_max = 0.0;  ///< lateral extent of the loaded area on the rail [m]
  double deepest_rail_y = 0.0;  ///< deepest interpenetration point of the patch on the rail [m]
  int regions = 0;  ///< connected parts of the loaded area (2: two separate lobes in one patch)
  Creepage creepage;
  double normal_force = 0.0;       ///< F_n [N]
  double force_x = 0.0;            ///< F_x [N]
  double force_y = 0.0;            ///< F_y [N]
  double moment_z = 0.0;           ///< M_z about the reference point [N m]
  double approach = 0.0;           ///< rigid approach of the bodies along n [m]
  double peak_pressure = 0.0;      ///< [Pa]
  double area = 0.0;               ///< loaded area [m^2]
  double adhesion_fraction = 0.0;  ///< stick area / loaded area [-]
  double force_vertical = 0.0;     ///< vertical force ON THE RAIL, + down [N]
  double force_lateral = 0.0;      ///< lateral force ON THE RAIL, track y (+ right) [N]
  bool converged = false;          ///< MIM normal and tangential solves converged
};

/// One wheel of one case.
struct WheelContact {
  Side side = Side::right;
  double vertical = 0.0;       ///< solved axle drop below the nominal height (+ down) [m]
  double vertical_load = 0.0;  ///< vertical force on the rail, all patches [N]
  double lateral_force = 0.0;  ///< lateral force on the rail, track y [N]
  int iterations = 0;          ///< height iterations
  std::vector<PatchContact> patches;
};

struct WheelsetContact {
  WheelsetCase input;
  std::array<WheelContact, 2> wheels;  ///< left, right
};

/// Interpenetration regions of one wheel less than this apart (edge to edge, across the track)
/// are one patch [m]: the benchmark's reference solution separates patches only beyond 8 mm
/// (its D_SEP), so a tread lobe next to a flange-root contact belongs to that patch.
inline constexpr double kPatchSeparationDistance = 8.0e-3;
/// The height solve stops when the vertical load is within this fraction of the prescribed
/// load [-].
inline constexpr double kVerticalLoadTolerance = 1.0e-4;

/// Contact of one wheel at a prescribed position, its height solved for the wheel load.
/// Throws std::runtime_error when the wheel cannot carry the load (no contact found).
[[nodiscard]] WheelContact solve_wheel_contact(const WheelRailPair& pair,
                                               const WheelsetContactSpec& spec,
                                               const WheelsetCase& c, Side side);

/// Contact of one wheel with its height given (no load balance): the patches at `vertical`.
[[nodiscard]] WheelContact wheel_contact_at(const WheelRailPair& pair,
                                            const WheelsetContactSpec& spec, const WheelsetCase& c,
                                            Side side, double vertical);

/// Both wheels of every case, in the given order.
[[nodiscard]] std::vector<WheelsetContact> solve_wheelset_contacts(
    const WheelRailPair& pair, const WheelsetContactSpec& spec,
    const std::vector<WheelsetCase>& cases);

/// Writes the table (one row per patch) as HDF5 (kind "wheelset_contact", /patches/<column>
/// with units; `pair_file` names the input in an attribute) and, when `csv_path` is not empty,
/// as CSV with the same columns.
void write_wheelset_contacts(const std::vector<WheelsetContact>& results,
                             const WheelsetContactSpec& spec, const std::string& pair_file,
                             const std::string& h5_path, const std::string& csv_path);

}  // namespace ferro::contact
