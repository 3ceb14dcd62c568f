// The co-running discrete track: equivalent per-wheelset values of a ballasted track and the
// equations of its rail and sleeper bodies (track_structure.hpp gives the model and its sources).
//
// References: see track_structure.hpp.
// Known deviations: see track_structure.hpp.

#include "ferro/track/track_structure.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ferro::track {
namespace {

constexpr double kSteelDensity = 7850.0;  // [kg/m^3], rail polar inertia per metre

void require(bool ok, const std::string& where, const char* field, const std::string& rule,
             double value) {
  if (!ok) {
    throw std::invalid_argument(fmt::format("{}.{}: {}, got {}", where, field, rule, value));
  }
}

void positive(double v, const std::string& where, const char* field, const char* unit) {
  require(std::isfinite(v) && v > 0.0, where, field, fmt::format("must be > 0 {}", unit), v);
}

void non_negative(double v, const std::string& where, const char* field, const char* unit) {
  require(std::isfinite(v) && v >= 0.0, where, field, fmt::format("must be >= 0 {}", unit), v);
}

double series(double k1, double k2) { return k1 * k2 / (k1 + k2); }

/// One direction's lumping over the rail's static deflection shape (derivation in the header):
/// the seats' stiffness counts n = 2 / (a beta) times, masses and dampers n_c = 3 / (2 a beta)
/// times, the rail 3 m' / (2 beta), with beta = (k_f / (4 E I))^(1/4) of a beam on a foundation
/// of seat stiffness k_seat every a.
struct Lumping {
  double n, nc, rail_mass;
};
Lumping lump(double k_seat, double spacing, double bending_stiffness, double rail_mass_per_length) {
  const double beta = std::pow(k_seat / spacing / (4.0 * bending_stiffness), 0.25);
  return {2.0 / (spacing * beta), 1.5 / (spacing * beta), 1.5 * rail_mass_per_length / beta};
}

}  // namespace

void BallastedTrackSpec::validate(const std::string& where) const {
  positive(rail_mass_per_length, where, "rail.mass_per_length", "kg/m");
  positive(rail_young_modulus, where, "rail.young_modulus", "Pa");
  positive(rail_shear_modulus, where, "rail.shear_modulus", "Pa");
  positive(rail_inertia_vertical, where, "rail.inertia_vertical", "m^4");
  positive(rail_inertia_lateral, where, "rail.inertia_lateral", "m^4");
  positive(rail_torsion_constant, where, "rail.torsion_constant", "m^4");
  positive(rail_height, where, "rail.height", "m");
  require(std::isfinite(rail_centroid_height) && rail_centroid_height > 0.0 &&
              rail_centroid_height < rail_height,
          where, "rail.centroid_height", "must lie in (0, rail.height) m", rail_centroid_height);
  positive(rail_foot_width, where, "rail.foot_width", "m");
  positive(pad_stiffness_vertical, where, "pad.stiffness_vertical", "N/m");
  non_negative(pad_damping_vertical, where, "pad.damping_vertical", "N s/m");
  positive(pad_stiffness_lateral, where, "pad.stiffness_lateral", "N/m");
  non_negative(pad_damping_lateral, where, "pad.damping_lateral", "N s/m");
  if (!std::isnan(pad_stiffness_roll)) {
    positive(pad_stiffness_roll, where, "pad.stiffness_roll", "N m/rad");
  }
  if (!std::isnan(pad_damping_roll)) {
    non_negative(pad_damping_roll, where, "pad.damping_roll", "N m s/rad");
  }
  positive(sleeper_mass, where, "sleeper.mass", "kg");
  positive(sleeper_length, where, "sleeper.length", "m");
  require(std::isfinite(sleeper_spacing) && sleeper_spacing > 0.1 && sleeper_spacing < 2.0, where,
          "sleeper.spacing", "must lie in (0.1, 2) m", sleeper_spacing);
  positive(ballast_stiffness_vertical, where, "ballast.stiffness_vertical", "N/m");
  non_negative(ballast_damping_vertical, where, "ballast.damping_vertical", "N s/m");
  positive(ballast_stiffness_lateral, where, "ballast.stiffness_lateral", "N/m");
  non_negative(ballast_damping_lateral, where, "ballast.damping_lateral", "N s/m");
  non_negative(ballast_mass, where, "ballast.mass", "kg");
}

void CoRunningTrackParams::validate(const std::string& where) const {
  positive(rail_mass_lateral, where, "rail_mass_lateral", "kg");
  positive(rail_mass_vertical, where, "rail_mass_vertical", "kg");
  positive(rail_roll_inertia, where, "rail_roll_inertia", "kg m^2");
  positive(rail_head_height, where, "rail_head_height", "m");
  positive(rail_base_depth, where, "rail_base_depth", "m");
  positive(pad_stiffness_lateral, where, "pad_stiffness_lateral", "N/m");
  positive(pad_stiffness_vertical, where, "pad_stiffness_vertical", "N/m");
  positive(pad_stiffness_roll, where, "pad_stiffness_roll", "N m/rad");
  non_negative(pad_damping_lateral, where, "pad_damping_lateral", "N s/m");
  non_negative(pad_damping_vertical, where, "pad_damping_vertical", "N s/m");
  non_negative(pad_damping_roll, where, "pad_damping_roll", "N m s/rad");
  positive(sleeper_mass_lateral, where, "sleeper_mass_lateral", "kg");
  positive(sleeper_mass_vertical, where, "sleeper_mass_vertical", "kg");
  positive(sleeper_roll_inertia, where, "sleeper_roll_inertia", "kg m^2");
  positive(rail_seat_half_spacing, where, "rail_seat_half_spacing", "m");
  positive(ballast_stiffness_vertical, where, "ballast_stiffness_vertical", "N/m");
  positive(ballast_stiffness_lateral, where, "ballast_stiffness_lateral", "N/m");
  non_negative(ballast_damping_vertical, where, "ballast_damping_vertical", "N s/m");
  non_negative(ballast_damping_lateral, where, "ballast_damping_lateral", "N s/m");
}

CoRunningTrackParams co_running_equivalent(const BallastedTrackSpec& s, double rail_spacing) {
  s.validate();
  const double a = s.sleeper_spacing;
  const double m_rail = s.rail_mass_per_length;
  const double m_sleepers = s.sleeper_mass + 2.0 * s.ballast_mass;  // one sleeper, two seats
  CoRunningTrackParams p;
  p.rail_seat_half_spacing = 0.5 * rail_spacing;
  p.rail_head_height = s.rail_height - s.rail_centroid_height;
  p.rail_base_depth = s.rail_centroid_height;

  // Vertical: pad and ballast of a seat in series on the rail's vertical bending.
  const Lumping z = lump(series(s.pad_stiffness_vertical, s.ballast_stiffness_vertical), a,
                         s.rail_young_modulus * s.rail_inertia_vertical, m_rail);
  const double n_z = z.n, nc_z = z.nc;
  p.rail_mass_vertical = z.rail_mass;
  p.pad_stiffness_vertical = n_z * s.pad_stiffness_vertical;
  p.pad_damping_vertical = nc_z * s.pad_damping_vertical;
  p.ballast_stiffness_vertical = n_z * s.ballast_stiffness_vertical;
  p.ballast_damping_vertical = nc_z * s.ballast_damping_vertical;
  p.sleeper_mass_vertical = nc_z * m_sleepers;
  p.sleeper_roll_inertia =
      nc_z * (s.sleeper_mass * s.sleeper_length * s.sleeper_length / 12.0 +
              2.0 * s.ballast_mass * p.rail_seat_half_spacing * p.rail_seat_half_spacing);

  // Lateral: the pad in series with half the sleeper's lateral ballast stiffness, on the rail's
  // lateral bending.
  const Lumping y = lump(series(s.pad_stiffness_lateral, 0.5 * s.ballast_stiffness_lateral), a,
                         s.rail_young_modulus * s.rail_inertia_lateral, m_rail);
  const double n_y = y.n, nc_y = y.nc;
  p.rail_mass_lateral = y.rail_mass;
  p.pad_stiffness_lateral = n_y * s.pad_stiffness_lateral;
  p.pad_damping_lateral = nc_y * s.pad_damping_lateral;
  p.ballast_stiffness_lateral = n_y * s.ballast_stiffness_lateral;
  p.ballast_damping_lateral = nc_y * s.ballast_damping_lateral;
  p.sleeper_mass_lateral = nc_y * m_sleepers;

  // Roll: the rail in torsion on the fastenings' roll stiffness; by default the pad's vertical
  // stiffness split between the two edges of the foot, where the clips hold it and a rolling rail
  // compresses the pad: k_z (b / 2)^2.
  const double foot2 = s.rail_foot_width * s.rail_foot_width / 4.0;
  const double k_roll =
      std::isnan(s.pad_stiffness_roll) ? s.pad_stiffness_vertical * foot2 : s.pad_stiffness_roll;
  const double c_roll =
      std::isnan(s.pad_damping_roll) ? s.pad_damping_vertical * foot2 : s.pad_damping_roll;
  const double lambda = std::sqrt(k_roll / (a * s.rail_shear_modulus * s.rail_torsion_constant));
  p.pad_stiffness_roll = 2.0 / (a * lambda) * k_roll;
  p.pad_damping_roll = 1.0 / (a * lambda) * c_roll;
  p.rail_roll_inertia =
      kSteelDensity * (s.rail_inertia_vertical + s.rail_inertia_lateral) / lambda;
  return p;
}

void co_running_track_accelerations(const CoRunningTrackParams& p, const double* q,
                                    const double* v, const RailLoad loads[2], double* acc,
                                    PadForce* pads) {
  const double ys = q[6], zs = q[7], rs = q[8];
  const double vys = v[6], vzs = v[7], vrs = v[8];
  const double b = p.rail_seat_half_spacing;
  double sleeper_fy = 0.0, sleeper_fz = 0.0, sleeper_mx = 0.0;
  for (int side = 0; side < 2; ++side) {
    const double sigma = side == 0 ? 1.0 : -1.0;  // left rail at +y
    const double* qr = q + 3 * side;
    const double* vr = v + 3 * side;
    // Pad between the rail base (arm (0, 0, -d) from the rail's centre of mass: a roll phi moves
    // it by +d phi along y) and the rail seat (arm (0, sigma b, 0) from the sleeper's reference:
    // a roll moves it by sigma b phi along z).
    const double d = p.rail_base_depth;
    const double dy = qr[0] + d * qr[2] - ys, dvy = vr[0] + d * vr[2] - vys;
    const double dz = qr[1] - zs - sigma * b * rs, dvz = vr[1] - vzs - sigma * b * vrs;
    const double dr = qr[2] - rs, dvr = vr[2] - vrs;
    const double fy = -(p.pad_stiffness_lateral * dy + p.pad_damping_lateral * dvy);
    const double fz = -(p.pad_stiffness_vertical * dz + p.pad_damping_vertical * dvz);
    const double mx = -(p.pad_stiffness_roll * dr + p.pad_damping_roll * dvr);
    if (pads != nullptr) pads[side] = PadForce{fy, fz, mx};
    const RailLoad& load = loads[side];
    double* ar = acc + 3 * side;
    ar[0] = (fy + load.force_y) / p.rail_mass_lateral;
    ar[1] = (fz + load.force_z) / p.rail_mass_vertical;
    // The pad force at the base turns the rail about its centre of mass: (r x F)_x with
    // r = (0, 0, -d) is d F_y.
    ar[2] = (mx + d * fy + load.moment_x) / p.rail_roll_inertia;
    // Its reaction on the sleeper at the rail seat: (r x F)_x with r = (0, sigma b, 0) is
    // sigma b F_z.
    sleeper_fy -= fy;
    sleeper_fz -= fz;
    sleeper_mx -= mx + sigma * b * fz;
    // Ballast under the rail seat.
    const double fb = -(p.ballast_stiffness_vertical * (zs + sigma * b * rs) +
                        p.ballast_damping_vertical * (vzs + sigma * b * vrs));
    sleeper_fz += fb;
    sleeper_mx += sigma * b * fb;
  }
  sleeper_fy -= p.ballast_stiffness_lateral * ys + p.ballast_damping_lateral * vys;
  acc[6] = sleeper_fy / p.sleeper_mass_lateral;
  acc[7] = sleeper_fz / p.sleeper_mass_vertical;
  acc[8] = sleeper_mx / p.sleeper_roll_inertia;
}

}  // namespace ferro::track
