#pragma once
// Manchester benchmark vehicle 1 (data/manchester_vehicle1.yaml: passenger coach on two two-axle
// bogies) as an explicit VehicleConfig for the vehicle tests: the numbers of that file, per
// axlebox primary and per side secondary elements, weights carried by spring preloads.

#include <cmath>

#include "ferro/vehicle/vehicle_config.hpp"

namespace ferro::vehicle::testing {

struct ManchesterMasses {
  static constexpr double car = 32000.0, bogie = 2615.0, wheelset = 1813.0;  // [kg]
  static constexpr double total() { return car + 2.0 * bogie + 4.0 * wheelset; }
};

inline VehicleConfig manchester_vehicle1(double gravity = 9.81) {
  VehicleConfig cfg;
  cfg.name = "manchester_vehicle1";
  cfg.gravity = gravity;
  const double r0 = 0.46, semi_bogie = 9.5, semi_base = 1.28, h_sec = 0.8275;
  RigidBodySpec car;
  car.name = "car_body";
  car.kind = BodyKind::car_body;
  car.mass = ManchesterMasses::car;
  car.inertia = {56800.0, 1970000.0, 1970000.0};
  car.position = {0.0, 0.0, 1.8};
  cfg.bodies.push_back(car);
  for (int b = 0; b < 2; ++b) {
    const double xb = b == 0 ? semi_bogie : -semi_bogie;
    RigidBodySpec frame;
    frame.name = b == 0 ? "bogie_1" : "bogie_2";
    frame.kind = BodyKind::bogie_frame;
    frame.mass = ManchesterMasses::bogie;
    frame.inertia = {1722.0, 1476.0, 3067.0};
    frame.position = {xb, 0.0, 0.6};
    cfg.bodies.push_back(frame);
  }
  for (int w = 0; w < 4; ++w) {
    const double xb = w < 2 ? semi_bogie : -semi_bogie;
    RigidBodySpec ws;
    ws.name = "wheelset_" + std::to_string(w + 1);
    ws.kind = BodyKind::wheelset;
    ws.mass = ManchesterMasses::wheelset;
    ws.inertia = {1120.0, 112.0, 1120.0};
    ws.position = {xb + (w % 2 == 0 ? semi_base : -semi_base), 0.0, r0};
    ws.nominal_rolling_radius = r0;
    cfg.bodies.push_back(ws);
  }
  const int car_i = 0;
  // Primary: per axlebox, at axle height, 1.0 m either side.
  const double per_axlebox = (ManchesterMasses::car / 8.0 + ManchesterMasses::bogie / 4.0) * gravity;
  for (int w = 0; w < 4; ++w) {
    const int bogie_i = 1 + w / 2;
    const double dx = w % 2 == 0 ? semi_base : -semi_base;
    for (double side : {1.0, -1.0}) {
      SuspensionElementSpec p;
      p.name = "primary_" + std::to_string(w + 1) + (side > 0 ? "_left" : "_right");
      p.type = ElementType::spring_damper;
      p.body_a = bogie_i;
      p.body_b = 3 + w;
      p.point_a = {dx, side * 1.0, r0 - 0.6};
      p.point_b = {0.0, side * 1.0, 0.0};
      p.stiffness = {31.391e6, 3.884e6, 1.220e6};
      p.damping = {0.0, 0.0, 4.0e3};
      p.preload = {0.0, 0.0, -per_axlebox};
      cfg.elements.push_back(p);
    }
  }
  // Secondary: per bogie side, springs and dampers, bogie yaw stiffness, anti-roll bar, lateral
  // bump stop.
  const double per_side = ManchesterMasses::car / 4.0 * gravity;
  for (int b = 0; b < 2; ++b) {
    const int bogie_i = 1 + b;
    const double xb = b == 0 ? semi_bogie : -semi_bogie;
    for (double side : {1.0, -1.0}) {
      SuspensionElementSpec s;
      s.name = "secondary_" + std::to_string(b + 1) + (side > 0 ? "_left" : "_right");
      s.type = ElementType::spring_damper;
      s.body_a = car_i;
      s.body_b = bogie_i;
      s.point_a = {xb, side * 1.0, h_sec - 1.8};
      s.point_b = {0.0, side * 1.0, h_sec - 0.6};
      s.stiffness = {160e3, 160e3, 430e3};
      s.damping = {0.0, 32e3, 20e3};
      s.preload = {0.0, 0.0, -per_side};
      cfg.elements.push_back(s);
    }
    SuspensionElementSpec yaw;
    yaw.name = "bogie_yaw_" + std::to_string(b + 1);
    yaw.type = ElementType::torsion;
    yaw.axis = Dof::yaw;
    yaw.body_a = car_i;
    yaw.body_b = bogie_i;
    yaw.k = 2.0 * 10.5e3;
    cfg.elements.push_back(yaw);
    SuspensionElementSpec arb = yaw;
    arb.name = "anti_roll_bar_" + std::to_string(b + 1);
    arb.axis = Dof::roll;
    arb.k = 940e3;
    cfg.elements.push_back(arb);
    SuspensionElementSpec stop;
    stop.name = "bump_stop_" + std::to_string(b + 1);
    stop.type = ElementType::bump_stop;
    stop.axis = Dof::y;
    stop.body_a = car_i;
    stop.body_b = bogie_i;
    stop.point_a = {xb, 0.0, 0.65 - 1.8};
    stop.point_b = {0.0, 0.0, 0.65 - 0.6};
    stop.clearance = 0.025;
    stop.table_displacement = {0.025, 0.030, 0.035, 0.040, 0.045, 0.050, 0.055, 0.060, 0.065};
    stop.table_force = {0, 600, 1760, 3730, 6870, 11580, 17170, 29200, 230000};
    cfg.elements.push_back(stop);
  }
  cfg.wheel_rail.friction = 0.32;
  cfg.wheel_rail.track_gauge = 1.435;
  return cfg;
}

}  // namespace ferro::vehicle::testing
