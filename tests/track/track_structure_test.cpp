// The co-running discrete track against closed forms: the per-wheelset equivalent of a
// ballasted track against the beam on an elastic foundation, the static deflection under the
// wheel loads against the springs in series, and the receptance of the implemented equations
// against the dynamic stiffness of the same spring-mass system assembled here independently.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

#include "ferro/track/track_structure.hpp"

namespace ferro::track {
namespace {

using cd = std::complex<double>;
constexpr int kN = kTrackPositions;

CoRunningTrackParams default_track() { return co_running_equivalent(BallastedTrackSpec{}, 1.5); }

/// Accelerations of the implemented equations.
Eigen::Matrix<double, kN, 1> accelerations(const CoRunningTrackParams& p, const double* q,
                                           const double* v, const RailLoad loads[2]) {
  Eigen::Matrix<double, kN, 1> a;
  co_running_track_accelerations(p, q, v, loads, a.data());
  return a;
}

/// The implemented equations linearised (they are linear: differences are exact to round-off):
/// acc = -Mi K q - Mi C v + Mi B u, with u the six loads (left y, z, roll moment; right ...).
struct Linear {
  Eigen::Matrix<double, kN, kN> minus_mik, minus_mic;
  Eigen::Matrix<double, kN, 6> mib;
};

Linear linearise(const CoRunningTrackParams& p) {
  Linear out;
  const double zero[kN] = {};
  const RailLoad none[2] = {};
  for (int j = 0; j < kN; ++j) {
    double e[kN] = {};
    e[j] = 1.0;
    out.minus_mik.col(j) = accelerations(p, e, zero, none);
    out.minus_mic.col(j) = accelerations(p, zero, e, none);
  }
  for (int j = 0; j < 6; ++j) {
    RailLoad loads[2] = {};
    double* f = j < 3 ? &loads[0].force_y : &loads[1].force_y;
    f[j % 3] = 1.0;
    out.mib.col(j) = accelerations(p, zero, zero, loads);
  }
  return out;
}

/// Receptance matrix (positions per load) of the implemented equations at angular frequency w.
Eigen::Matrix<cd, kN, 6> receptance(const Linear& l, double w) {
  const Eigen::Matrix<cd, kN, kN> d = -w * w * Eigen::Matrix<cd, kN, kN>::Identity() -
                                      l.minus_mik.cast<cd>() - cd(0.0, w) * l.minus_mic.cast<cd>();
  return d.partialPivLu().solve(l.mib.cast<cd>());
}

/// The same track assembled here as springs and dampers between points of rigid bodies: each
/// element contributes k b b^T, with b the element's deflection per unit of the positions.
struct Assembled {
  Eigen::Matrix<double, kN, kN> m = Eigen::Matrix<double, kN, kN>::Zero();
  Eigen::Matrix<double, kN, kN> k = Eigen::Matrix<double, kN, kN>::Zero();
  Eigen::Matrix<double, kN, kN> c = Eigen::Matrix<double, kN, kN>::Zero();
  void element(const Eigen::Matrix<double, kN, 1>& b, double stiffness, double damping) {
    k += stiffness * b * b.transpose();
    c += damping * b * b.transpose();
  }
};

Assembled assemble(const CoRunningTrackParams& p) {
  Assembled a;
  const double s = p.rail_seat_half_spacing, d = p.rail_base_depth;
  for (int side = 0; side < 2; ++side) {
    const int r = 3 * side;
    const double sigma = side == 0 ? 1.0 : -1.0;
    a.m(r, r) = p.rail_mass_lateral;
    a.m(r + 1, r + 1) = p.rail_mass_vertical;
    a.m(r + 2, r + 2) = p.rail_roll_inertia;
    using V = Eigen::Matrix<double, kN, 1>;
    V lateral = V::Zero();  // rail base (y + d roll) against the rail seat (sleeper y)
    lateral(r) = 1.0;
    lateral(r + 2) = d;
    lateral(6) = -1.0;
    a.element(lateral, p.pad_stiffness_lateral, p.pad_damping_lateral);
    V vertical = V::Zero();  // rail z against the seat (sleeper z + sigma s roll)
    vertical(r + 1) = 1.0;
    vertical(7) = -1.0;
    vertical(8) = -sigma * s;
    a.element(vertical, p.pad_stiffness_vertical, p.pad_damping_vertical);
    V roll = V::Zero();
    roll(r + 2) = 1.0;
    roll(8) = -1.0;
    a.element(roll, p.pad_stiffness_roll, p.pad_damping_roll);
    V ballast = V::Zero();  // under the seat
    ballast(7) = 1.0;
    ballast(8) = sigma * s;
    a.element(ballast, p.ballast_stiffness_vertical, p.ballast_damping_vertical);
  }
  Eigen::Matrix<double, kN, 1> ballast_lateral = Eigen::Matrix<double, kN, 1>::Zero();
  ballast_lateral(6) = 1.0;
  a.element(ballast_lateral, p.ballast_stiffness_lateral, p.ballast_damping_lateral);
  a.m(6, 6) = p.sleeper_mass_lateral;
  a.m(7, 7) = p.sleeper_mass_vertical;
  a.m(8, 8) = p.sleeper_roll_inertia;
  return a;
}

/// Generalised load of a force (fy, fz) at the top of a rail (head_height above its centre of
/// mass, on its centreline): the roll moment is -h fy.
Eigen::Matrix<cd, kN, 1> head_force(const CoRunningTrackParams& p, int side, double fy,
                                    double fz) {
  Eigen::Matrix<cd, kN, 1> f = Eigen::Matrix<cd, kN, 1>::Zero();
  f(3 * side) = fy;
  f(3 * side + 1) = fz;
  f(3 * side + 2) = -p.rail_head_height * fy;
  return f;
}

std::vector<double> frequencies() {  // 1 ... 2000 Hz, log spaced
  std::vector<double> f;
  for (int i = 0; i <= 24; ++i) f.push_back(std::pow(10.0, 3.30103 * i / 24.0));
  return f;
}

TEST(CoRunningTrack, equivalent_of_the_default_track_is_the_beam_on_elastic_foundation) {
  // Beam on a Winkler foundation (Hetenyi): static stiffness under a point load 8 E I beta^3;
  // the lumped pad and ballast in series must give it (the equivalence keeps the static
  // deflection), and the rail mass is 3 m' / (2 beta).
  const BallastedTrackSpec s;
  const CoRunningTrackParams p = default_track();
  const double k_seat = 1.0 / (1.0 / s.pad_stiffness_vertical + 1.0 / s.ballast_stiffness_vertical);
  const double ei = s.rail_young_modulus * s.rail_inertia_vertical;
  const double beta = std::pow(k_seat / s.sleeper_spacing / (4.0 * ei), 0.25);
  const double k_beam = 8.0 * ei * beta * beta * beta;
  const double k_lumped =
      1.0 / (1.0 / p.pad_stiffness_vertical + 1.0 / p.ballast_stiffness_vertical);
  EXPECT_NEAR(k_lumped / k_beam, 1.0, 1e-12);
  EXPECT_NEAR(p.rail_mass_vertical, 1.5 * s.rail_mass_per_length / beta, 1e-9);
  // The default's figures as documented (track_structure.hpp): 153.8 MN/m per wheel,
  // 62.5 kg of rail, 484 kg of sleepers, 462 and 231 MN/m.
  EXPECT_NEAR(k_lumped / 1e6, 153.8, 0.05);
  EXPECT_NEAR(p.rail_mass_vertical, 62.5, 0.05);
  EXPECT_NEAR(p.sleeper_mass_vertical, 484.6, 0.5);
  EXPECT_NEAR(p.pad_stiffness_vertical / 1e6, 462.0, 0.5);
  EXPECT_NEAR(p.ballast_stiffness_vertical / 1e6, 231.0, 0.5);
}

TEST(CoRunningTrack, static_deflection_under_wheel_loads_is_the_springs_in_series) {
  // Wheel loads Q_L, Q_R on the rail heads and a lateral force Y on the left head: each rail
  // compresses its pad by Q / k_pad; the sleeper's seats carry Q plus the couple of Y about the
  // seat level, Y H / (2 s) more on the left and less on the right (H the rail height, s half
  // the seat spacing), and sink by that load over k_ballast. Tolerance 1e-9: a linear solve.
  const CoRunningTrackParams p = default_track();
  const Linear l = linearise(p);
  const double q_left = 61.0e3, q_right = 48.0e3, y_left = 9.0e3;
  Eigen::Matrix<double, 6, 1> u;
  u << y_left, -q_left, -p.rail_head_height * y_left, 0.0, -q_right, 0.0;
  const Eigen::Matrix<double, kN, 1> q = l.minus_mik.partialPivLu().solve(-l.mib * u);
  const double s = p.rail_seat_half_spacing;
  const double couple = y_left * (p.rail_head_height + p.rail_base_depth) / (2.0 * s);
  const double seat_left = q_left + couple, seat_right = q_right - couple;
  EXPECT_NEAR(q(1) / -(q_left / p.pad_stiffness_vertical + seat_left / p.ballast_stiffness_vertical),
              1.0, 1e-9);
  EXPECT_NEAR(q(4) / -(q_right / p.pad_stiffness_vertical + seat_right / p.ballast_stiffness_vertical),
              1.0, 1e-9);
  EXPECT_NEAR((q(7) + s * q(8)) / (-seat_left / p.ballast_stiffness_vertical), 1.0, 1e-9);
  EXPECT_NEAR((q(7) - s * q(8)) / (-seat_right / p.ballast_stiffness_vertical), 1.0, 1e-9);
}

TEST(CoRunningTrack, vertical_receptance_matches_the_two_mass_closed_form) {
  // Equal vertical forces on both rail heads: per rail the rail mass on the pad, on half the
  // sleeper, on the ballast: H = (k_b* + k_p* - w^2 m_s/2) / ((k_p* - w^2 m_r)(k_b* + k_p* -
  // w^2 m_s/2) - k_p*^2), k* = k + i w c. Within 1e-6 over 1-2000 Hz (the bound is 1 %).
  const CoRunningTrackParams p = default_track();
  const Linear l = linearise(p);
  for (const double f : frequencies()) {
    const double w = 2.0 * std::numbers::pi * f;
    const cd kp(p.pad_stiffness_vertical, w * p.pad_damping_vertical);
    const cd kb(p.ballast_stiffness_vertical, w * p.ballast_damping_vertical);
    const cd sleeper = kb + kp - w * w * 0.5 * p.sleeper_mass_vertical;
    const cd closed = sleeper / ((kp - w * w * p.rail_mass_vertical) * sleeper - kp * kp);
    const Eigen::Matrix<cd, kN, 6> h = receptance(l, w);
    const cd model = h(1, 1) + h(1, 4);  // left rail z under unit loads on both rails
    EXPECT_LT(std::abs(model / closed - 1.0), 1e-6) << "f = " << f << " Hz";
  }
}

TEST(CoRunningTrack, lateral_and_antisymmetric_receptance_match_the_assembled_system) {
  // Lateral forces at the rail heads (both rails alike, and the left rail alone) and
  // antisymmetric vertical forces: the implemented equations against the dynamic stiffness
  // K - w^2 M + i w C assembled here from the springs' deflection vectors. Within 1e-6.
  const CoRunningTrackParams p = default_track();
  const Linear l = linearise(p);
  const Assembled a = assemble(p);
  const auto head_y = [&](const Eigen::Matrix<cd, kN, 1>& q, int side) {
    return q(3 * side) - p.rail_head_height * q(3 * side + 2);
  };
  for (const double f : frequencies()) {
    const double w = 2.0 * std::numbers::pi * f;
    const Eigen::Matrix<cd, kN, kN> d =
        a.k.cast<cd>() - w * w * a.m.cast<cd>() + cd(0.0, w) * a.c.cast<cd>();
    const auto lu = d.partialPivLu();
    const Eigen::Matrix<cd, kN, 6> h = receptance(l, w);
    const auto model = [&](double yl, double zl, double yr, double zr) {
      Eigen::Matrix<cd, 6, 1> u;
      u << yl, zl, -p.rail_head_height * yl, yr, zr, -p.rail_head_height * yr;
      return Eigen::Matrix<cd, kN, 1>(h * u);
    };
    // Both rails pushed the same way.
    const Eigen::Matrix<cd, kN, 1> closed_sym = lu.solve(head_force(p, 0, 1.0, 0.0) +
                                                         head_force(p, 1, 1.0, 0.0));
    const Eigen::Matrix<cd, kN, 1> model_sym = model(1.0, 0.0, 1.0, 0.0);
    EXPECT_LT(std::abs(head_y(model_sym, 0) / head_y(closed_sym, 0) - 1.0), 1e-6) << f;
    // The left rail alone (gauge spreading load).
    const Eigen::Matrix<cd, kN, 1> closed_one = lu.solve(head_force(p, 0, 1.0, 0.0));
    const Eigen::Matrix<cd, kN, 1> model_one = model(1.0, 0.0, 0.0, 0.0);
    EXPECT_LT(std::abs(head_y(model_one, 0) / head_y(closed_one, 0) - 1.0), 1e-6) << f;
    // Opposite vertical forces (sleeper roll).
    const Eigen::Matrix<cd, kN, 1> closed_anti =
        lu.solve(head_force(p, 0, 0.0, 1.0) + head_force(p, 1, 0.0, -1.0));
    const Eigen::Matrix<cd, kN, 1> model_anti = model(0.0, 1.0, 0.0, -1.0);
    EXPECT_LT(std::abs(model_anti(1) / closed_anti(1) - 1.0), 1e-6) << f;
  }
}

TEST(CoRunningTrack, rejects_a_track_out_of_range_naming_the_field) {
  BallastedTrackSpec s;
  s.pad_stiffness_vertical = -1.0;
  try {
    (void)co_running_equivalent(s, 1.5);
    FAIL() << "accepted a negative pad stiffness";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pad.stiffness_vertical"), std::string::npos) << e.what();
  }
  s = BallastedTrackSpec{};
  s.rail_centroid_height = 0.3;  // above the rail's top
  EXPECT_THROW((void)co_running_equivalent(s, 1.5), std::invalid_argument);
}

}  // namespace
}  // namespace ferro::track
