// The model's output signals at (t, x): per-wheel forces, creepages and contact place, the car
// body's lateral acceleration, position and speed (names and units: layout.cpp).

#include "dynamics.hpp"
#include "output_signals.hpp"

namespace ferro::vehicle::detail {

void signals(const ModelData& m, Workspace& ws, double t, std::span<const double> x,
             std::span<double> out) {
  ws.wheels.assign(2 * m.contact_bodies.size(), WheelResult{});
  double ay = std::numeric_limits<double>::quiet_NaN();
  evaluate(m, ws, t, x, {}, EvaluationOutputs{ws.wheels.data(), &ay, true});
  std::size_t o = 0;
  for (std::size_t body = 0; body < m.contact_bodies.size(); ++body) {
    for (std::size_t side = 0; side < 2; ++side) {
      const WheelResult& w = ws.wheels[2 * body + side];
      out[o++] = w.lateral_towards_centre;
      out[o++] = w.vertical;
      out[o++] = w.normal_force;
      out[o++] = w.creepage_x;
      out[o++] = w.creepage_y;
      out[o++] = w.spin;
      out[o++] = w.contact_y;  // 0 when lifted, like every place and angle below
      out[o++] = w.contact_angle;
      out[o++] = w.points;
      for (double f : w.point_normal_force) out[o++] = f;
      out[o++] = w.points > 0 ? 1.0 : 0.0;
      out[o++] = w.creep_force_x;
      out[o++] = w.creep_force_y;
      out[o++] = w.spin_moment;
      out[o++] = w.wear_number;
      out[o++] = w.largest.rolling_radius;
      out[o++] = w.largest.wheel_y;
      out[o++] = w.largest.rail_y;
      out[o++] = w.largest.semi_axis_a;
      out[o++] = w.largest.semi_axis_b;
      out[o++] = w.largest.peak_pressure;
      for (const PointResult& p : w.point) {
        if (!m.in.outputs.contact_point_details) break;
        out[o++] = p.creep_force_x;
        out[o++] = p.creep_force_y;
        out[o++] = p.spin_moment;
        out[o++] = p.wear_number;
        out[o++] = p.contact_angle;
        out[o++] = p.rolling_radius;
        out[o++] = p.wheel_y;
        out[o++] = p.rail_y;
        out[o++] = p.peak_pressure;
      }
    }
    const WheelResult& l = ws.wheels[2 * body];
    const WheelResult& r = ws.wheels[2 * body + 1];
    out[o++] = l.points > 0 && r.points > 0 ? l.largest.rolling_radius - r.largest.rolling_radius : 0.0;
    // Relative to the pair of rails: the mean of the two rails' directions.
    out[o++] = 0.5 * (l.angle_of_attack + r.angle_of_attack);
  }
  for (std::size_t w = 0; w < m.contact_bodies.size(); ++w) {
    const auto i = static_cast<std::size_t>(m.contact_bodies[w]);
    const BodyData& b = m.bodies[i];
    const BodyKinematics& k = ws.kin[i];
    // Elastic lateral displacement of each rail head (zero on a rigid track).
    std::array<double, 2> head_y{0.0, 0.0};
    if (b.track >= 0) {
      for (std::size_t s = 0; s < 2; ++s) {
        const std::size_t q = static_cast<std::size_t>(b.track) + 3 * s;
        head_y[s] = x[q] - m.track->rail_head_height * x[q + 2];
      }
    }
    out[o++] = b.rest.y() + k.u.y() - (k.irregularity.lateral + 0.5 * (head_y[0] + head_y[1]));
    if (b.track < 0) continue;
    for (std::size_t s = 0; s < 2; ++s) {
      const std::size_t q = static_cast<std::size_t>(b.track) + 3 * s;
      const track::PadForce& pad = ws.pad_forces[w][s];
      const double outwards = s == 0 ? 1.0 : -1.0;  // the left rail's field side is +y
      out[o++] = head_y[s];
      out[o++] = x[q + 1];
      out[o++] = -outwards * pad.force_y;  // the pad pushes the rail back: the rail pushes out
      out[o++] = pad.force_z;  // the pad holds the rail up (force_z > 0): compression
    }
  }
  if (m.car_body >= 0) out[o++] = ay;
  out[o++] = m.in.start_position + m.in.speed.distance(t);
  out[o++] = m.in.speed.speed(t);
  o += output_signal_values(m, ws, x, out.subspan(o));
}

}  // namespace ferro::vehicle::detail
