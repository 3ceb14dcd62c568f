// Vehicle scenes: the scene's contact and track parts override the vehicle file's wheel-rail
// block key by key, the model selection and speed ramp are read, and --tangential replaces the
// creep model. Oracle: the values written in tests/scenarios/data/vehicle_overrides.yaml and in
// scenarios/vehicles/manchester_vehicle1.yaml.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::scenarios {
namespace {

const std::string kScene = "tests/scenarios/data/vehicle_overrides.yaml";

TEST(VehicleScene, contact_and_track_parts_override_the_vehicle_file) {
  const Scene s = load_scene(kScene);
  ASSERT_EQ(s.model.type, "vehicle");
  EXPECT_EQ(s.model.vehicle.name, "manchester_vehicle1");
  const auto& w = s.model.vehicle.wheel_rail;
  EXPECT_EQ(w.geometry, "search");
  EXPECT_EQ(w.friction, 0.4);
  EXPECT_EQ(w.tangential_model, "fastsim");
  EXPECT_EQ(w.tangential_options.at("mx"), "12");
  EXPECT_EQ(w.reduction.k11, 0.5);
  EXPECT_EQ(w.reduction.k22, 0.6);
  EXPECT_EQ(w.reduction.k23, 1.0);
  EXPECT_EQ(w.regularisation_speed, 0.5);
  EXPECT_EQ(w.track_gauge, 1.445);       // from the track part
  EXPECT_EQ(s.track.design.gauge, 1.445);
  EXPECT_EQ(w.rail_inclination, 0.025);  // from the track part
  EXPECT_EQ(w.shear_modulus, 82.0e9);    // kept from the vehicle file
  EXPECT_EQ(w.flange_back_distance, 1.360);
  EXPECT_EQ(s.model.selection.scope, "bogie");
  EXPECT_EQ(s.model.selection.index, 1);
  EXPECT_EQ(s.model.selection.frozen, (std::vector<std::string>{"wheelset_3.roll", "z"}));
  EXPECT_EQ(s.simulation.speed, 0.0);
  EXPECT_EQ(s.simulation.acceleration, 1.5);
  EXPECT_EQ(s.simulation.start_position, 20.0);
  EXPECT_EQ(s.simulation.initial.at("wheelset_3.y"), 1.0e-3);
  EXPECT_EQ(s.simulation.initial_position.at("wheelset_3.y").first, 26);  // its line
  // The included vehicle file is kept in the scene text written to the output.
  EXPECT_NE(s.text.find("included: "), std::string::npos);
  EXPECT_NE(s.text.find("Manchester benchmark vehicle 1"), std::string::npos);
}

TEST(VehicleScene, thesis_conical_tread_rolls_as_a_one_in_ten_cone) {
  // The thesis pair (S1002 with a 1/10 conical tread on UIC60 inclined 1:10) as the thesis
  // scenes select it. Oracle, a cone: while both wheels touch the cone, the rolling-radius
  // difference is exactly 2 gamma y (gamma = 0.1) and the contact angle relative to the axle is
  // atan(0.1) on both wheels. Tolerances: the table is interpolated on its lateral grid, and the
  // contact point moves on the rail crown but not off the cone for |y| <= 4 mm.
  // Second oracle, the thesis' wheel diameter (table 3.1, d0 = 920 mm): centred, both wheels roll
  // on 0.46 m, the radius the wheelsets turn at (V/r0), so a coasting vehicle has no steady
  // longitudinal creepage. Tolerance: the cone from the S1002 tread-section bound (-26 mm)
  // passes 0.14 mm above r0 at the taping line and the centred contact lies 1-2 mm outboard of
  // it; a cone from -15 mm rolls 0.69 mm small there.
  constexpr double kConicity = 0.1;
  constexpr double kNominalRadius = 0.46;       // m, thesis table 3.1 and the vehicle file
  constexpr double kCentredRadiusTol = 0.1e-3;  // m, see above
  constexpr double kRadiusDiffTol = 0.02;       // relative, table interpolation
  constexpr double kAngleTol = 2.0e-3;          // rad, table interpolation
  const Scene s = load_scene("scenarios/scenes/thesis_critical_speed.yaml");
  const auto& w = s.model.vehicle.wheel_rail;
  EXPECT_EQ(w.wheel_tread_conicity, kConicity);
  EXPECT_EQ(w.wheel_tread_join_y, -0.026);
  const auto source = vehicle::make_geometry_source(w, "");
  std::vector<contact::WheelRailContact> points;
  for (const double y : {-4.0e-3, -2.0e-3, 0.0, 2.0e-3, 4.0e-3}) {
    // Lower the wheelset until both wheels touch (0.02 mm steps): the rigid contact state.
    contact::WheelsetPose pose;
    pose.lateral = y;
    double r[2] = {NAN, NAN};
    for (pose.vertical = -5.0e-3; pose.vertical < 10.0e-3; pose.vertical += 0.02e-3) {
      source->contacts(pose, points);
      r[0] = r[1] = NAN;
      for (const auto& c : points) r[static_cast<int>(c.side)] = c.rolling_radius;
      if (std::isfinite(r[0]) && std::isfinite(r[1])) break;
    }
    for (const auto& c : points)
      EXPECT_NEAR(std::abs(c.contact_angle), std::atan(kConicity), kAngleTol) << y;
    ASSERT_TRUE(std::isfinite(r[0]) && std::isfinite(r[1])) << y;
    if (y == 0.0) {
      EXPECT_NEAR(r[0], kNominalRadius, kCentredRadiusTol);
      EXPECT_NEAR(r[1], kNominalRadius, kCentredRadiusTol);
      continue;
    }
    // Shift to the right (+y, contact frame): the right wheel rolls on a larger radius.
    EXPECT_NEAR((r[1] - r[0]) / (2.0 * kConicity * y), 1.0, kRadiusDiffTol) << y;
  }
}

TEST(VehicleScene, tangential_override) {
  Scene s = load_scene(kScene);
  override_tangential(s, "fastsim", "--tangential");  // same model: options kept
  EXPECT_EQ(s.model.vehicle.wheel_rail.tangential_options.size(), 2u);
  override_tangential(s, "chopaya", "--tangential");
  EXPECT_EQ(s.model.vehicle.wheel_rail.tangential_model, "chopaya");
  EXPECT_TRUE(s.model.vehicle.wheel_rail.tangential_options.empty());
  try {
    override_tangential(s, "chopya", "--tangential");
    FAIL() << "accepted an unknown model";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--tangential: unknown tangential model 'chopya'"),
              std::string::npos)
        << e.what();
  }
  Scene legacy = load_scene("scenarios/scenes/wheelset_hunting.yaml");
  EXPECT_THROW(override_tangential(legacy, "fastsim", "--tangential"), std::invalid_argument);
}

TEST(VehicleScene, normal_override) {
  Scene s = load_scene("scenarios/scenes/thesis_1in10_erri_low_semi_hertz.yaml");
  EXPECT_EQ(s.model.vehicle.wheel_rail.normal_model, "semi_hertz");
  override_normal(s, "hertz", "--normal");
  EXPECT_EQ(s.model.vehicle.wheel_rail.normal_model, "hertz");
  const auto message = [](Scene& scene, const std::string& name) {
    try {
      override_normal(scene, name, "--normal");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(message(s, "semi-hertz").find("--normal: unknown normal model 'semi-hertz'; allowed: "
                                          "hertz, semi_hertz"),
            std::string::npos);
  // The imported one-point table has no profiles, so no gap for semi-Hertz.
  Scene imported = load_scene("scenarios/scenes/cooperrider_straight.yaml");
  EXPECT_NE(message(imported, "semi_hertz").find("geometry 'imported'"), std::string::npos)
      << message(imported, "semi_hertz");
  EXPECT_EQ(imported.model.vehicle.wheel_rail.normal_model, "hertz");
}

}  // namespace
}  // namespace ferro::scenarios
