// Suspension elements of the multibody model against closed forms: a body standing on 100 mm
// cant and held sideways only by a bump stop settles where the table gives the downhill weight
// component; held by a damper with series stiffness it creeps downhill at F / c.
#include <gtest/gtest.h>

#include <cmath>

#include "conical_test_source.hpp"
#include "ferro/track/track.hpp"
#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::vehicle {
namespace {

constexpr double kG = 9.81;
constexpr double kMass = 1000.0;
constexpr double kCant = 0.100;  // over the 1.5 m rail spacing

/// One body (lateral DOF only) on a canted curve at rest, attached to the track frame by
/// `element`. Downhill is +y (positive cant raises the right rail).
VehicleModelInputs body_on_cant(const SuspensionElementSpec& element) {
  VehicleModelInputs in;
  RigidBodySpec b;
  b.name = "car_body";
  b.kind = BodyKind::car_body;
  b.mass = kMass;
  b.inertia = {1000.0, 1000.0, 1000.0};
  b.position = {0.0, 0.0, 1.0};
  b.active = {false, true, false, false, false, false};
  in.config.bodies.push_back(b);
  in.config.elements.push_back(element);
  in.config.gravity = kG;
  track::TrackDesign design;
  track::SectionSpec curve{track::SectionKind::kCurve, 200.0};
  curve.radius = 5000.0;
  curve.cant = kCant;
  design.sections.push_back(curve);
  in.track = std::make_shared<track::Track>(track::Alignment(design));
  in.start_position = 100.0;
  in.geometry = std::make_shared<testing::ConicalTestSource>(testing::ConicalTestParams{});
  return in;
}

double downhill_force() { return kMass * kG * kCant / 1.5; }  // m g sin(phi) [N]

TEST(VehicleModelElements, bump_stop_holds_the_downhill_weight_where_its_table_says) {
  // Closed form: linear interpolation of the table at F = m g sin(phi); Newton on a piecewise
  // linear law converges to round-off.
  constexpr double kTol = 1e-9;  // [m]
  SuspensionElementSpec stop;
  stop.name = "stop";
  stop.type = ElementType::bump_stop;
  stop.axis = Dof::y;
  stop.body_a = -1;
  stop.body_b = 0;
  stop.point_a = {0.0, 0.0, 1.0};
  stop.clearance = 0.025;
  stop.table_displacement = {0.025, 0.030, 0.035, 0.040};
  stop.table_force = {0.0, 600.0, 1760.0, 3730.0};
  const VehicleModel m(body_on_cant(stop));
  std::vector<double> guess = m.rest_state();  // start on the table, beyond the free play
  guess[static_cast<std::size_t>(m.state_index("car_body", Dof::y))] = 0.03;
  const auto x = static_equilibrium(m, 0.0, guess);
  const double f = downhill_force();  // 654 N: between 600 and 1760 N
  ASSERT_GT(f, 600.0);
  ASSERT_LT(f, 1760.0);
  const double expected = 0.030 + 0.005 * (f - 600.0) / (1760.0 - 600.0);
  EXPECT_NEAR(x[static_cast<std::size_t>(m.state_index("car_body", Dof::y))], expected, kTol);
}

TEST(VehicleModelElements, series_damper_creeps_downhill_at_force_over_damping) {
  // Maxwell element (k in series with c) under a constant force F: after the transient
  // (time constant ~ c/k and the mass-spring period) the body moves at v = F / c and the spring
  // carries F. Integrated to 2 s with c/k = 5 ms; rtol 1e-8 => 1e-6 relative is loose.
  constexpr double kRelTol = 1e-6;
  SuspensionElementSpec damper;
  damper.name = "yaw_damper";
  damper.type = ElementType::series_damper;
  damper.axis = Dof::y;
  damper.body_a = -1;
  damper.body_b = 0;
  damper.point_a = {0.0, 0.0, 1.0};
  damper.k = 2.0e6;
  damper.c = 1.0e4;
  const VehicleModel m(body_on_cant(damper));
  ASSERT_EQ(m.size(), 3u);
  IntegratorSettings s;
  s.rtol = 1e-8;
  s.atol = 1e-12;
  auto integrator = make_integrator(s);
  const auto r =
      integrator->integrate(m, m.rest_state(), output_grid(0.0, 2.0, 0.1), [](double, auto) {
        return true;
      });
  ASSERT_EQ(r.status, IntegrationResult::Status::kCompleted) << r.message;
  const double v = r.state[static_cast<std::size_t>(m.rate_index("car_body", Dof::y))];
  EXPECT_NEAR(v / (downhill_force() / damper.c), 1.0, kRelTol);
}

}  // namespace
}  // namespace ferro::vehicle
