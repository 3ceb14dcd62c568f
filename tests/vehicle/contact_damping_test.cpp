// Hunt-Crossley damping of the wheel-rail normal force (wheel_rail.hunt_crossley_alpha):
//  - hunt_crossley_bounce: a wheelset bouncing on its two Hertz contacts decays at the closed-form
//    damping ratio of the linearised oscillator (k = 3 N0 / (2 delta0) per wheel from Hertz,
//    c = alpha N0 per wheel from Hunt & Crossley 1975), in the eigenvalues and in a time run;
//  - the penetration rate the damping uses is the time derivative of the Hertz penetration
//    along a trajectory through lateral, vertical and cross-level defects (true cone): the
//    damped force equals N (1 + alpha d(delta)/dt) with d(delta)/dt by central differences of
//    the undamped model;
//  - the static equilibrium does not depend on the damping.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "conical_test_source.hpp"
#include "ferro/contact/material.hpp"
#include "ferro/contact/normal/hertz.hpp"
#include "ferro/track/irregularity.hpp"
#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/stability.hpp"
#include "ferro/vehicle/vehicle_model.hpp"
#include "manchester_config.hpp"

namespace ferro::vehicle {
namespace {

constexpr double kG = 9.81;
constexpr double kMass = 1813.0;                                   // Manchester wheelset [kg]
constexpr double kA = 1.0 / (2.0 * 0.46), kB = 1.0 / (2.0 * 0.3);  // relative curvatures [1/m]

/// A wheelset free to move vertically only, on two flat Hertz contacts (no suspension).
VehicleModelInputs bouncing_wheelset(double alpha) {
  VehicleModelInputs in;
  RigidBodySpec w;
  w.name = "wheelset_1";
  w.kind = BodyKind::wheelset;
  w.mass = kMass;
  w.inertia = {kMass * 0.75 * 0.75, 0.1 * kMass * 0.46 * 0.46, kMass * 0.75 * 0.75};
  w.position = {0.0, 0.0, 0.46};
  w.nominal_rolling_radius = 0.46;
  w.active = {false, false, true, false, false, false};
  in.config.bodies.push_back(w);
  in.config.wheel_rail.tangential_model = "kalker_linear";
  in.config.wheel_rail.hunt_crossley_alpha = alpha;
  in.config.gravity = kG;
  in.selection.scope = "wheelset";
  testing::ConicalTestParams g;
  g.curvature_a = kA;
  g.curvature_b = kB;
  in.geometry = std::make_shared<testing::ConicalTestSource>(g);
  in.speed.initial = 10.0;
  return in;
}

/// Closed-form linearised oscillator of bouncing_wheelset(): natural frequency [rad/s] and
/// damping ratio.
struct Oscillator {
  double omega_n = 0.0, zeta = 0.0;
};
Oscillator linearised_bounce(double alpha) {
  const double n0 = 0.5 * kMass * kG;  // static load per wheel [N]
  const auto mat = contact::combine(contact::Material::steel(), contact::Material::steel());
  const double delta0 = contact::hertz_solve(kA, kB, n0, mat.contact_modulus).approach;
  const double k = 2.0 * 1.5 * n0 / delta0;  // two wheels, dN/d(delta) = 3 N / (2 delta)
  const double c = 2.0 * alpha * n0;         // two wheels, dN/d(delta_dot) = alpha N
  Oscillator o;
  o.omega_n = std::sqrt(k / kMass);
  o.zeta = c / (2.0 * std::sqrt(k * kMass));
  return o;
}

TEST(HuntCrossley, bounce_eigenvalue_matches_the_linearised_damping_ratio) {
  // Central-difference Jacobian about the static state (relative steps ~1e-7): the eigenvalue
  // agrees with the closed form to far better than 1e-4.
  constexpr double kRelTol = 1e-4;
  for (double alpha : {1.0, 3.0, 10.0}) {
    const VehicleModel m(bouncing_wheelset(alpha));
    const auto modes = linear_modes(m, 0.0, static_equilibrium(m));
    ASSERT_EQ(modes.size(), 2u);  // one complex pair
    const Oscillator o = linearised_bounce(alpha);
    EXPECT_NEAR(modes.front().damping_ratio / o.zeta, 1.0, kRelTol) << "alpha " << alpha;
    EXPECT_NEAR(std::abs(modes.front().eigenvalue) / o.omega_n, 1.0, kRelTol);
    std::printf(
        "Hunt-Crossley bounce, alpha %4.1f s/m: zeta closed form %.6f, eigenvalue %.6f "
        "(rel. error %.1e); omega_n %.2f rad/s (rel. error %.1e)\n",
        alpha, o.zeta, modes.front().damping_ratio, modes.front().damping_ratio / o.zeta - 1.0,
        o.omega_n, std::abs(modes.front().eigenvalue) / o.omega_n - 1.0);
  }
}

TEST(HuntCrossley, bounce_decays_at_the_linearised_damping_ratio) {
  // Released 1 % of the static penetration below its rest height: the logarithmic decrement of
  // successive peaks gives the damping ratio. The Hertz force is nonlinear; at 1 % amplitude
  // the stiffness and the damping coefficient vary by +-0.5 % and +-1 % over a cycle, and peak
  // times are located by parabolas through sampled points (400 per period): 1 % tolerance.
  constexpr double kRelTol = 1e-2;
  constexpr double kAlpha = 10.0;  // [s/m], zeta ~ 0.06
  const Oscillator o = linearised_bounce(kAlpha);
  const VehicleModel m(bouncing_wheelset(kAlpha));
  std::vector<double> x0 = static_equilibrium(m);
  const auto iz = static_cast<std::size_t>(m.state_index("wheelset_1", Dof::z));
  const double z_eq = x0[iz];
  const double amplitude = 0.01 * std::abs(z_eq);
  x0[iz] -= amplitude;

  IntegratorSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-16;
  const double period = 2.0 * std::numbers::pi / o.omega_n;
  std::vector<double> z;
  const auto observer = [&](double, std::span<const double> x) {
    z.push_back(x[iz] - z_eq);
    return true;
  };
  const auto result = make_integrator(s)->integrate(
      m, x0, output_grid(0.0, 6.0 * period, period / 400.0), observer);
  ASSERT_EQ(result.status, IntegrationResult::Status::kCompleted) << result.message;

  // Minima (the wheelset is released below rest): parabolic peak values.
  std::vector<double> peaks;
  for (std::size_t i = 1; i + 1 < z.size(); ++i) {
    if (z[i] < z[i - 1] && z[i] <= z[i + 1]) {
      const double a = 0.5 * (z[i - 1] + z[i + 1]) - z[i], b = 0.5 * (z[i + 1] - z[i - 1]);
      peaks.push_back(std::abs(z[i] - b * b / (4.0 * a)));
    }
  }
  ASSERT_GE(peaks.size(), 4u);
  const double cycles = static_cast<double>(peaks.size() - 1);
  const double decrement = std::log(peaks.front() / peaks.back()) / cycles;
  const double zeta =
      decrement / std::sqrt(4.0 * std::numbers::pi * std::numbers::pi + decrement * decrement);
  EXPECT_NEAR(zeta / o.zeta, 1.0, kRelTol) << "closed form " << o.zeta << ", run " << zeta;
  std::printf(
      "Hunt-Crossley bounce, alpha %.1f s/m: zeta closed form %.5f, time run %.5f "
      "(rel. error %.1e)\n",
      kAlpha, o.zeta, zeta, zeta / o.zeta - 1.0);
  // Undamped: no decay at all (the Hertz spring conserves energy).
  const VehicleModel m0(bouncing_wheelset(0.0));
  z.clear();
  const auto r0 = make_integrator(s)->integrate(
      m0, x0, output_grid(0.0, 3.0 * period, period / 400.0), observer);
  ASSERT_EQ(r0.status, IntegrationResult::Status::kCompleted) << r0.message;
  double lowest_late = 0.0;
  for (std::size_t i = z.size() / 2; i < z.size(); ++i) lowest_late = std::min(lowest_late, z[i]);
  EXPECT_NEAR(-lowest_late / amplitude, 1.0, kRelTol);
}

// Manchester vehicle 1 on a true cone (contact angle atan 0.1), one wheelset with its primary
// suspension, over lateral, vertical and cross-level defects.
VehicleModelInputs wheelset_over_defects(double alpha) {
  VehicleModelInputs in;
  in.config = testing::manchester_vehicle1(kG);
  WheelRailSpec& wr = in.config.wheel_rail;
  wr.geometry = "conical";
  wr.nominal_radius = 0.46;
  wr.conicity = 0.1;
  wr.contact_half_distance = 0.75;
  wr.conical_curvature_a = kA;
  wr.conical_curvature_b = kB;
  wr.hunt_crossley_alpha = alpha;
  in.geometry = make_geometry_source(wr, FERRO_DATA_DIR);
  in.selection.scope = "wheelset";
  auto irr = std::make_shared<track::IrregularitySum>();
  const std::pair<track::IrregularityChannel, double> defects[] = {
      {track::IrregularityChannel::kLateral, 0.004},
      {track::IrregularityChannel::kVertical, -0.003},
      {track::IrregularityChannel::kCrossLevel, 0.005}};
  double start = 100.0;
  for (const auto& [channel, amplitude] : defects) {
    track::IsolatedDefectSpec d;
    d.channel = channel;
    d.amplitude = amplitude;
    d.wavelength = 8.0 + start / 100.0;  // different phases at the probe point
    d.start_s = start;
    irr->add(std::make_shared<track::IsolatedDefect>(d));
    start += 1.5;
  }
  track::TrackDesign design;
  design.sections.push_back({track::SectionKind::kStraight, 500.0});
  in.track = std::make_shared<track::Track>(track::Alignment(design), irr);
  // The leading wheelset (rest x 10.78 m) at s = 105 m, inside all three defects.
  in.start_position = 105.0 - 10.78;
  in.speed.initial = 30.0;
  return in;
}

std::size_t index_of(const std::vector<SignalInfo>& info, const std::string& name) {
  for (std::size_t i = 0; i < info.size(); ++i) {
    if (info[i].name == name) return i;
  }
  ADD_FAILURE() << "no signal " << name;
  return 0;
}

TEST(HuntCrossley, penetration_rate_is_the_rate_of_the_hertz_penetration) {
  // Oracle: delta(t) = (N(t) / K)^(2/3) of the undamped model (a cone keeps its curvatures, so
  // K is fixed), differentiated by central differences of step h along x(t) = x0 + h x0'
  // (positions moved by their rates; the defects move under the wheelset at V). Difference
  // error ~ h^2 delta''' / 6: 1e-6 relative on the damping term alpha delta_dot (~1e-2 of N).
  constexpr double kAlpha = 3.0;  // [s/m]
  constexpr double kStep = 1e-6;  // [s]
  constexpr double kRelTolDampingTerm = 1e-5;
  const VehicleModel damped(wheelset_over_defects(kAlpha));
  const VehicleModel undamped(wheelset_over_defects(0.0));
  const auto states = damped.state_info();
  std::vector<double> x0 = damped.rest_state();
  const auto set = [&](const std::string& name, double value) {
    x0[index_of(states, name)] = value;
  };
  // Static position over the defects, wheelset moving laterally, vertically and in roll.
  x0 = static_equilibrium(undamped);
  set("wheelset_1.y_dot", 0.05);
  set("wheelset_1.z_dot", -0.004);
  set("wheelset_1.roll_dot", 0.03);
  std::vector<double> rates(x0.size(), 0.0);
  for (const char* dof : {"y", "z", "roll", "yaw"}) {
    const std::string body = "wheelset_1.";
    rates[index_of(states, body + dof)] = x0[index_of(states, body + dof + "_dot")];
  }
  // Yaw is held still: the damping leaves the yaw rate's share out (documented).
  x0[index_of(states, "wheelset_1.yaw_dot")] = 0.0;
  rates[index_of(states, "wheelset_1.yaw")] = 0.0;

  const auto info = damped.signal_info();
  std::vector<double> sig(info.size());
  const auto force = [&](const VehicleModel& m, double t, double shift, const char* side) {
    std::vector<double> x = x0;
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += shift * rates[i];
    m.signals(t, x, sig);
    return sig[index_of(info, std::string("wheelset_1.") + side + ".normal_force")];
  };
  const double t0 = 0.0;
  for (const char* side : {"left", "right"}) {
    const double n0 = force(undamped, t0, 0.0, side);
    ASSERT_GT(n0, 10e3) << side;
    const double delta_plus = std::pow(force(undamped, t0 + kStep, kStep, side), 2.0 / 3.0);
    const double delta_minus = std::pow(force(undamped, t0 - kStep, -kStep, side), 2.0 / 3.0);
    const double delta = std::pow(n0, 2.0 / 3.0);  // all three in units of K^(-2/3)
    const double rate = (delta_plus - delta_minus) / (2.0 * kStep) / delta;  // delta_dot / delta
    const auto mat = contact::combine(contact::Material::steel(), contact::Material::steel());
    const double delta_m = contact::hertz_solve(kA, kB, n0, mat.contact_modulus).approach;  // [m]
    const double expected_term = kAlpha * rate * delta_m;  // alpha d(delta)/dt
    ASSERT_GT(std::abs(expected_term), 1e-3) << side << ": the probe must move the contact";
    const double damped_term = force(damped, t0, 0.0, side) / n0 - 1.0;
    EXPECT_NEAR(damped_term / expected_term, 1.0, kRelTolDampingTerm) << side;
    std::printf(
        "%s wheel: alpha delta_dot %.6e (central differences) against %.6e (model), "
        "rel. error %.1e\n",
        side, expected_term, damped_term, damped_term / expected_term - 1.0);
  }
}

TEST(HuntCrossley, static_equilibrium_does_not_depend_on_the_damping) {
  // At rest the penetration rate is zero: the same equilibrium to the solver's tolerance.
  constexpr double kTol = 1e-12;  // [m] / [rad]
  VehicleModelInputs in0 = wheelset_over_defects(0.0);
  VehicleModelInputs in1 = wheelset_over_defects(10.0);
  in0.selection.scope = in1.selection.scope = "vehicle";
  in0.track = in1.track = nullptr;
  in0.speed.initial = in1.speed.initial = 0.0;
  const auto x0 = static_equilibrium(VehicleModel(std::move(in0)));
  const auto x1 = static_equilibrium(VehicleModel(std::move(in1)));
  ASSERT_EQ(x0.size(), x1.size());
  for (std::size_t i = 0; i < x0.size(); ++i) EXPECT_NEAR(x0[i], x1[i], kTol) << "state " << i;
}

TEST(HuntCrossley, negative_alpha_is_refused) {
  EXPECT_THROW(VehicleModel(bouncing_wheelset(-1.0)), std::invalid_argument);
  EXPECT_THROW(VehicleModel(bouncing_wheelset(std::nan(""))), std::invalid_argument);
}

}  // namespace
}  // namespace ferro::vehicle
