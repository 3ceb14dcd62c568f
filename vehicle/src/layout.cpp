// State layout seen from outside: state and signal names with units, state indices of body DOF,
// the Jacobian's half-bandwidths from the coupling structure.

#include <fmt/format.h>

#include <algorithm>

#include "model_data.hpp"
#include "output_signals.hpp"
#include "workspace.hpp"

namespace ferro::vehicle::detail {
namespace {

const char* kind_name(BodyKind k) {
  switch (k) {
    case BodyKind::car_body:
      return "car_body";
    case BodyKind::bogie_frame:
      return "bogie_frame";
    case BodyKind::wheelset:
      return "wheelset";
  }
  return "?";
}

void name_states(ModelData& m) {
  m.states.resize(m.n_states);
  static const char* kPosUnit[6] = {"m", "m", "m", "rad", "rad", "rad"};
  static const char* kRateUnit[6] = {"m/s", "m/s", "m/s", "rad/s", "rad/s", "rad/s"};
  for (const BodyData& b : m.bodies) {
    for (std::size_t d = 0; d < 6; ++d) {
      if (b.q[d] < 0) continue;
      m.states[static_cast<std::size_t>(b.q[d])] = {
          fmt::format("{}.{}", b.name, kDofNames[d]), kPosUnit[d],
          fmt::format("{} {} ({}), from rest in its track frame", b.name, kDofNames[d],
                      kind_name(b.kind))};
      m.states[static_cast<std::size_t>(b.v[d])] = {
          fmt::format("{}.{}_dot", b.name, kDofNames[d]), kRateUnit[d],
          fmt::format("rate of {}.{}", b.name, kDofNames[d])};
    }
    if (b.spin >= 0) {
      m.states[static_cast<std::size_t>(b.spin)] = {
          fmt::format("{}.spin", b.name), "rad/s",
          "spin speed perturbation beta (spin = V/r0 + beta)"};
    }
  }
  for (const BodyData& b : m.bodies) {
    if (b.track < 0) continue;
    for (int j = 0; j < track::kTrackPositions; ++j) {
      const std::string name = fmt::format("track.{}.{}", b.name, track::kTrackPositionNames[j]);
      const bool angle = name.ends_with("roll");
      m.states[static_cast<std::size_t>(b.track + j)] = {
          name, angle ? "rad" : "m",
          fmt::format("co-running track under {}: {} displacement from the unloaded track",
                      b.name, track::kTrackPositionNames[j])};
      m.states[static_cast<std::size_t>(b.track + track::kTrackPositions + j)] = {
          name + "_dot", angle ? "rad/s" : "m/s", fmt::format("rate of {}", name)};
    }
  }
  for (const ElementData& e : m.elements) {
    if (e.state >= 0) {
      m.states[static_cast<std::size_t>(e.state)] = {
          fmt::format("{}.damper_deflection", e.spec.name), "m",
          "internal deflection of the damper in series with its stiffness"};
    }
  }
}

void name_signals(ModelData& m) {
  for (int bi : m.contact_bodies) {
    const std::string& name = m.bodies[static_cast<std::size_t>(bi)].name;
    for (const char* side : {"left", "right"}) {
      const auto add = [&](const char* what, const char* unit, const char* desc) {
        m.signal_list.push_back({fmt::format("{}.{}.{}", name, side, what), unit, desc});
      };
      add("Y", "N", "lateral rail force on the wheel, + towards the track centre");
      add("Q", "N", "vertical rail force on the wheel, + up");
      add("normal_force", "N", "sum of the normal forces of the wheel's contact points");
      add("creepage_x", "-", "longitudinal creepage of the most loaded point");
      add("creepage_y", "-", "lateral creepage of the most loaded point");
      add("spin", "1/m", "spin creepage of the most loaded point");
      add("contact_y", "m",
          "lateral contact position from the rail reference point, + outwards (0 when lifted)");
      add("contact_angle", "rad", "contact angle of the most loaded point (0 when lifted)");
      add("points", "-", "number of loaded contact points");
      for (int k = 1; k <= WheelResult::kPointSignals; ++k) {
        m.signal_list.push_back(
            {fmt::format("{}.{}.point_{}.normal_force", name, side, k), "N",
             fmt::format("normal force of the wheel's loaded contact point {} in the order the "
                         "geometry source lists them (the multi-point table: increasing "
                         "wheel-profile coordinate), 0 when the wheel has fewer points",
                         k)});
      }
      add("in_contact", "-", "1 when the wheel has a loaded contact point, 0 when lifted");
      add("creep_force_x", "N", "longitudinal creep force on the wheel, sum over its points");
      add("creep_force_y", "N", "lateral creep force (contact frame y = n x x), sum over its points");
      add("spin_moment", "N m", "creep moment about the contact normal, sum over its points");
      add("wear_number", "N",
          "T gamma = Tx creepage_x + Ty creepage_y (force on the rail times creepage: the "
          "frictional energy per metre rolled without the spin term), sum over its points");
      add("rolling_radius", "m", "rolling radius at the most loaded point");
      add("contact_wheel_y", "m", "most loaded point on the wheel profile (profile coordinate)");
      add("contact_rail_y", "m", "most loaded point on the rail profile (profile coordinate)");
      add("semi_axis_a", "m", "longitudinal semi-axis of the most loaded point's patch");
      add("semi_axis_b", "m", "lateral semi-axis of the most loaded point's patch");
      add("peak_pressure", "Pa", "peak contact pressure of the most loaded point");
      for (int k = 1; m.in.outputs.contact_point_details && k <= WheelResult::kPointSignals; ++k) {
        const auto point = [&](const char* what, const char* unit, const char* desc) {
          m.signal_list.push_back({fmt::format("{}.{}.point_{}.{}", name, side, k, what), unit,
                                   fmt::format("{} of loaded point {} (0 without it)", desc, k)});
        };
        point("creep_force_x", "N", "longitudinal creep force");
        point("creep_force_y", "N", "lateral creep force");
        point("spin_moment", "N m", "creep moment about the normal");
        point("wear_number", "N", "T gamma");
        point("contact_angle", "rad", "contact angle");
        point("rolling_radius", "m", "rolling radius");
        point("wheel_y", "m", "wheel-profile coordinate");
        point("rail_y", "m", "rail-profile coordinate");
        point("peak_pressure", "Pa", "peak pressure");
      }
    }
    m.signal_list.push_back({fmt::format("{}.rolling_radius_difference", name), "m",
                             "rolling radius of the left wheel's most loaded point minus the "
                             "right's (0 when a wheel is lifted)"});
    m.signal_list.push_back({fmt::format("{}.angle_of_attack", name), "rad",
                             "yaw of the wheelset relative to its rails' actual direction "
                             "(irregularities and rail deflection included; the mean over the "
                             "two rails), + nose left"});
  }
  for (int bi : m.contact_bodies) {
    const BodyData& b = m.bodies[static_cast<std::size_t>(bi)];
    m.signal_list.push_back(
        {fmt::format("{}.y_rel_rails", b.name), "m",
         "lateral displacement of the axle centre from the mid-point of its two rails' heads "
         "(irregularities and rail deflection included), + left"});
    if (b.track < 0) continue;
    for (const char* side : {"left", "right"}) {
      const auto add = [&](const char* what, const char* unit, const char* desc) {
        m.signal_list.push_back({fmt::format("track.{}.{}_rail.{}", b.name, side, what), unit, desc});
      };
      add("head_lateral", "m", "elastic lateral displacement of the rail head under the wheel, + left");
      add("head_vertical", "m", "elastic vertical displacement of the rail under the wheel, + up");
      add("seat_force_lateral", "N",
          "lateral force of the rail on its rail seats (pads), + towards the field side");
      add("seat_force_vertical", "N", "vertical force of the rail on its rail seats (pads), + down");
    }
  }
  if (m.car_body >= 0) {
    m.signal_list.push_back(
        {"car_body.ay", "m/s^2", "lateral acceleration read at the car body's centre of mass"});
  }
  m.signal_list.push_back({"position", "m", "arc length of the vehicle reference point"});
  m.signal_list.push_back({"speed", "m/s", "vehicle speed"});
}

}  // namespace

void name_states_and_signals(ModelData& m) {
  name_states(m);
  name_output_states(m);
  name_signals(m);
  name_output_signals(m);
}

std::pair<int, int> jacobian_bandwidth(const ModelData& m) {
  int band = 0;
  const auto couple = [&](int lo_a, int hi_a, int lo_b, int hi_b) {
    if (hi_a <= lo_a || hi_b <= lo_b) return;
    band = std::max({band, hi_a - 1 - lo_b, hi_b - 1 - lo_a});
  };
  for (const BodyData& b : m.bodies) couple(b.block_begin, b.block_end, b.block_begin, b.block_end);
  for (const ElementData& e : m.elements) {
    const BodyData& bb = m.bodies[static_cast<std::size_t>(e.b)];
    if (e.a >= 0) {
      const BodyData& ba = m.bodies[static_cast<std::size_t>(e.a)];
      couple(ba.block_begin, ba.block_end, bb.block_begin, bb.block_end);
    }
    if (e.state >= 0) {
      couple(e.state, e.state + 1, bb.block_begin, bb.block_end);
      if (e.a >= 0) {
        const BodyData& ba = m.bodies[static_cast<std::size_t>(e.a)];
        couple(e.state, e.state + 1, ba.block_begin, ba.block_end);
      }
    }
  }
  return {band, band};
}

std::vector<std::vector<int>> jacobian_pattern(const ModelData& m) {
  const std::size_t nb = m.bodies.size();
  // Bodies joined by an element (each with itself).
  std::vector<std::vector<bool>> joined(nb, std::vector<bool>(nb, false));
  for (std::size_t i = 0; i < nb; ++i) joined[i][i] = true;
  for (const ElementData& e : m.elements) {
    if (e.a < 0) continue;
    joined[static_cast<std::size_t>(e.a)][static_cast<std::size_t>(e.b)] = true;
    joined[static_cast<std::size_t>(e.b)][static_cast<std::size_t>(e.a)] = true;
  }
  std::vector<std::vector<int>> pattern(m.n_states);
  const auto rows_of = [&](const BodyData& b, std::vector<int>& rows) {
    for (int i = b.block_begin; i < b.block_end; ++i) rows.push_back(i);
  };
  for (std::size_t i = 0; i < nb; ++i) {
    const BodyData& b = m.bodies[i];
    std::vector<int> body_rows, own_rows;
    for (std::size_t k = 0; k < nb; ++k) {
      if (joined[i][k]) rows_of(m.bodies[k], body_rows);
    }
    rows_of(b, own_rows);
    const int track_end = b.track < 0 ? b.track : b.track + 2 * track::kTrackPositions;
    for (int j = b.block_begin; j < b.block_end; ++j) {
      const bool track_state = b.track >= 0 && j >= b.track && j < track_end;
      pattern[static_cast<std::size_t>(j)] = track_state ? own_rows : body_rows;
    }
  }
  // An output filter's state acts on its own channel's states alone (a cascade of sections).
  const int per = m.output_filter.states_per_channel();
  const auto channel = [&](int first) {
    std::vector<int> rows;
    for (int i = first; i < first + per; ++i) rows.push_back(i);
    for (int i = first; i < first + per; ++i) pattern[static_cast<std::size_t>(i)] = rows;
  };
  if (per > 0) {
    for (const BodyData& b : m.bodies)
      if (b.has_contact && b.output_filters >= 0)
        for (int c = 0; c < 4; ++c) channel(b.output_filters + c * per);
    for (const SensorData& s : m.sensors)
      for (const int first : s.filter)
        if (first >= 0) channel(first);
  }
  return pattern;
}

}  // namespace ferro::vehicle::detail
