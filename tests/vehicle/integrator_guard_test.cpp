// What every integrator adapter checks at each step, against closed forms: the divergence guard
// (x' = x from x(0) = 1 leaves the bound 100 at t* = ln 100, and the run must stop there as a
// solver failure, no output beyond the bound) and the stop request (honoured between two
// right-hand sides, the run ending at a completed step whose state is the exact e^t); and the
// state bounds the models derive from their geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ferro/contact/geometry/conical_source.hpp"
#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/suspended_wheelset.hpp"
#include "ferro/vehicle/vehicle_model.hpp"
#include "manchester_config.hpp"

namespace ferro::vehicle {
namespace {

constexpr double kBound = 100.0;

// x' = x, bounded by kBound; counts its right-hand sides.
class Growth final : public OdeSystem {
 public:
  std::size_t size() const override { return 1; }
  int rhs(double, std::span<const double> x, std::span<double> xd) const override {
    ++calls;
    xd[0] = x[0];
    return kRhsOk;
  }
  std::vector<SignalInfo> state_info() const override { return {{"x", "m", ""}}; }
  std::vector<StateBound> state_bounds() const override {
    return {{0, kBound, "the test's bound"}};
  }
  mutable long calls = 0;
};

IntegratorSettings settings_for(const std::string& method) {
  IntegratorSettings s;
  s.method = method;
  s.rtol = 1e-8;
  s.atol = 1e-10;
  if (method == "odeint_bs3" || method == "bdf2") s.fixed_step = 1e-3;
  return s;
}

class EveryAdapter : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryAdapter, stops_where_the_state_leaves_its_bound) {
  Growth sys;
  const double t_cross = std::log(kBound);  // 4.605 s
  double last_output = -1.0, largest = 0.0;
  const auto r = make_integrator(settings_for(GetParam()))
                     ->integrate(sys, std::vector<double>{1.0}, output_grid(0.0, 10.0, 0.1),
                                 [&](double t, std::span<const double> x) {
                                   last_output = t;
                                   largest = std::max(largest, std::abs(x[0]));
                                   return true;
                                 });
  EXPECT_EQ(r.status, IntegrationResult::Status::kSolverFailure) << r.message;
  EXPECT_NE(r.message.find("beyond its bound"), std::string::npos) << r.message;
  EXPECT_LE(largest, kBound);  // no output beyond the bound reached the observer
  // Found at the first step end or output past the crossing: not before it (to the solver's
  // accuracy), and before the next output.
  EXPECT_GE(r.t_reached, t_cross - 1e-6) << r.message;
  EXPECT_LE(r.t_reached, t_cross + 0.1) << r.message;
  EXPECT_LT(last_output, t_cross);
  ASSERT_EQ(r.state.size(), 1u);
  EXPECT_GT(r.state[0], kBound);
}

TEST_P(EveryAdapter, a_stop_request_ends_the_run_at_a_completed_step) {
  Growth sys;
  auto integ = make_integrator(settings_for(GetParam()));
  // Stop once 30 right-hand sides have been evaluated: between two outputs 1 s apart (every
  // method needs more than that for the 4 s).
  integ->set_stop_request([&] { return sys.calls >= 30; });
  int outputs = 0;
  const auto r = integ->integrate(sys, std::vector<double>{1.0}, output_grid(0.0, 4.0, 1.0),
                                  [&](double, std::span<const double>) {
                                    ++outputs;
                                    return true;
                                  });
  EXPECT_EQ(r.status, IntegrationResult::Status::kInterrupted) << r.message;
  EXPECT_LT(r.t_reached, 4.0);
  // No right-hand side after the request, but those of a Jacobian under way (rosenbrock4 forms
  // its own: 2 n + 2 = 4 evaluations).
  EXPECT_LE(sys.calls, 30 + 4);
  ASSERT_EQ(r.state.size(), 1u);
  // The state of a completed step: e^t to the method's accuracy.
  EXPECT_NEAR(r.state[0], std::exp(r.t_reached), 1e-5 * std::exp(r.t_reached)) << r.t_reached;
}

INSTANTIATE_TEST_SUITE_P(Integrators, EveryAdapter,
                         ::testing::Values("cvode_bdf", "cvode_adams", "arkode_erk",
                                           "arkode_dirk", "odeint_dopri5", "odeint_rosenbrock4",
                                           "odeint_bs3", "bdf2"));

TEST(StateBounds, the_vehicle_bounds_follow_its_track_and_wheel_geometry) {
  // The Manchester vehicle on conical wheels (gamma 0.1, e 0.75 m).
  contact::ConicalContactParams cone;
  cone.conicity = 0.1;
  cone.contact_half_distance = 0.75;
  cone.nominal_radius = 0.46;
  cone.curvature_a = 1.0 / (2.0 * 0.46);
  cone.curvature_b = 1.0 / (2.0 * 0.3);
  VehicleModelInputs in;
  in.config = testing::manchester_vehicle1();
  in.geometry = std::make_shared<contact::ConicalContactSource>(cone);
  in.speed.initial = 30.0;
  const VehicleModel m(std::move(in));
  const auto& wr = m.inputs().config.wheel_rail;
  const double flangeway = 0.5 * (wr.track_gauge - wr.flange_back_distance);  // 37.5 mm
  const auto bounds = m.state_bounds();
  const auto info = m.state_info();
  int wheelset_lateral = 0;
  for (const StateBound& b : bounds) {
    const std::string& name = info[b.index].name;
    const bool angle = info[b.index].unit == "rad";
    if (angle) {
      EXPECT_DOUBLE_EQ(b.limit, 0.5) << name;
    } else if (name.rfind("wheelset_", 0) == 0 && !name.ends_with(".x")) {
      EXPECT_DOUBLE_EQ(b.limit, 2.0 * flangeway) << name;
      wheelset_lateral += name.ends_with(".y") ? 1 : 0;
    } else {
      EXPECT_DOUBLE_EQ(b.limit, 0.5 * wr.track_gauge) << name;
    }
    EXPECT_FALSE(b.reason.empty());
  }
  EXPECT_EQ(wheelset_lateral, 4);
  // The static equilibrium lies well inside them.
  const auto x = static_equilibrium(m);
  for (const StateBound& b : bounds) EXPECT_LT(std::abs(x[b.index]), 0.1 * b.limit);
}

TEST(StateBounds, the_linear_wheelset_keeps_its_contact_points_on_the_rails) {
  SuspendedWheelsetParams p;
  p.mass = 1887;
  p.yaw_inertia = 1887 * 0.7465 * 0.7465;
  p.half_gauge = 0.7465;
  p.rolling_radius = 0.4575;
  p.conicity = 0.05;
  p.primary_stiffness_x = p.primary_stiffness_y = 1e6;
  const SuspendedWheelset w(p, CreepCoefficients{1e7, 1e7}, 30.0);
  const auto b = w.state_bounds();
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].index, 0u);
  EXPECT_DOUBLE_EQ(b[0].limit, 0.7465);
  EXPECT_EQ(b[1].index, 1u);
  EXPECT_DOUBLE_EQ(b[1].limit, 0.5);
}

}  // namespace
}  // namespace ferro::vehicle
