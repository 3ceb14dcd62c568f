#pragma once
// The track structure under a vehicle: `rigid` (the rails stay where the design and the
// irregularities put them) or `discrete`, a co-running discrete track under every wheelset, as
// vehicle-dynamics codes carry it: per rail a rail body (lateral, vertical and roll motion of its
// centre of mass) on the rail pads, both rails on one sleeper body (lateral, vertical, roll) on
// the ballast, stiffness and damping per direction. The bodies move with the wheelset (their
// state is the deflection under it); they are lumped per wheelset from a ballasted track
// described per rail seat.
//
// Equivalent per-wheelset values (co_running_equivalent). The rail is a beam on an elastic
// foundation of per-metre stiffness k_f = k_s / a (k_s the pad and ballast of one rail seat in
// series, a the sleeper spacing), beta = (k_f / (4 E I))^(1/4). Under a point load its static
// deflection is w(x) = w0 e^(-beta |x|) (cos beta x + sin beta |x|) with w0 = P beta / (2 k_f), so
// its static stiffness is K = 2 k_f / beta (Hetenyi 1946; Zimmermann). With that static shape as
// the Ritz function of the lumped model:
//   - the stiffnesses keep the static deflections of rail and sleeper: k_pad,eq = n k_pad,
//     k_ballast,eq = n k_ballast with n = 2 / (a beta) (the load on the seat under the wheel is
//     P a beta / 2), so the springs in series give K exactly;
//   - masses and dampers weigh with the square of the shape: the rail m_r = m' int (w/w0)^2 dx =
//     3 m' / (2 beta); the sleeper and ballast masses and the pad and ballast dampers of a seat
//     count n_c = 3 / (2 a beta) times;
//   - the lateral direction the same with the rail's lateral bending stiffness E I_z, the lateral
//     pad and half the sleeper's lateral ballast stiffness per rail seat;
//   - rail roll: the rail in torsion G J on the fastenings' roll stiffness k_theta per seat,
//     lambda = sqrt(k_theta / (a G J)), static stiffness 2 k_theta / (a lambda) (n_theta =
//     2 / (a lambda)), roll inertia rho I_p / lambda (shape e^(-lambda |x|)).
// The sleeper body carries the participating sleepers (n_c of them, their roll inertia as uniform
// bars) and the participating ballast mass.
//
// Defaults (BallastedTrackSpec): 60E1 rail (EN 13674-1: 60.21 kg/m, I_y 3038 cm^4, I_z 512.3
// cm^4, height 172 mm, centroid 80.9 mm above the base; torsion constant 221 cm^4 computed from the
// section), B70-type concrete monoblock sleepers (280 kg, 2.60 m) at 0.60 m, a standard
// stiff-to-medium pad (200 MN/m, 40 kN s/m vertical; 40 MN/m, 40 kN s/m lateral; roll stiffness
// k_z b^2 / 4: the vertical pad stiffness split between the edges of the 150 mm foot, where the
// clips hold the rail and a rolling rail loads the pad (a uniform pad alone, k_z b^2 / 12, lets
// the rails roll by ~10 mrad under the flange forces of the derailment scene, 50-60 kN; the
// fastening's real roll restraint was not at hand: an engineering estimate)), ballast 100 MN/m and 60 kN s/m per rail seat vertically (Zhai,
// Wang & Lin, J. Sound Vib. 270 (2004) 673-683: 58.8 kN s/m; the stiffness chosen so that the
// static track stiffness per wheel is 154 MN/m, the 150 MN/m British Rail's GM/TT0088 uses for
// concrete-sleepered track) and 50 MN/m, 40 kN s/m laterally per sleeper (an engineering estimate:
// no published value was at hand). Per wheelset this gives a rail of 62.5 kg (vertical), pads of
// 462 MN/m, sleepers of 484 kg, ballast of 231 MN/m per rail side, lumped frequencies 137 Hz
// (track on ballast) and 490 Hz (rail on pads).
//
// References: Hetenyi, "Beams on Elastic Foundation" (1946); Knothe & Grassie, Veh. Syst. Dyn. 22
// (1993) 209-262 (track models for vehicle-track interaction); Zhai, Wang & Cai, Veh. Syst. Dyn.
// 47 (2009) 1349-1376 (rail vertical, lateral and torsional motion under the wheel); EN 13674-1
// (60E1 section).
// Known deviations: the bodies do not travel with the rail material (the co-running
// approximation: the deflection shape moves with the load, convective terms V d/dx neglected, far
// below the track's critical speed); the neighbouring wheelsets' deflection basins do not
// interact (at a 2.5 m wheelbase the neighbour's deflection under a wheel is -3.6 %); the
// sleeper's lateral ballast force acts at the rail-seat level (no coupling of sleeper roll and
// lateral motion through the ballast's depth); the rail has no longitudinal motion (longitudinal
// creep forces go to the ground); no pinned-pinned resonance (discrete support) and no
// frequency dependence of pad and ballast; the static state of the track under its own weight is
// the reference (displacements are from it). The lumping keeps the static receptance exactly but
// not the resonances: against the same rail continuously or discretely supported by the same
// seats, the default track's full-track and rail-on-pad receptance peaks lie 17 % higher (130 and
// 477 Hz against 111 and 408 Hz) and the full-track peak is 35 % higher; the wheel on the track
// (P2 mode, 58 Hz) is within 0.1 % in frequency and 7 % in damping (tests/track,
// track_receptance_test.cpp).

#include <limits>
#include <string>

namespace ferro::track {

/// A ballasted track described per rail seat (one rail on one sleeper), SI units.
struct BallastedTrackSpec {
  static constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
  // Rail (60E1, EN 13674-1).
  double rail_mass_per_length = 60.21;       ///< [kg/m]
  double rail_young_modulus = 2.10e11;       ///< [Pa]
  double rail_shear_modulus = 8.08e10;       ///< [Pa]
  double rail_inertia_vertical = 3.038e-5;   ///< I_y, vertical bending [m^4]
  double rail_inertia_lateral = 5.123e-6;    ///< I_z, lateral bending [m^4]
  double rail_torsion_constant = 2.21e-6;    ///< J [m^4]
  double rail_height = 0.172;                ///< base to top of rail [m]
  double rail_centroid_height = 0.0809;      ///< centre of mass above the base [m]
  double rail_foot_width = 0.150;            ///< [m]
  // Fastening: rail pad and clips, per rail seat.
  double pad_stiffness_vertical = 200.0e6;   ///< [N/m]
  double pad_damping_vertical = 40.0e3;      ///< [N s/m]
  double pad_stiffness_lateral = 40.0e6;     ///< [N/m]
  double pad_damping_lateral = 40.0e3;       ///< [N s/m]
  /// Roll stiffness and damping of the fastening [N m/rad], [N m s/rad]; NaN: the pad's
  /// vertical values split between the foot's edges, k_z b^2 / 4 and c_z b^2 / 4.
  double pad_stiffness_roll = kUnset;
  double pad_damping_roll = kUnset;
  // Sleeper (B70-type concrete monoblock).
  double sleeper_mass = 280.0;               ///< whole sleeper [kg]
  double sleeper_length = 2.60;              ///< [m]
  double sleeper_spacing = 0.60;             ///< [m]
  // Ballast.
  double ballast_stiffness_vertical = 100.0e6;  ///< under one rail seat [N/m]
  double ballast_damping_vertical = 60.0e3;     ///< under one rail seat [N s/m]
  double ballast_stiffness_lateral = 50.0e6;    ///< whole sleeper [N/m]
  double ballast_damping_lateral = 40.0e3;      ///< whole sleeper [N s/m]
  double ballast_mass = 0.0;  ///< participating ballast under one rail seat, moves with it [kg]

  /// Throws std::invalid_argument "<where>.<field>: ..." for a value out of range.
  void validate(const std::string& where = "track.structure") const;
};

/// The lumped track under one wheelset. Rail bodies at the rail reference points (+-half the
/// rail spacing), their centre of mass rail_head_height below the top of rail; the pads act at
/// the rail base, rail_base_depth below the centre of mass, on the sleeper's rail seats at
/// +-rail_seat_half_spacing; the ballast acts under the rail seats (vertical) and at the
/// sleeper's reference point on the track centreline at rail-seat level (lateral).
struct CoRunningTrackParams {
  double rail_mass_lateral = 0.0;     ///< [kg]
  double rail_mass_vertical = 0.0;    ///< [kg]
  double rail_roll_inertia = 0.0;     ///< about the rail's centre of mass [kg m^2]
  double rail_head_height = 0.0;      ///< top of rail above the rail's centre of mass [m]
  double rail_base_depth = 0.0;       ///< rail base below the rail's centre of mass [m]
  double pad_stiffness_lateral = 0.0, pad_damping_lateral = 0.0;    ///< per rail [N/m], [N s/m]
  double pad_stiffness_vertical = 0.0, pad_damping_vertical = 0.0;  ///< per rail
  double pad_stiffness_roll = 0.0, pad_damping_roll = 0.0;  ///< per rail [N m/rad], [N m s/rad]
  double sleeper_mass_lateral = 0.0;   ///< [kg]
  double sleeper_mass_vertical = 0.0;  ///< [kg]
  double sleeper_roll_inertia = 0.0;   ///< [kg m^2]
  double rail_seat_half_spacing = 0.0; ///< [m]
  double ballast_stiffness_vertical = 0.0, ballast_damping_vertical = 0.0;  ///< per rail seat
  double ballast_stiffness_lateral = 0.0, ballast_damping_lateral = 0.0;    ///< whole sleeper

  /// Throws std::invalid_argument naming the field (every value finite and > 0, dampers >= 0).
  void validate(const std::string& where = "track.structure") const;
};

/// The per-wheelset equivalent of a ballasted track (derivation at the top of this file);
/// `rail_spacing` is the distance between the rails' reference points (rail seats at +-half).
[[nodiscard]] CoRunningTrackParams co_running_equivalent(const BallastedTrackSpec& spec,
                                                         double rail_spacing);

/// The structure chosen in a scene's track block.
struct TrackStructureSpec {
  enum class Kind { rigid, discrete };
  Kind kind = Kind::rigid;
  BallastedTrackSpec ballasted;  ///< kind discrete
  [[nodiscard]] bool flexible() const { return kind != Kind::rigid; }
};

/// Positions of the co-running track under one wheelset, in state order: the left rail's
/// lateral, vertical and roll displacement (of its centre of mass, track axes y left, z up, roll
/// about x), the right rail's, the sleeper's (reference point on the centreline at rail-seat
/// level). Their rates follow in the same order.
inline constexpr int kTrackPositions = 9;
inline constexpr const char* kTrackPositionNames[kTrackPositions] = {
    "left_rail.y",  "left_rail.z",  "left_rail.roll", "right_rail.y", "right_rail.z",
    "right_rail.roll", "sleeper.y", "sleeper.z",      "sleeper.roll"};

/// What acts on one rail from outside the track (the wheel's contact forces): force along y and
/// z of the track axes [N] and moment about x through the rail's centre of mass [N m].
struct RailLoad {
  double force_y = 0.0, force_z = 0.0, moment_x = 0.0;
};

/// Pad forces on a rail from its rail seat (track axes) [N], and the pad's roll moment [N m].
struct PadForce {
  double force_y = 0.0, force_z = 0.0, moment_x = 0.0;
};

/// Accelerations of the track positions (kTrackPositions values into `acc`) from the positions
/// `q`, rates `v` and the loads on the left [0] and right [1] rail; pad forces per rail into
/// `pads` when given.
void co_running_track_accelerations(const CoRunningTrackParams& p, const double* q,
                                    const double* v, const RailLoad loads[2], double* acc,
                                    PadForce* pads = nullptr);

}  // namespace ferro::track
