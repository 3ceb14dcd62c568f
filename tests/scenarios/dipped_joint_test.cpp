// P2 force of a wheelset over a dipped rail joint on the co-running discrete track against
// Jenkins et al. (1974), "The effect of track and vehicle parameters on wheel/rail vertical
// dynamic forces", Railway Engineering Journal 3(1) 2-16:
//   P2 = P0 + 2 alpha V sqrt(mu / (mu + mt)) [1 - pi ct / (4 sqrt(kt (mu + mt)))] sqrt(kt mu)
// with 2 alpha the joint's total angle, V the speed, mu the unsprung mass per wheel (half the
// wheelset), kt, ct, mt the track's stiffness, damping and mass per wheel.
//
// Mapping of the model's track (per rail: a rail mass mr on the pad kp, cp; its share of the
// sleeper ms on the ballast kb, cb) onto Jenkins' single-mass track by the static deflection
// shape (Rayleigh): the rail moves by w, the sleeper by w kp / (kp + kb), so
//   kt = kp kb / (kp + kb), mt = mr + ms (kp / (kp + kb))^2,
//   ct = cp (kb / (kp + kb))^2 + cb (kp / (kp + kb))^2.
// P2 is read as the peak of the mean wheel load of the leading wheelset low-passed by a
// zero-phase second-order Butterworth filter at 150 Hz (P2's ~60 Hz passes with 2 % loss of the
// increment, the P1 ringing at the rail's mass on the Hertz and pad stiffness, ~700 Hz, is
// removed); P1 is the raw peak.
// kP2Tol, 15 % of P2: Jenkins' formula is the response of one unsprung mass on a one-mass track
// to a step of vertical velocity; the model has the Hertz contact in series (linearised at P0,
// ~1.2 GN/m: alone it lowers the increment P2 - P0 by ~7 %), the primary suspension above the
// wheelset, and a two-mass track whose sleeper does not follow the static shape at 60 Hz.
// Measured: P2 7 % below Jenkins, the increment 18 % below (12 % below with the Hertz stiffness
// in series in kt).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "ferro/scenarios/analysis/signal_filter.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/track/track_structure.hpp"
#include "ferro/vehicle/integrator.hpp"

namespace ferro::scenarios {
namespace {

constexpr double kP2Tol = 0.15;

TEST(DippedJoint, p2_against_jenkins) {
  Scene scene = load_scene(std::string(FERRO_SOURCE_DIR) + "/tests/scenarios/data/dipped_joint.yaml");
  const auto system = build_system(scene, scene.simulation.speed);
  const std::vector<double> x0 = initial_state(scene, *system);
  const auto signals = system->signal_info();
  std::size_t left = 0, right = 0;
  for (std::size_t i = 0; i < signals.size(); ++i) {
    if (signals[i].name == "wheelset_1.left.Q") left = i;
    if (signals[i].name == "wheelset_1.right.Q") right = i;
  }
  ASSERT_NE(left, right);
  const double dt = scene.output.interval;
  std::vector<double> time, load, sig(signals.size());
  const auto result = vehicle::make_integrator(scene.solver)
                          ->integrate(*system, x0,
                                      vehicle::output_grid(0.0, scene.simulation.t_end, dt),
                                      [&](double t, std::span<const double> x) {
                                        system->signals(t, x, sig);
                                        time.push_back(t);
                                        load.push_back(0.5 * (sig[left] + sig[right]));
                                        return true;
                                      });
  ASSERT_EQ(result.status, vehicle::IntegrationResult::Status::kCompleted) << result.message;

  // When the leading wheelset (the foremost, its position x ahead of the vehicle centre at
  // start_position) reaches the joint.
  const auto& cfg = scene.model.vehicle;
  double mu = 0.0, ws_x = 0.0;
  for (const auto& b : cfg.bodies) {
    if (b.kind == vehicle::BodyKind::wheelset && b.position.x() > ws_x - 1e-9) {
      ws_x = b.position.x();
      mu = 0.5 * b.mass;
    }
  }
  const double v = scene.simulation.speed;
  const double joint_s = 60.0, alpha2 = 2.0 * 2.0 * 0.030 / 40.0;  // total angle 2 alpha
  const double t_joint = (joint_s - scene.simulation.start_position - ws_x) / v;
  ASSERT_GT(t_joint, 0.5);
  ASSERT_LT(t_joint + 0.05, scene.simulation.t_end);

  const analysis::AnalogFilter low_pass = analysis::butterworth_lowpass_analog(2, 150.0);
  const std::vector<double> filtered =
      analysis::filtfilt(analysis::bilinear(low_pass, 1.0 / dt), load,
                         analysis::edge_padding(low_pass, 1.0 / dt));
  double p0 = 0.0, p2 = 0.0, p1 = 0.0;
  int n0 = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] > t_joint - 0.10 && time[i] < t_joint - 0.02) {  // on the slope, settled
      p0 += filtered[i];
      ++n0;
    }
    if (time[i] >= t_joint && time[i] < t_joint + 0.03) {  // P1 and P2 follow within 30 ms
      p2 = std::max(p2, filtered[i]);
      p1 = std::max(p1, load[i]);
    }
  }
  ASSERT_GT(n0, 0);
  p0 /= n0;

  const track::CoRunningTrackParams p =
      track::co_running_equivalent(scene.track.structure.ballasted, 1.5);
  const double kp = p.pad_stiffness_vertical, kb = p.ballast_stiffness_vertical;
  const double share_rail = kb / (kp + kb), share_sleeper = kp / (kp + kb);
  const double kt = kp * kb / (kp + kb);
  const double mt = p.rail_mass_vertical + 0.5 * p.sleeper_mass_vertical * share_sleeper * share_sleeper;
  const double ct = p.pad_damping_vertical * share_rail * share_rail +
                    p.ballast_damping_vertical * share_sleeper * share_sleeper;
  const double jenkins =
      p0 + alpha2 * v * std::sqrt(mu / (mu + mt)) *
               (1.0 - std::numbers::pi * ct / (4.0 * std::sqrt(kt * (mu + mt)))) * std::sqrt(kt * mu);
  std::printf(
      "[ figures  ] 2 alpha %.1f mrad, V %.0f m/s; track per wheel kt %.1f MN/m, mt %.1f kg, ct "
      "%.1f kN s/m; mu %.0f kg. P0 %.1f kN, P2 %.1f kN (Jenkins %.1f kN, increment %+.1f %%), P1 "
      "%.1f kN\n",
      alpha2 * 1e3, v, kt / 1e6, mt, ct / 1e3, mu, p0 / 1e3, p2 / 1e3, jenkins / 1e3,
      100.0 * ((p2 - p0) / (jenkins - p0) - 1.0), p1 / 1e3);
  EXPECT_NEAR(p2 / jenkins, 1.0, kP2Tol);
  EXPECT_GT(p2 - p0, 0.5 * (jenkins - p0));  // the increment itself, within a factor 2
  EXPECT_GT(p1, p2);  // the P1 ringing rides above P2
}

}  // namespace
}  // namespace ferro::scenarios
