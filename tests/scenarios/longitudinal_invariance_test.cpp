// Translation invariance along a straight perfect track: Manchester vehicle 1 on S1002 / UIC60
// 1:40 (scenarios/scenes/manchester_critical_speed.yaml), every body free lengthwise, the
// wheelsets free to spin. Moving the whole vehicle forward by dx (every body's x, no velocity)
// changes nothing physical, so every acceleration must stay what it was at the equilibrium.
// A wheel-rail coupling that left the contact point at the wheelset's rest x while the axle
// moved would put the normal force a lever dx ahead of or behind the axle: a moment N dx about
// the axle (11 N m per 0.1 mm on this vehicle) that spins the wheelset up as it moves forward,
// which runs away with the bogie (a real eigenvalue of +4.5 /s at 75 m/s on the thesis setup).
#include <gtest/gtest.h>

#include <cmath>

#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::scenarios {
namespace {

TEST(LongitudinalInvariance, moving_the_whole_vehicle_forward_changes_no_acceleration) {
  Scene s = load_scene(std::string(FERRO_SOURCE_DIR) +
                       "/scenarios/scenes/manchester_critical_speed.yaml");
  for (auto& b : s.model.vehicle.bodies) {
    b.active[static_cast<std::size_t>(vehicle::Dof::x)] = true;
    if (b.kind == vehicle::BodyKind::wheelset) b.spin_dof = true;
  }
  const auto sys = build_system(s, 60.0);
  const auto& model = dynamic_cast<const vehicle::VehicleModel&>(*sys);
  const auto x_eq = vehicle::static_equilibrium(model, 0.0);
  std::vector<double> shifted = x_eq, a0(x_eq.size()), a1(x_eq.size());
  constexpr double kShift = 1e-3;  // [m]
  int moved = 0;
  for (const auto& b : s.model.vehicle.bodies) {
    const int q = model.state_index(b.name, vehicle::Dof::x);
    ASSERT_GE(q, 0) << b.name;
    shifted[static_cast<std::size_t>(q)] += kShift;
    ++moved;
  }
  EXPECT_EQ(moved, 7);
  ASSERT_EQ(sys->rhs(0.0, x_eq, a0), 0);
  ASSERT_EQ(sys->rhs(0.0, shifted, a1), 0);
  const auto info = sys->state_info();
  // Accelerations at the equilibrium are round-off of forces of ~50 kN on ~2 t bodies; the
  // tolerance is 1e-9 g, and the moment N dx of a misplaced contact point gives 0.1 rad/s^2 on
  // a wheelset's spin.
  constexpr double kTol = 1e-8;  // [m/s^2, rad/s^2]
  for (std::size_t i = 0; i < a0.size(); ++i)
    EXPECT_NEAR(a1[i], a0[i], kTol) << info[i].name;
}

}  // namespace
}  // namespace ferro::scenarios
