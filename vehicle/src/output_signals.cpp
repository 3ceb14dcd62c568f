// Sensors and in-run anti-alias filters (see output_signals.hpp and vehicle_model.hpp).
//
// References: Wickens (2003) ch. 2 and Shabana et al. (2008) ch. 6 for the rigid-body point
// acceleration a_p = a_G + alpha x r + w x (w x r); Oppenheim & Schafer (2010) §4.8 (sampling a
// signal band-limited below the Nyquist frequency loses nothing; a low-pass before decimation);
// Butterworth sections 1/Q_k = 2 sin((2k - 1) pi / (2 n)).
// Known deviations: the sensor reading uses the model's small-angle body rates (the absolute
// angular velocity is the frame's plus the angle rates, vehicle_model.hpp) and its diagonal
// inertia in track axes, as the equations of motion do.

#include "output_signals.hpp"

#include "dynamics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ferro::vehicle::detail {

namespace {

constexpr const char* kAxes[3] = {"x", "y", "z"};

// Accelerometer reading at `point` (body axes) of a body: specific force (acceleration minus
// gravity) in body axes. Along a degree of freedom with a state, the equations of motion give
// the centre's specific force F/m (the body's forces exclude gravity) and the absolute angular
// acceleration (M - w_h x h) / I; along a frozen one the body moves with its track frame, whose
// terms (vehicle_model.hpp) are then the whole acceleration: the frame's specific force and
// alpha x r + w x (w x r) + 2 w x u' for a translation, alpha + w x theta' for a rotation.
Eigen::Vector3d specific_force(const BodyData& b, const BodyKinematics& k,
                               const Eigen::Vector3d& point) {
  const Eigen::Vector3d& w = k.motion.angular_velocity;
  const Eigen::Vector3d w_h = w + k.rates;
  Eigen::Vector3d h = b.inertia.cwiseProduct(w_h);
  if (b.kind == BodyKind::wheelset) h += b.inertia.y() * k.spin * k.attitude.col(1);
  Eigen::Vector3d alpha = (k.moment - w_h.cross(h)).cwiseQuotient(b.inertia);
  Eigen::Vector3d f_centre = k.force / b.mass;
  const Eigen::Vector3d r_centre = Eigen::Vector3d(0.0, b.rest.y(), b.rest.z()) + k.u;
  const Eigen::Vector3d held = k.motion.specific_force + k.motion.angular_acceleration.cross(r_centre) +
                               w.cross(w.cross(r_centre)) + 2.0 * w.cross(k.u_dot);
  const Eigen::Vector3d held_alpha = k.motion.angular_acceleration + w.cross(k.rates);
  for (std::size_t d = 0; d < 3; ++d) {
    const auto e = static_cast<Eigen::Index>(d);
    if (b.q[d] < 0) f_centre[e] = held[e];
    if (b.q[d + 3] < 0) alpha[e] = held_alpha[e];
  }
  const Eigen::Vector3d r = k.attitude * point;
  const Eigen::Vector3d f = f_centre + alpha.cross(r) + w_h.cross(w_h.cross(r));
  return k.attitude.transpose() * f;
}

// Wheel channels of a contact body: [Y left, Q left, Y right, Q right].
double wheel_channel(const WheelResult* wheels, std::size_t w, int channel) {
  const WheelResult& r = wheels[2 * w + static_cast<std::size_t>(channel / 2)];
  return channel % 2 == 0 ? r.lateral_towards_centre : r.vertical;
}

// Rates of one channel's cascade whose states start at `first`.
void channel_rates(const OutputFilterData& f, double input, int first, std::span<const double> x,
                   std::span<double> xdot) {
  const double w2 = f.omega * f.omega;
  double in = input;
  for (std::size_t k = 0; k < f.inv_q.size(); ++k) {
    const auto y = static_cast<std::size_t>(first) + 2 * k;
    xdot[y] = x[y + 1];
    xdot[y + 1] = w2 * (in - x[y]) - f.omega * f.inv_q[k] * x[y + 1];
    in = x[y];
  }
}

double channel_output(const OutputFilterData& f, int first, std::span<const double> x) {
  return x[static_cast<std::size_t>(first) + 2 * (f.inv_q.size() - 1)];
}

}  // namespace

void add_patch(PointTotals& totals, const contact::ContactPatch& patch,
               const contact::TangentialProblem& problem, const contact::TangentialSolution& tang) {
  PointResult& r = totals.result;
  r.creep_force_x += tang.force_x;
  r.creep_force_y += tang.force_y;
  r.spin_moment += tang.moment_z;
  // The creep force on the wheel opposes its slip: -(F . creepage) is the energy dissipated
  // per metre rolled by the translational creepages (the spin term -Mz phi, left out of
  // T gamma as wear models define it, makes the total >= 0).
  r.wear_number -= tang.force_x * problem.creepage.longitudinal +
                   tang.force_y * problem.creepage.lateral;
  if (patch.normal_force > totals.largest_patch_force) {
    totals.largest_patch_force = patch.normal_force;
    r.semi_axis_a = patch.semi_axis_x;
    r.semi_axis_b = patch.semi_axis_y;
  }
  r.peak_pressure = std::max(r.peak_pressure, patch.peak_pressure);
}

void record_point(WheelResult& w, const contact::WheelRailContact& c, const PointTotals& totals,
                  double normal_force) {
  PointResult r = totals.result;
  r.contact_angle = c.contact_angle;
  r.rolling_radius = c.rolling_radius;
  // Sources without profiles (conical, imported tables) have no profile coordinates: 0.
  r.wheel_y = std::isnan(c.wheel_y) ? 0.0 : c.wheel_y;
  r.rail_y = std::isnan(c.rail_y) ? 0.0 : c.rail_y;
  if (w.points < WheelResult::kPointSignals) w.point[static_cast<std::size_t>(w.points)] = r;
  w.creep_force_x += r.creep_force_x;
  w.creep_force_y += r.creep_force_y;
  w.spin_moment += r.spin_moment;
  w.wear_number += r.wear_number;
  if (normal_force > w.largest_normal_force) w.largest = r;
}

void record_pose(WheelResult* left_right, const RailRelativePose& rel, int side) {
  for (int s = 0; s < 2; ++s) {
    if (side >= 0 && s != side) continue;
    left_right[s].angle_of_attack = rel.yaw;
  }
}

void resolve_output_signals(ModelData& m) {
  const OutputSignalsSpec& o = m.in.outputs;
  if (!(o.anti_alias_frequency >= 0.0) || !std::isfinite(o.anti_alias_frequency))
    throw std::invalid_argument(fmt::format(
        "outputs.anti_alias_frequency: must be >= 0 Hz (0: no filters), got {}",
        o.anti_alias_frequency));
  if (o.anti_alias_frequency > 0.0) {
    if (o.anti_alias_order < 2 || o.anti_alias_order > 8 || o.anti_alias_order % 2 != 0)
      throw std::invalid_argument(fmt::format(
          "outputs.anti_alias_order: allowed 2, 4, 6, 8, got {}", o.anti_alias_order));
    m.output_filter.order = o.anti_alias_order;
    m.output_filter.omega = 2.0 * M_PI * o.anti_alias_frequency;
    for (int k = 1; k <= o.anti_alias_order / 2; ++k)
      m.output_filter.inv_q.push_back(2.0 * std::sin((2.0 * k - 1.0) * M_PI / (2.0 * o.anti_alias_order)));
  }
  for (std::size_t s = 0; s < o.sensors.size(); ++s) {
    const SensorSpec& spec = o.sensors[s];
    const std::string where = fmt::format("outputs.sensors[{}]", s);
    if (spec.name.empty())
      throw std::invalid_argument(fmt::format("{}.name: must not be empty", where));
    for (std::size_t t = 0; t < s; ++t)
      if (o.sensors[t].name == spec.name)
        throw std::invalid_argument(fmt::format("{}.name: '{}' is used twice", where, spec.name));
    if (!spec.point.allFinite())
      throw std::invalid_argument(fmt::format("{}.point: must be finite", where));
    for (char a : spec.filtered_axes)
      if (a != 'x' && a != 'y' && a != 'z')
        throw std::invalid_argument(fmt::format(
            "{}.filtered_axes: '{}': allowed any of x, y, z", where, spec.filtered_axes));
    SensorData d;
    d.spec = spec;
    std::string names;
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      names += (names.empty() ? "" : ", ") + m.bodies[i].name;
      if (m.bodies[i].name == spec.body) d.body = static_cast<int>(i);
    }
    if (d.body < 0)
      throw std::invalid_argument(
          fmt::format("{}.body: no body '{}'; bodies: {}", where, spec.body, names));
    m.sensors.push_back(std::move(d));
  }
}

int lay_out_output_filters(ModelData& m, std::size_t i, int next) {
  BodyData& b = m.bodies[i];
  for (const SensorData& s : m.sensors)
    if (s.body == static_cast<int>(i) && !b.dynamic)
      throw std::invalid_argument(fmt::format(
          "outputs.sensors: '{}' is on body '{}', which has no states in this model (scope or "
          "frozen degrees of freedom)",
          s.spec.name, b.name));
  const int per = m.output_filter.states_per_channel();
  if (per == 0) return next;
  b.output_filters = next;
  if (b.has_contact) next += 4 * per;  // Y and Q of both wheels
  for (SensorData& s : m.sensors) {
    if (s.body != static_cast<int>(i)) continue;
    for (int a = 0; a < 3; ++a) {
      if (s.spec.filtered_axes.find(kAxes[a][0]) == std::string::npos) continue;
      s.filter[static_cast<std::size_t>(a)] = next;
      next += per;
    }
  }
  if (next == b.output_filters) b.output_filters = -1;
  return next;
}

void name_output_states(ModelData& m) {
  const OutputFilterData& f = m.output_filter;
  if (f.order == 0) return;
  const auto name_channel = [&](int first, const std::string& signal, const std::string& unit) {
    for (std::size_t k = 0; k < f.inv_q.size(); ++k) {
      const auto y = static_cast<std::size_t>(first) + 2 * k;
      m.states[y] = {fmt::format("{}.filter_{}", signal, k + 1), unit,
                     fmt::format("anti-alias low-pass of {}: output of section {}", signal, k + 1)};
      m.states[y + 1] = {fmt::format("{}.filter_{}_rate", signal, k + 1), unit + "/s",
                         fmt::format("rate of {}.filter_{}", signal, k + 1)};
    }
  };
  for (const BodyData& b : m.bodies) {
    if (!b.has_contact || b.output_filters < 0) continue;
    int c = 0;
    for (const char* side : {"left", "right"})
      for (const char* what : {"Y", "Q"})
        name_channel(b.output_filters + (c++) * f.order, fmt::format("{}.{}.{}", b.name, side, what),
                     "N");
  }
  for (const SensorData& s : m.sensors)
    for (int a = 0; a < 3; ++a)
      if (s.filter[static_cast<std::size_t>(a)] >= 0)
        name_channel(s.filter[static_cast<std::size_t>(a)],
                     fmt::format("{}.a{}", s.spec.name, kAxes[a]), "m/s^2");
}

void name_output_signals(ModelData& m) {
  const OutputFilterData& f = m.output_filter;
  const std::string filter_text =
      f.order > 0 ? fmt::format("through the run's anti-alias low-pass (Butterworth, order {}, "
                                "{:g} Hz)",
                                f.order, f.omega / (2.0 * M_PI))
                  : "";
  for (const SensorData& s : m.sensors) {
    const std::string at = fmt::format("at ({:g}, {:g}, {:g}) m of {}", s.spec.point.x(),
                                       s.spec.point.y(), s.spec.point.z(), s.spec.body);
    for (int a = 0; a < 3; ++a)
      m.signal_list.push_back(
          {fmt::format("{}.a{}", s.spec.name, kAxes[a]), "m/s^2",
           fmt::format("accelerometer reading (specific force) along body {} {}{}", kAxes[a], at,
                       a == 2 ? ", +g at rest" : "")});
    for (int a = 0; a < 3; ++a)
      m.signal_list.push_back({fmt::format("{}.d{}", s.spec.name, kAxes[a]), "m",
                               fmt::format("displacement along {} from rest {}, track-frame axes",
                                           kAxes[a], at)});
  }
  if (f.order == 0) return;
  for (int bi : m.contact_bodies) {
    const std::string& name = m.bodies[static_cast<std::size_t>(bi)].name;
    for (const char* side : {"left", "right"})
      for (const char* what : {"Y", "Q"})
        m.signal_list.push_back({fmt::format("{}.{}.{}_filtered", name, side, what), "N",
                                 fmt::format("{}.{}.{} {}", name, side, what, filter_text)});
  }
  for (const SensorData& s : m.sensors)
    for (int a = 0; a < 3; ++a)
      if (s.filter[static_cast<std::size_t>(a)] >= 0)
        m.signal_list.push_back({fmt::format("{}.a{}_filtered", s.spec.name, kAxes[a]), "m/s^2",
                                 fmt::format("{}.a{} {}", s.spec.name, kAxes[a], filter_text)});
}

void output_filter_rates(const ModelData& m, const Workspace& ws, const WheelResult* wheels,
                         std::span<const double> x, std::span<double> xdot) {
  const OutputFilterData& f = m.output_filter;
  if (f.order == 0) return;
  for (std::size_t w = 0; w < m.contact_bodies.size(); ++w) {
    const BodyData& b = m.bodies[static_cast<std::size_t>(m.contact_bodies[w])];
    for (int c = 0; c < 4; ++c)
      channel_rates(f, wheel_channel(wheels, w, c), b.output_filters + c * f.order, x, xdot);
  }
  for (const SensorData& s : m.sensors) {
    const auto bi = static_cast<std::size_t>(s.body);
    const Eigen::Vector3d a = specific_force(m.bodies[bi], ws.kin[bi], s.spec.point);
    for (int c = 0; c < 3; ++c)
      if (s.filter[static_cast<std::size_t>(c)] >= 0)
        channel_rates(f, a[c], s.filter[static_cast<std::size_t>(c)], x, xdot);
  }
}

std::size_t output_signal_values(const ModelData& m, const Workspace& ws,
                                 std::span<const double> x, std::span<double> out) {
  std::size_t o = 0;
  for (const SensorData& s : m.sensors) {
    const auto bi = static_cast<std::size_t>(s.body);
    const BodyKinematics& k = ws.kin[bi];
    const Eigen::Vector3d a = specific_force(m.bodies[bi], k, s.spec.point);
    for (int c = 0; c < 3; ++c) out[o++] = a[c];
    const Eigen::Vector3d d = k.u + (k.attitude - Eigen::Matrix3d::Identity()) * s.spec.point;
    for (int c = 0; c < 3; ++c) out[o++] = d[c];
  }
  const OutputFilterData& f = m.output_filter;
  if (f.order == 0) return o;
  for (int bi : m.contact_bodies) {
    const BodyData& b = m.bodies[static_cast<std::size_t>(bi)];
    for (int c = 0; c < 4; ++c) out[o++] = channel_output(f, b.output_filters + c * f.order, x);
  }
  for (const SensorData& s : m.sensors)
    for (int c = 0; c < 3; ++c)
      if (s.filter[static_cast<std::size_t>(c)] >= 0)
        out[o++] = channel_output(f, s.filter[static_cast<std::size_t>(c)], x);
  return o;
}

std::vector<std::size_t> output_state_indices(const ModelData& m) {
  std::vector<std::size_t> out;
  const int per = m.output_filter.order;
  if (per == 0) return out;
  const auto add = [&](int first, int channels) {
    for (int i = 0; i < channels * per; ++i) out.push_back(static_cast<std::size_t>(first + i));
  };
  for (const BodyData& b : m.bodies) {
    if (b.output_filters < 0) continue;
    if (b.has_contact) add(b.output_filters, 4);
  }
  for (const SensorData& s : m.sensors)
    for (int first : s.filter)
      if (first >= 0) add(first, 1);
  std::sort(out.begin(), out.end());
  return out;
}

void set_output_filters_steady(const ModelData& m, Workspace& ws, double t, std::span<double> x) {
  const OutputFilterData& f = m.output_filter;
  if (f.order == 0) return;
  ws.wheels.assign(2 * m.contact_bodies.size(), WheelResult{});
  evaluate(m, ws, t, x, {}, EvaluationOutputs{ws.wheels.data(), nullptr});
  const auto steady = [&](int first, double input) {
    for (std::size_t k = 0; k < f.inv_q.size(); ++k) {
      x[static_cast<std::size_t>(first) + 2 * k] = input;
      x[static_cast<std::size_t>(first) + 2 * k + 1] = 0.0;
    }
  };
  for (std::size_t w = 0; w < m.contact_bodies.size(); ++w) {
    const BodyData& b = m.bodies[static_cast<std::size_t>(m.contact_bodies[w])];
    for (int c = 0; c < 4; ++c)
      steady(b.output_filters + c * f.order, wheel_channel(ws.wheels.data(), w, c));
  }
  for (const SensorData& s : m.sensors) {
    const auto bi = static_cast<std::size_t>(s.body);
    const Eigen::Vector3d a = specific_force(m.bodies[bi], ws.kin[bi], s.spec.point);
    for (int c = 0; c < 3; ++c)
      if (s.filter[static_cast<std::size_t>(c)] >= 0) steady(s.filter[static_cast<std::size_t>(c)], a[c]);
  }
}

}  // namespace ferro::vehicle::detail
