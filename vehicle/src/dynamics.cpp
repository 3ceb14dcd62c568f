// One evaluation of the vehicle model: body kinematics in the moving track frames, suspension
// elements, wheel-rail forces, equations of motion (vehicle_model.hpp gives the equations).
//
// References: see vehicle_model.hpp.
// Known deviations: see vehicle_model.hpp.

#include "dynamics.hpp"

#include "output_signals.hpp"

#include <cmath>

namespace ferro::vehicle::detail {
namespace {

/// Positions, rates, attitude and spin of every body from the state; accumulators cleared.
void body_kinematics(const ModelData& m, Workspace& ws, double s_ref, double speed, double rate,
                     std::span<const double> x) {
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const BodyData& b = m.bodies[i];
    BodyKinematics& k = ws.kin[i];
    frame_at(m, s_ref + b.rest.x(), speed, rate, k, b.has_contact);
    for (std::size_t d = 0; d < 3; ++d) {
      const auto e = static_cast<Eigen::Index>(d);
      k.u[e] = b.q[d] >= 0 ? x[static_cast<std::size_t>(b.q[d])] : 0.0;
      k.u_dot[e] = b.v[d] >= 0 ? x[static_cast<std::size_t>(b.v[d])] : 0.0;
      k.angles[e] = b.q[d + 3] >= 0 ? x[static_cast<std::size_t>(b.q[d + 3])] : 0.0;
      k.rates[e] = b.v[d + 3] >= 0 ? x[static_cast<std::size_t>(b.v[d + 3])] : 0.0;
    }
    k.attitude = attitude_matrix(k.angles);
    k.spin = b.kind == BodyKind::wheelset
                 ? speed / b.r0 + (b.spin >= 0 ? x[static_cast<std::size_t>(b.spin)] : 0.0)
                 : 0.0;
    k.force.setZero();
    k.moment.setZero();
  }
}

/// Accelerations of every dynamic body in its track frame into xdot.
void equations_of_motion(const ModelData& m, const Workspace& ws, double rate,
                         std::span<double> xdot) {
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const BodyData& b = m.bodies[i];
    if (!b.dynamic) continue;
    const BodyKinematics& k = ws.kin[i];
    const Eigen::Vector3d& w = k.motion.angular_velocity;
    const Eigen::Vector3d& alpha = k.motion.angular_acceleration;
    const Eigen::Vector3d r = Eigen::Vector3d(0.0, b.rest.y(), b.rest.z()) + k.u;
    const Eigen::Vector3d acc = k.force / b.mass - k.motion.specific_force - alpha.cross(r) -
                                w.cross(w.cross(r)) - 2.0 * w.cross(k.u_dot);
    const Eigen::Vector3d w_h = w + k.rates;
    Eigen::Vector3d h = b.inertia.cwiseProduct(w_h);
    const Eigen::Vector3d axle = k.attitude.col(1);
    if (b.kind == BodyKind::wheelset) h += b.inertia.y() * k.spin * axle;
    const Eigen::Vector3d ang_acc =
        (k.moment - w_h.cross(h)).cwiseQuotient(b.inertia) - alpha - w.cross(k.rates);
    for (std::size_t d = 0; d < 3; ++d) {
      const auto e = static_cast<Eigen::Index>(d);
      if (b.q[d] >= 0) {
        xdot[static_cast<std::size_t>(b.q[d])] = k.u_dot[e];
        xdot[static_cast<std::size_t>(b.v[d])] = acc[e];
      }
      if (b.q[d + 3] >= 0) {
        xdot[static_cast<std::size_t>(b.q[d + 3])] = k.rates[e];
        xdot[static_cast<std::size_t>(b.v[d + 3])] = ang_acc[e];
      }
    }
    if (b.spin >= 0) {
      // I_y (d spin / dt) = M_y - (w_h x H)_y - I_y (alpha + w x theta')_y, spin = V/r0 + beta.
      xdot[static_cast<std::size_t>(b.spin)] = ang_acc.y() - rate / b.r0;
    }
  }
}

/// The co-running track under every contact wheelset: rates of its positions and the
/// accelerations its pads, ballast and the wheels' loads give (into xdot when not empty); the
/// pad forces into the workspace.
void track_motion(const ModelData& m, Workspace& ws, std::span<const double> x,
                  std::span<double> xdot) {
  ws.pad_forces.resize(m.contact_bodies.size());
  constexpr auto n = static_cast<std::size_t>(track::kTrackPositions);
  std::array<double, n> acc{};
  for (std::size_t w = 0; w < m.contact_bodies.size(); ++w) {
    const auto q = static_cast<std::size_t>(m.bodies[static_cast<std::size_t>(m.contact_bodies[w])].track);
    track::co_running_track_accelerations(*m.track, &x[q], &x[q + n], ws.rail_loads[w].data(),
                                          acc.data(), ws.pad_forces[w].data());
    if (xdot.empty()) continue;
    for (std::size_t j = 0; j < n; ++j) {
      xdot[q + j] = x[q + n + j];
      xdot[q + n + j] = acc[j];
    }
  }
}

}  // namespace

void frame_at(const ModelData& m, double s, double speed, double rate, BodyKinematics& k,
              bool irregular) {
  if (m.in.track) {
    if (irregular) {
      const track::TrackPoint p = m.in.track->at(s);
      k.frame = p.frame;
      k.irregularity = p.irregularity;
    } else {
      k.frame = m.in.track->alignment().frame(s);
      k.irregularity = track::IrregularitySample{};
    }
  } else {
    k.frame = track::TrackFrame{};
    k.frame.s = s;
    k.frame.position = Eigen::Vector3d(s, 0.0, 0.0);
    k.frame.gauge = m.in.config.wheel_rail.track_gauge;
    k.frame.rail_spacing = m.nominal_rail_spacing;
    k.irregularity = track::IrregularitySample{};
  }
  k.motion = track::frame_kinematics(k.frame, speed, rate, m.in.config.gravity);
}

void evaluate(const ModelData& m, Workspace& ws, double t, std::span<const double> x,
              std::span<double> xdot, const EvaluationOutputs& outputs, double speed_override) {
  if (ws.kin.size() < m.bodies.size()) ws.kin.resize(m.bodies.size());
  const double speed = std::isfinite(speed_override) ? speed_override : m.in.speed.speed(t);
  const double rate = m.in.speed.rate(t);
  const double s_ref = m.in.start_position + m.in.speed.distance(t);

  body_kinematics(m, ws, s_ref, speed, rate, x);
  // The output filters read the wheel forces of every right-hand side.
  WheelResult* wheels = outputs.wheels;
  if (wheels == nullptr && m.output_filter.order > 0 && !xdot.empty()) {
    ws.wheels.assign(2 * m.contact_bodies.size(), WheelResult{});
    wheels = ws.wheels.data();
  }
  for (const ElementData& e : m.elements) {
    if (e.a < 0) frame_at(m, s_ref + e.spec.point_a.x(), speed, rate, ws.track_frame, false);
    apply_element(m, e, ws.kin, ws.track_frame, x, xdot);
  }
  if (m.track) ws.rail_loads.assign(m.contact_bodies.size(), {});
  for (std::size_t w = 0; w < m.contact_bodies.size(); ++w) {
    const auto i = static_cast<std::size_t>(m.contact_bodies[w]);
    apply_wheel_rail(m, m.bodies[i], ws.kin[i], x, ws.wheel_rail,
                     m.track ? ws.rail_loads[w].data() : nullptr,
                     wheels != nullptr ? wheels + 2 * w : nullptr);
  }
  if (outputs.car_body_ay != nullptr && m.car_body >= 0) {
    const BodyData& b = m.bodies[static_cast<std::size_t>(m.car_body)];
    const BodyKinematics& k = ws.kin[static_cast<std::size_t>(m.car_body)];
    *outputs.car_body_ay = b.dynamic ? (k.attitude.transpose() * k.force).y() / b.mass
                                     : std::numeric_limits<double>::quiet_NaN();
  }
  if (!xdot.empty()) equations_of_motion(m, ws, rate, xdot);
  if (m.track && (!xdot.empty() || outputs.pad_forces)) track_motion(m, ws, x, xdot);
  if (!xdot.empty()) output_filter_rates(m, ws, wheels, x, xdot);
}

}  // namespace ferro::vehicle::detail
