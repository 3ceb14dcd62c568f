// Building the model data from its inputs: validation (the specs' own validate()), body order,
// elements, the selection (scope, frozen DOF), the state layout and the contact mechanics.
// State and signal names: layout.cpp.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/contact/kij/kij_table.hpp"
#include "model_data.hpp"
#include "output_signals.hpp"

namespace ferro::vehicle::detail {

void name_states_and_signals(ModelData& m);  // layout.cpp

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

void validate_inputs(const VehicleModelInputs& in) {
  require(in.geometry != nullptr, "geometry: a contact geometry source is required");
  in.config.validate();
  require(std::isfinite(in.speed.initial) && in.speed.initial >= 0.0,
          "speed.initial: must be finite and >= 0 m/s");
  require(std::isfinite(in.speed.acceleration), "speed.acceleration: must be finite m/s^2");
  require(std::isfinite(in.start_position), "start_position: must be finite m");
}

/// Bodies in state order (decreasing rest x); returns the model index of each config body.
std::vector<int> order_bodies(ModelData& m) {
  const auto& bodies = m.in.config.bodies;
  const int n = static_cast<int>(bodies.size());
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return bodies[static_cast<std::size_t>(a)].position.x() >
           bodies[static_cast<std::size_t>(b)].position.x();
  });
  std::vector<int> position_of(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const int config_index = order[static_cast<std::size_t>(i)];
    position_of[static_cast<std::size_t>(config_index)] = i;
    const RigidBodySpec& s = bodies[static_cast<std::size_t>(config_index)];
    BodyData b;
    b.name = s.name;
    b.kind = s.kind;
    b.mass = s.mass;
    b.inertia = s.inertia;
    b.rest = s.position;
    b.r0 = s.kind == BodyKind::wheelset ? s.nominal_rolling_radius : 0.0;
    m.bodies.push_back(b);
  }
  return position_of;
}

/// Which bodies the selection's scope keeps.
std::vector<bool> bodies_in_scope(const ModelData& m) {
  const ModelSelection& sel = m.in.selection;
  std::vector<bool> in_scope(m.bodies.size(), false);
  const auto nth_of_kind = [&](BodyKind kind, int index, const char* what) {
    int count = 0;
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      if (m.bodies[i].kind != kind) continue;
      if (count++ == index) return static_cast<int>(i);
    }
    throw std::invalid_argument(fmt::format(
        "selection.index: {} {} requested, the vehicle has {}", what, index, count));
  };
  if (sel.scope == "vehicle") {
    std::fill(in_scope.begin(), in_scope.end(), true);
  } else if (sel.scope == "bogie") {
    const int bogie = nth_of_kind(BodyKind::bogie_frame, sel.index, "bogie");
    in_scope[static_cast<std::size_t>(bogie)] = true;
    for (const ElementData& e : m.elements) {
      const int other = e.a == bogie ? e.b : (e.b == bogie ? e.a : -1);
      if (other >= 0 && m.bodies[static_cast<std::size_t>(other)].kind == BodyKind::wheelset) {
        in_scope[static_cast<std::size_t>(other)] = true;
      }
    }
  } else if (sel.scope == "wheelset") {
    in_scope[static_cast<std::size_t>(nth_of_kind(BodyKind::wheelset, sel.index, "wheelset"))] =
        true;
  } else {
    throw std::invalid_argument(fmt::format(
        "selection.scope: unknown '{}'; allowed: vehicle, bogie, wheelset", sel.scope));
  }
  return in_scope;
}

/// Active DOF per body (model order): the spec's flags, minus frozen ones, minus a wheelset's
/// pitch (its rotation about the axle is the spin), none outside the scope.
std::vector<std::array<bool, 6>> active_dofs(const ModelData& m,
                                             const std::vector<int>& position_of,
                                             const std::vector<bool>& in_scope) {
  const auto& cfg = m.in.config;
  std::vector<std::array<bool, 6>> active(m.bodies.size());
  for (std::size_t c = 0; c < cfg.bodies.size(); ++c) {
    const auto i = static_cast<std::size_t>(position_of[c]);
    active[i] = cfg.bodies[c].active;
    if (cfg.bodies[c].kind == BodyKind::wheelset) active[i][4] = false;
    if (!in_scope[i]) active[i].fill(false);
  }
  for (const std::string& f : m.in.selection.frozen) {
    const auto dot = f.find('.');
    const std::string body = dot == std::string::npos ? "" : f.substr(0, dot);
    const std::string dof = dot == std::string::npos ? f : f.substr(dot + 1);
    const auto it = std::find(kDofNames.begin(), kDofNames.end(), dof);
    require(it != kDofNames.end(),
            fmt::format("selection.frozen: '{}': unknown DOF '{}'; allowed: x, y, z, roll, pitch, "
                        "yaw (optionally as body.dof)",
                        f, dof));
    const auto k = static_cast<std::size_t>(it - kDofNames.begin());
    bool found = body.empty();
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      if (body.empty() || m.bodies[i].name == body) {
        active[i][k] = false;
        found = true;
      }
    }
    require(found, fmt::format("selection.frozen: '{}': no body named '{}'", f, body));
  }
  return active;
}

/// State layout: per body [positions][rates][spin], then the series dampers it hosts.
void lay_out_states(ModelData& m, const std::vector<int>& position_of,
                    const std::vector<bool>& in_scope,
                    const std::vector<std::array<bool, 6>>& active) {
  const auto& cfg = m.in.config;
  std::vector<bool> spin_dof(m.bodies.size(), false);
  for (std::size_t c = 0; c < cfg.bodies.size(); ++c) {
    spin_dof[static_cast<std::size_t>(position_of[c])] = cfg.bodies[c].spin_dof;
  }
  int next = 0;
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    BodyData& b = m.bodies[i];
    b.block_begin = next;
    for (std::size_t d = 0; d < 6; ++d) {
      if (active[i][d]) b.q[d] = next++;
    }
    for (std::size_t d = 0; d < 6; ++d) {
      if (active[i][d]) b.v[d] = next++;
    }
    if (b.kind == BodyKind::wheelset && spin_dof[i] && in_scope[i]) b.spin = next++;
    b.dynamic = next > b.block_begin;
    b.has_contact = b.kind == BodyKind::wheelset && in_scope[i];
    for (ElementData& e : m.elements) {
      if (e.spec.type != ElementType::series_damper) continue;
      const bool a_in = e.a >= 0 && in_scope[static_cast<std::size_t>(e.a)];
      const bool b_in = in_scope[static_cast<std::size_t>(e.b)];
      const int host = a_in ? e.a : e.b;
      if (host == static_cast<int>(i) && (a_in || b_in)) e.state = next++;
    }
    // The co-running track under a wheelset: its positions and rates, next to the wheelset.
    if (b.has_contact && m.in.track_structure.flexible()) {
      b.track = next;
      next += 2 * track::kTrackPositions;
    }
    next = lay_out_output_filters(m, i, next);
    b.block_end = next;
  }
  m.n_states = static_cast<std::size_t>(next);

  // Drop elements between two bodies without states (they cannot act on the model).
  std::erase_if(m.elements, [&](const ElementData& e) {
    const bool a_dyn = e.a >= 0 && m.bodies[static_cast<std::size_t>(e.a)].dynamic;
    const bool b_dyn = m.bodies[static_cast<std::size_t>(e.b)].dynamic;
    return !a_dyn && !b_dyn && e.state < 0;
  });
  for (ElementData& e : m.elements) {
    const Eigen::Vector3d pb = m.bodies[static_cast<std::size_t>(e.b)].rest + e.spec.point_b;
    const Eigen::Vector3d pa =
        e.a >= 0 ? Eigen::Vector3d(m.bodies[static_cast<std::size_t>(e.a)].rest + e.spec.point_a)
                 : e.spec.point_a;
    e.rest_vector = pb - pa;
  }
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    if (m.bodies[i].has_contact) m.contact_bodies.push_back(static_cast<int>(i));
    if (m.bodies[i].kind == BodyKind::car_body && m.car_body < 0) m.car_body = static_cast<int>(i);
  }
}

void build_contact_mechanics(ModelData& m) {
  const WheelRailSpec& wr = m.in.config.wheel_rail;
  ContactMechanics& c = m.contact;
  if (wr.normal_model == "semi_hertz") {
    c.semi_hertz_pair = m.in.geometry->profile_pair();
    require(c.semi_hertz_pair != nullptr,
            fmt::format("wheel_rail.normal: semi_hertz needs the wheel and rail profiles around "
                        "each contact point, which geometry '{}' does not have; allowed with it: "
                        "hertz (semi_hertz needs geometry table or search)",
                        m.in.geometry->name()));
  }
  c.material = contact::Material{wr.shear_modulus, wr.poisson};
  c.contact_modulus = contact::combine(c.material, c.material).contact_modulus;
  c.reduction = wr.reduction;
  if (!wr.reduction_table.empty()) {
    try {
      c.reduction_table.emplace(contact::KijTable::read_hdf5(wr.reduction_table),
                                wr.reduction_table_point);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(
          fmt::format("wheel_rail.reduction_table ({}): {}", wr.reduction_table, e.what()));
    }
  }
  try {
    c.tangential = contact::make_tangential_model(wr.tangential_model, wr.tangential_options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("wheel_rail.tangential_model: {}", e.what()));
  }
  if (m.in.track) m.nominal_rail_spacing = m.in.track->alignment().design().rail_spacing;
}

void build_track_structure(ModelData& m) {
  if (!m.in.track_structure.flexible()) return;
  m.track = track::co_running_equivalent(m.in.track_structure.ballasted, m.nominal_rail_spacing);
  m.track->validate();
}

}  // namespace

std::shared_ptr<const ModelData> build_model_data(VehicleModelInputs inputs) {
  validate_inputs(inputs);
  auto data = std::make_shared<ModelData>();
  ModelData& m = *data;
  m.in = std::move(inputs);
  const std::vector<int> position_of = order_bodies(m);
  resolve_output_signals(m);
  // Elements (validated against the config's indices, stored with model indices).
  for (const SuspensionElementSpec& s : m.in.config.elements) {
    ElementData e;
    e.spec = s;
    e.a = s.body_a >= 0 ? position_of[static_cast<std::size_t>(s.body_a)] : -1;
    e.b = position_of[static_cast<std::size_t>(s.body_b)];
    m.elements.push_back(e);
  }
  const std::vector<bool> in_scope = bodies_in_scope(m);
  lay_out_states(m, position_of, in_scope, active_dofs(m, position_of, in_scope));
  build_contact_mechanics(m);
  build_track_structure(m);
  name_states_and_signals(m);
  return data;
}

Eigen::Matrix3d attitude_matrix(const Eigen::Vector3d& a) {
  // R = Rz(yaw) Ry(pitch) Rx(roll).
  const double cx = std::cos(a.x()), sx = std::sin(a.x());
  const double cy = std::cos(a.y()), sy = std::sin(a.y());
  const double cz = std::cos(a.z()), sz = std::sin(a.z());
  Eigen::Matrix3d r;
  r << cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx,  //
      sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx,   //
      -sy, cy * sx, cy * cx;
  return r;
}

}  // namespace ferro::vehicle::detail
