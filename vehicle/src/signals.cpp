// The model's output signals at (t, x): per-wheel forces, creepages and contact place, the car
// body's lateral acceleration, position and speed (names and units: layout.cpp).

#include "dynamics.hpp"

namespace ferro::vehicle::detail {

void signals(const ModelData& m, Workspace& ws, double t, std::span<const double> x,
             std::span<double> out) {
  ws.wheels.assign(2 * m.contact_bodies.size(), WheelResult{});
  double ay = std::numeric_limits<double>::quiet_NaN();
  evaluate(m, ws, t, x, {}, EvaluationOutputs{ws.wheels.data(), &ay});
  std::size_t o = 0;
  for (const WheelResult& w : ws.wheels) {
    out[o++] = w.lateral_towards_centre;
    out[o++] = w.vertical;
    out[o++] = w.normal_force;
    out[o++] = w.creepage_x;
    out[o++] = w.creepage_y;
    out[o++] = w.spin;
    out[o++] = w.points > 0 ? w.contact_y : std::numeric_limits<double>::quiet_NaN();
    out[o++] = w.points > 0 ? w.contact_angle : std::numeric_limits<double>::quiet_NaN();
    out[o++] = w.points;
    for (double f : w.point_normal_force) out[o++] = f;
  }
  if (m.car_body >= 0) out[o++] = ay;
  out[o++] = m.in.start_position + m.in.speed.distance(t);
  out[o++] = m.in.speed.speed(t);
}

}  // namespace ferro::vehicle::detail
