// VehicleModel: construction (validation, selection, state layout), equations of motion in the
// moving track frames, signals, static equilibrium.
//
// References: see vehicle_model.hpp.
// Known deviations: see vehicle_model.hpp.

#include "ferro/vehicle/vehicle_model.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "ferro/contact/geometry/contact_sources.hpp"
#include "ferro/contact/geometry/profile.hpp"
#include "vehicle_model_impl.hpp"

namespace ferro::vehicle {

// ---------------------------------------------------------------------------------------------
// Speed profile

double SpeedProfile::speed(double t) const { return std::max(0.0, initial + acceleration * t); }

double SpeedProfile::rate(double t) const {
  return initial + acceleration * t > 0.0 || (initial == 0.0 && acceleration > 0.0) ? acceleration
                                                                                     : 0.0;
}

double SpeedProfile::distance(double t) const {
  if (acceleration >= 0.0 || initial + acceleration * t > 0.0) {
    return initial * t + 0.5 * acceleration * t * t;
  }
  // Decelerating to a stop at t_stop = -initial / acceleration.
  return -0.5 * initial * initial / acceleration;
}

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

bool finite_positive(double v) { return std::isfinite(v) && v > 0.0; }

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

void validate_element(const SuspensionElementSpec& s, const std::string& where, int n_bodies) {
  require(s.body_b >= 0 && s.body_b < n_bodies,
          fmt::format("{}.body_b: must index a body (0..{}), got {}", where, n_bodies - 1,
                      s.body_b));
  require(s.body_a >= -1 && s.body_a < n_bodies && s.body_a != s.body_b,
          fmt::format("{}.body_a: must index another body or be -1 (track frame), got {}", where,
                      s.body_a));
  const auto finite3 = [](const Eigen::Vector3d& v) { return v.allFinite(); };
  require(finite3(s.point_a) && finite3(s.point_b),
          fmt::format("{}.point_a/point_b: must be finite [m]", where));
  switch (s.type) {
    case ElementType::spring_damper:
      require(finite3(s.stiffness) && (s.stiffness.array() >= 0.0).all(),
              fmt::format("{}.stiffness: must be finite and >= 0 N/m", where));
      require(finite3(s.damping) && (s.damping.array() >= 0.0).all(),
              fmt::format("{}.damping: must be finite and >= 0 N s/m", where));
      require(finite3(s.preload), fmt::format("{}.preload: must be finite [N]", where));
      break;
    case ElementType::series_damper:
      require(static_cast<int>(s.axis) <= 2,
              fmt::format("{}.axis: series_damper acts along x, y or z", where));
      require(finite_positive(s.k), fmt::format("{}.k: series stiffness must be > 0 N/m", where));
      require(finite_positive(s.c), fmt::format("{}.c: damping must be > 0 N s/m", where));
      break;
    case ElementType::bump_stop: {
      require(static_cast<int>(s.axis) <= 2,
              fmt::format("{}.axis: bump_stop acts along x, y or z", where));
      require(std::isfinite(s.clearance) && s.clearance >= 0.0,
              fmt::format("{}.clearance: must be >= 0 m", where));
      const auto& xs = s.table_displacement;
      require(!xs.empty() && xs.size() == s.table_force.size(),
              fmt::format("{}.table_displacement/table_force: need equal, non-zero lengths",
                          where));
      require(xs.size() >= 2 || xs.front() > s.clearance,
              fmt::format("{}.table_displacement: need two points or one beyond the clearance",
                          where));
      for (std::size_t i = 0; i < xs.size(); ++i) {
        require(std::isfinite(xs[i]) && std::isfinite(s.table_force[i]) && xs[i] >= s.clearance &&
                    (i == 0 || xs[i] > xs[i - 1]),
                fmt::format("{}.table_displacement[{}]: must be finite, >= clearance and "
                            "increasing",
                            where, i));
      }
      break;
    }
    case ElementType::torsion:
      require(s.axis == Dof::roll || s.axis == Dof::yaw,
              fmt::format("{}.axis: torsion acts about roll or yaw", where));
      require(std::isfinite(s.k) && s.k >= 0.0 && std::isfinite(s.c) && s.c >= 0.0,
              fmt::format("{}.k/c: must be finite and >= 0", where));
      break;
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Construction

VehicleModel::VehicleModel(VehicleModelInputs inputs) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.in = std::move(inputs);
  const VehicleConfig& cfg = m.in.config;
  const WheelRailSpec& wr = cfg.wheel_rail;
  const int n_bodies = static_cast<int>(cfg.bodies.size());

  require(m.in.geometry != nullptr, "geometry: a contact geometry source is required");
  require(n_bodies > 0, "bodies: at least one body is required");
  require(finite_positive(cfg.gravity), "gravity: must be > 0 m/s^2");
  require(std::isfinite(m.in.speed.initial) && m.in.speed.initial >= 0.0,
          "speed.initial: must be finite and >= 0 m/s");
  require(std::isfinite(m.in.speed.acceleration), "speed.acceleration: must be finite m/s^2");
  require(std::isfinite(m.in.start_position), "start_position: must be finite m");
  require(std::isfinite(wr.friction) && wr.friction >= 0.0, "wheel_rail.friction: must be >= 0");
  require(finite_positive(wr.regularisation_speed),
          "wheel_rail.regularisation_speed: must be > 0 m/s");
  require(std::isfinite(wr.hunt_crossley_alpha) && wr.hunt_crossley_alpha >= 0.0,
          "wheel_rail.hunt_crossley_alpha: must be finite and >= 0 s/m");
  require(finite_positive(wr.shear_modulus), "wheel_rail.shear_modulus: must be > 0 Pa");
  require(std::isfinite(wr.poisson) && wr.poisson >= 0.0 && wr.poisson < 0.5,
          "wheel_rail.poisson: must be in [0, 0.5)");
  require(wr.normal_model == "hertz" || wr.normal_model == "semi_hertz",
          fmt::format("wheel_rail.normal: '{}' is not available in the vehicle model; "
                      "allowed: hertz, semi_hertz",
                      wr.normal_model));
  if (wr.normal_model == "semi_hertz") {
    m.semi_hertz_pair = m.in.geometry->profile_pair();
    require(m.semi_hertz_pair != nullptr,
            fmt::format("wheel_rail.normal: semi_hertz needs the wheel and rail profiles around "
                        "each contact point, which geometry '{}' does not have; allowed with it: "
                        "hertz (semi_hertz needs geometry table or search)",
                        m.in.geometry->name()));
  }
  for (int i = 0; i < 4; ++i) {
    require(finite_positive(wr.reduction[static_cast<std::size_t>(i)]),
            fmt::format("wheel_rail.reduction[{}]: K_ij must be finite and > 0", i));
  }

  // Bodies.
  std::vector<int> order(static_cast<std::size_t>(n_bodies));
  std::iota(order.begin(), order.end(), 0);
  for (int i = 0; i < n_bodies; ++i) {
    const RigidBodySpec& b = cfg.bodies[static_cast<std::size_t>(i)];
    const std::string where = fmt::format("bodies[{}] ('{}')", i, b.name);
    require(!b.name.empty(), fmt::format("bodies[{}].name: must not be empty", i));
    for (int j = 0; j < i; ++j) {
      require(cfg.bodies[static_cast<std::size_t>(j)].name != b.name,
              fmt::format("{}.name: duplicate of bodies[{}]", where, j));
    }
    require(finite_positive(b.mass), fmt::format("{}.mass: must be > 0 kg, got {}", where, b.mass));
    require(b.inertia.allFinite() && (b.inertia.array() > 0.0).all(),
            fmt::format("{}.inertia: roll, pitch, yaw must be > 0 kg m^2", where));
    require(b.position.allFinite(), fmt::format("{}.position: must be finite [m]", where));
    if (b.kind == BodyKind::wheelset) {
      require(finite_positive(b.nominal_rolling_radius),
              fmt::format("{}.nominal_rolling_radius: must be > 0 m", where));
    }
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return cfg.bodies[static_cast<std::size_t>(a)].position.x() >
           cfg.bodies[static_cast<std::size_t>(b)].position.x();
  });
  std::vector<int> position_of(static_cast<std::size_t>(n_bodies));  // config -> model index
  for (int i = 0; i < n_bodies; ++i) position_of[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = i;

  for (int i : order) {
    const RigidBodySpec& s = cfg.bodies[static_cast<std::size_t>(i)];
    BodyData b;
    b.name = s.name;
    b.kind = s.kind;
    b.mass = s.mass;
    b.inertia = s.inertia;
    b.rest = s.position;
    b.r0 = s.kind == BodyKind::wheelset ? s.nominal_rolling_radius : 0.0;
    m.bodies.push_back(b);
  }

  // Elements (validated against the config's indices, stored with model indices).
  for (std::size_t i = 0; i < cfg.elements.size(); ++i) {
    const SuspensionElementSpec& s = cfg.elements[i];
    validate_element(s, fmt::format("elements[{}] ('{}')", i, s.name), n_bodies);
    ElementData e;
    e.spec = s;
    e.a = s.body_a >= 0 ? position_of[static_cast<std::size_t>(s.body_a)] : -1;
    e.b = position_of[static_cast<std::size_t>(s.body_b)];
    m.elements.push_back(e);
  }

  // Selection: which bodies are in scope, which wheelsets have contact.
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

  // Active DOF: the spec's flags, minus frozen ones, minus a wheelset's pitch.
  std::vector<std::array<bool, 6>> active(m.bodies.size());
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const RigidBodySpec& s = cfg.bodies[static_cast<std::size_t>(order[i])];
    active[i] = s.active;
    if (s.kind == BodyKind::wheelset) active[i][4] = false;
    if (!in_scope[i]) active[i].fill(false);
  }
  for (const std::string& f : sel.frozen) {
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

  // State layout: per body [positions][rates][spin], then its series dampers.
  int next = 0;
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    BodyData& b = m.bodies[i];
    const RigidBodySpec& s = cfg.bodies[static_cast<std::size_t>(order[i])];
    b.block_begin = next;
    for (int d = 0; d < 6; ++d) {
      if (active[i][static_cast<std::size_t>(d)]) b.q[static_cast<std::size_t>(d)] = next++;
    }
    for (int d = 0; d < 6; ++d) {
      if (active[i][static_cast<std::size_t>(d)]) b.v[static_cast<std::size_t>(d)] = next++;
    }
    if (b.kind == BodyKind::wheelset && s.spin_dof && in_scope[i]) b.spin = next++;
    b.dynamic = next > b.block_begin;
    b.has_contact = b.kind == BodyKind::wheelset && in_scope[i];
    for (ElementData& e : m.elements) {
      if (e.spec.type != ElementType::series_damper) continue;
      const bool a_in = e.a >= 0 && in_scope[static_cast<std::size_t>(e.a)];
      const bool b_in = in_scope[static_cast<std::size_t>(e.b)];
      const int host = a_in ? e.a : e.b;
      if (host == static_cast<int>(i) && (a_in || b_in)) e.state = next++;
    }
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

  // Names.
  m.states.resize(m.n_states);
  static const char* kPosUnit[6] = {"m", "m", "m", "rad", "rad", "rad"};
  static const char* kRateUnit[6] = {"m/s", "m/s", "m/s", "rad/s", "rad/s", "rad/s"};
  for (const BodyData& b : m.bodies) {
    for (std::size_t d = 0; d < 6; ++d) {
      if (b.q[d] >= 0) {
        m.states[static_cast<std::size_t>(b.q[d])] = {
            fmt::format("{}.{}", b.name, kDofNames[d]), kPosUnit[d],
            fmt::format("{} {} ({}), from rest in its track frame", b.name, kDofNames[d],
                        kind_name(b.kind))};
        m.states[static_cast<std::size_t>(b.v[d])] = {
            fmt::format("{}.{}_dot", b.name, kDofNames[d]), kRateUnit[d],
            fmt::format("rate of {}.{}", b.name, kDofNames[d])};
      }
    }
    if (b.spin >= 0) {
      m.states[static_cast<std::size_t>(b.spin)] = {
          fmt::format("{}.spin", b.name), "rad/s", "spin speed perturbation beta (spin = V/r0 + beta)"};
    }
  }
  for (const ElementData& e : m.elements) {
    if (e.state >= 0) {
      m.states[static_cast<std::size_t>(e.state)] = {
          fmt::format("{}.damper_deflection", e.spec.name), "m",
          "internal deflection of the damper in series with its stiffness"};
    }
  }
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
      add("contact_y", "m", "lateral contact position from the rail reference point, + outwards");
      add("contact_angle", "rad", "contact angle of the most loaded point");
      add("points", "-", "number of loaded contact points");
      for (int k = 1; k <= WheelResult::kPointSignals; ++k) {
        m.signal_list.push_back(
            {fmt::format("{}.{}.point_{}.normal_force", name, side, k), "N",
             fmt::format("normal force of the wheel's loaded contact point {} in the order the "
                         "geometry source lists them (the multi-point table: increasing "
                         "wheel-profile coordinate), 0 when the wheel has fewer points",
                         k)});
      }
    }
  }
  if (m.car_body >= 0) {
    m.signal_list.push_back(
        {"car_body.ay", "m/s^2", "lateral acceleration read at the car body's centre of mass"});
  }
  m.signal_list.push_back({"position", "m", "arc length of the vehicle reference point"});
  m.signal_list.push_back({"speed", "m/s", "vehicle speed"});

  // Contact mechanics.
  m.material = contact::Material{wr.shear_modulus, wr.poisson};
  m.contact_modulus = contact::combine(m.material, m.material).contact_modulus;
  m.reduction = contact::ReductionFactors{wr.reduction[0], wr.reduction[1], wr.reduction[2],
                                          wr.reduction[3]};
  if (!wr.reduction_table.empty()) {
    try {
      m.reduction_table.emplace(contact::KijTable::read_hdf5(wr.reduction_table),
                                wr.reduction_table_point);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(
          fmt::format("wheel_rail.reduction_table ({}): {}", wr.reduction_table, e.what()));
    }
  }
  try {
    m.tangential = contact::make_tangential_model(wr.tangential_model, wr.tangential_options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("wheel_rail.tangential_model: {}", e.what()));
  }
  if (m.in.track) m.nominal_rail_spacing = m.in.track->alignment().design().rail_spacing;
}

VehicleModel::~VehicleModel() = default;

// ---------------------------------------------------------------------------------------------
// Evaluation

void VehicleModel::Impl::frame_at(double s, double speed, double rate, BodyKinematics& k,
                                  bool irregular) const {
  if (in.track) {
    if (irregular) {
      const track::TrackPoint p = in.track->at(s);
      k.frame = p.frame;
      k.irregularity = p.irregularity;
    } else {
      k.frame = in.track->alignment().frame(s);
      k.irregularity = track::IrregularitySample{};
    }
  } else {
    k.frame = track::TrackFrame{};
    k.frame.s = s;
    k.frame.position = Eigen::Vector3d(s, 0.0, 0.0);
    k.frame.gauge = in.config.wheel_rail.track_gauge;
    k.frame.rail_spacing = nominal_rail_spacing;
    k.irregularity = track::IrregularitySample{};
  }
  k.motion = track::frame_kinematics(k.frame, speed, rate, in.config.gravity);
}

void VehicleModel::Impl::evaluate(double t, std::span<const double> x, std::span<double> xdot,
                                  WheelResult* wheels, double* car_body_ay,
                                  double speed_override) const {
  thread_local std::vector<BodyKinematics> kin;
  if (kin.size() < bodies.size()) kin.resize(bodies.size());

  const double speed = std::isfinite(speed_override) ? speed_override : in.speed.speed(t);
  const double rate = in.speed.rate(t);
  const double s_ref = in.start_position + in.speed.distance(t);

  // Body kinematics.
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const BodyData& b = bodies[i];
    BodyKinematics& k = kin[i];
    frame_at(s_ref + b.rest.x(), speed, rate, k, b.has_contact);
    for (std::size_t d = 0; d < 3; ++d) {
      k.u[static_cast<Eigen::Index>(d)] = b.q[d] >= 0 ? x[static_cast<std::size_t>(b.q[d])] : 0.0;
      k.u_dot[static_cast<Eigen::Index>(d)] =
          b.v[d] >= 0 ? x[static_cast<std::size_t>(b.v[d])] : 0.0;
      k.angles[static_cast<Eigen::Index>(d)] =
          b.q[d + 3] >= 0 ? x[static_cast<std::size_t>(b.q[d + 3])] : 0.0;
      k.rates[static_cast<Eigen::Index>(d)] =
          b.v[d + 3] >= 0 ? x[static_cast<std::size_t>(b.v[d + 3])] : 0.0;
    }
    k.attitude = attitude_matrix(k.angles);
    k.spin = b.kind == BodyKind::wheelset
                 ? speed / b.r0 + (b.spin >= 0 ? x[static_cast<std::size_t>(b.spin)] : 0.0)
                 : 0.0;
    k.force.setZero();
    k.moment.setZero();
  }

  // Suspension elements.
  BodyKinematics track_frame;
  for (const ElementData& e : elements) {
    if (e.a < 0) frame_at(s_ref + e.spec.point_a.x(), speed, rate, track_frame, false);
    apply_element(*this, e, kin, track_frame, x, xdot);
  }

  // Wheel-rail forces.
  for (std::size_t w = 0; w < contact_bodies.size(); ++w) {
    const auto i = static_cast<std::size_t>(contact_bodies[w]);
    apply_wheel_rail(*this, bodies[i], kin[i], wheels != nullptr ? wheels + 2 * w : nullptr);
  }

  if (car_body_ay != nullptr && car_body >= 0) {
    const BodyData& b = bodies[static_cast<std::size_t>(car_body)];
    const BodyKinematics& k = kin[static_cast<std::size_t>(car_body)];
    *car_body_ay = b.dynamic ? (k.attitude.transpose() * k.force).y() / b.mass
                             : std::numeric_limits<double>::quiet_NaN();
  }
  if (xdot.empty()) return;

  // Equations of motion in each body's track frame.
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const BodyData& b = bodies[i];
    if (!b.dynamic) continue;
    const BodyKinematics& k = kin[i];
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
      if (b.q[d] >= 0) {
        xdot[static_cast<std::size_t>(b.q[d])] = k.u_dot[static_cast<Eigen::Index>(d)];
        xdot[static_cast<std::size_t>(b.v[d])] = acc[static_cast<Eigen::Index>(d)];
      }
      if (b.q[d + 3] >= 0) {
        xdot[static_cast<std::size_t>(b.q[d + 3])] = k.rates[static_cast<Eigen::Index>(d)];
        xdot[static_cast<std::size_t>(b.v[d + 3])] = ang_acc[static_cast<Eigen::Index>(d)];
      }
    }
    if (b.spin >= 0) {
      // I_y (d spin / dt) = M_y - (w_h x H)_y - I_y (alpha + w x theta')_y, spin = V/r0 + beta.
      xdot[static_cast<std::size_t>(b.spin)] = ang_acc.y() - rate / b.r0;
    }
  }
}

std::size_t VehicleModel::size() const { return impl_->n_states; }

int VehicleModel::rhs(double t, std::span<const double> x, std::span<double> xdot) const {
  try {
    impl_->evaluate(t, x, xdot, nullptr, nullptr);
  } catch (const std::out_of_range&) {
    // The vehicle left the designed track or a contact table's range. A trial state of the
    // integrator's corrector may do so while the solution does not: recoverable (the step is
    // cut); a solution that really leaves it still stops the run after repeated failures.
    return kRhsRecoverable;
  } catch (const std::exception&) {
    return kRhsRecoverable;
  }
  for (double v : xdot) {
    if (!std::isfinite(v)) return kRhsRecoverable;
  }
  return kRhsOk;
}

std::vector<SignalInfo> VehicleModel::state_info() const { return impl_->states; }
std::vector<SignalInfo> VehicleModel::signal_info() const { return impl_->signal_list; }

void VehicleModel::signals(double t, std::span<const double> x, std::span<double> out) const {
  const Impl& m = *impl_;
  thread_local std::vector<WheelResult> wheels;
  wheels.assign(2 * m.contact_bodies.size(), WheelResult{});
  double ay = std::numeric_limits<double>::quiet_NaN();
  m.evaluate(t, x, {}, wheels.data(), &ay);
  std::size_t o = 0;
  for (const WheelResult& w : wheels) {
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

std::pair<int, int> VehicleModel::jacobian_bandwidth() const {
  const Impl& m = *impl_;
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

std::vector<double> VehicleModel::rest_state() const {
  return std::vector<double>(impl_->n_states, 0.0);
}

std::size_t VehicleModel::wheelset_count() const { return impl_->contact_bodies.size(); }

int VehicleModel::state_index(const std::string& body, Dof dof) const {
  for (const BodyData& b : impl_->bodies) {
    if (b.name == body) return b.q[static_cast<std::size_t>(dof)];
  }
  return -1;
}

int VehicleModel::rate_index(const std::string& body, Dof dof) const {
  for (const BodyData& b : impl_->bodies) {
    if (b.name == body) return b.v[static_cast<std::size_t>(dof)];
  }
  return -1;
}

const VehicleModelInputs& VehicleModel::inputs() const { return impl_->in; }

// ---------------------------------------------------------------------------------------------
// Static equilibrium

namespace {

struct NewtonOutcome {
  bool converged = false;
  double residual = 0.0;  ///< largest scaled residual at the end [-]
  int iterations = 0;
};

}  // namespace

std::vector<double> VehicleModel::static_equilibrium(double t,
                                                     std::span<const double> start) const {
  const Impl& m = *impl_;
  if (!start.empty() && start.size() != m.n_states) {
    throw std::invalid_argument(fmt::format(
        "static_equilibrium: start has {} entries, the model {} states", start.size(), m.n_states));
  }
  std::vector<double> guess = rest_state();
  // Unknowns: positions, spin perturbations and series-damper deflections; residuals: the
  // accelerations of those positions and the rates of the other two.
  std::vector<int> unknown, residual;
  // Each residual is scaled to a fraction of the body's weight: a translational acceleration by
  // 1/g (force / weight), an angular acceleration by r_k/g with r_k = sqrt(I_k/m) the radius of
  // gyration (moment / (weight r_k)), a series-damper deflection rate by 1/(g * 1 s). Forces and
  // moments of bodies of any mass then meet one relative criterion.
  std::vector<double> scale;
  const double g = m.in.config.gravity > 0.0 ? m.in.config.gravity : 9.81;
  // The longitudinal position of the whole vehicle is neutral (no longitudinal stiffness to the
  // ground at zero velocity): the car body's x stays at its rest value and defines it.
  for (const BodyData& b : m.bodies) {
    for (std::size_t d = 0; d < 6; ++d) {
      if (b.q[d] >= 0 && !(d == 0 && b.kind == BodyKind::car_body)) {
        unknown.push_back(b.q[d]);
        residual.push_back(b.v[d]);
        scale.push_back(d < 3 ? 1.0 / g : std::sqrt(b.inertia[static_cast<Eigen::Index>(d - 3)] / b.mass) / g);
      }
    }
    if (b.spin >= 0) {
      unknown.push_back(b.spin);
      residual.push_back(b.spin);
      scale.push_back(std::sqrt(b.inertia[1] / b.mass) / g);
    }
    // Lower a wheelset onto the rails (touching height of the centred pose, found by bisection
    // on the source's contacts, then a typical Hertz approach) so that Newton starts with
    // contact stiffness.
    if (b.has_contact && b.q[2] >= 0) {
      std::vector<contact::WheelRailContact> points;
      double lifted = -0.02, penetrating = 0.02;  // pose.vertical bracket [m]
      for (int it = 0; it < 40; ++it) {
        contact::WheelsetPose pose;
        pose.vertical = 0.5 * (lifted + penetrating);
        m.in.geometry->contacts(pose, points);
        (points.empty() ? lifted : penetrating) = pose.vertical;
      }
      guess[static_cast<std::size_t>(b.q[2])] = -(penetrating + 1.0e-4);
    }
  }
  for (const ElementData& e : m.elements) {
    if (e.state >= 0) {
      unknown.push_back(e.state);
      residual.push_back(e.state);
      scale.push_back(1.0 / g);  // [s/m]: a deflection rate of 1 m/s counts as 1 g
    }
  }
  const auto n = static_cast<Eigen::Index>(unknown.size());
  if (n == 0) return start.empty() ? guess : std::vector<double>(start.begin(), start.end());

  // Relative to the weight: 1e-9 is far below the 0.1 % wheel-load test and above the
  // round-off of the contact forces (~1e-13 of the weight); kStallTol accepts a Newton that
  // stalled at the geometry's resolution (a table or search resolves gaps to ~1e-10 m, which
  // a Hertz stiffness of ~1e9 N/m turns into ~1e-7 of a wheel load).
  constexpr double kResidualTol = 1e-9;  // [-]
  constexpr double kStallTol = 1e-6;     // [-]
  constexpr double kStep = 1e-8;         // finite-difference step [m, rad]

  // Scaled residual at `state` for the speed `speed` (NaN: the profile's V(t)); false where the
  // model cannot be evaluated (a pose outside a contact table, the track's end).
  std::vector<double> xdot(m.n_states);
  const auto eval = [&](const std::vector<double>& state, double speed, Eigen::VectorXd& r) {
    try {
      m.evaluate(t, state, xdot, nullptr, nullptr, speed);
    } catch (const std::exception&) {
      return false;
    }
    for (Eigen::Index i = 0; i < n; ++i) {
      r[i] = xdot[static_cast<std::size_t>(residual[i])] * scale[static_cast<std::size_t>(i)];
      if (!std::isfinite(r[i])) return false;
    }
    return true;
  };

  // Damped Newton from x (updated in place): numerical Jacobian, minimum-norm steps (weakly
  // determined directions stay near rest), step halved until the residual's 2-norm falls.
  Eigen::VectorXd r(n), r_trial(n), r_step(n);
  Eigen::MatrixXd J(n, n);
  const auto newton = [&](std::vector<double>& x, double speed, int max_iterations) {
    NewtonOutcome out;
    if (!eval(x, speed, r)) {
      out.residual = std::numeric_limits<double>::infinity();
      return out;
    }
    for (; out.iterations < max_iterations; ++out.iterations) {
      out.residual = r.lpNorm<Eigen::Infinity>();
      if (out.residual < kResidualTol) {
        out.converged = true;
        return out;
      }
      for (Eigen::Index j = 0; j < n; ++j) {
        std::vector<double> xp = x;
        xp[static_cast<std::size_t>(unknown[j])] += kStep;
        if (!eval(xp, speed, r_step)) return out;
        J.col(j) = (r_step - r) / kStep;
      }
      const Eigen::VectorXd dx = J.completeOrthogonalDecomposition().solve(-r);
      double lambda = 1.0;
      bool improved = false;
      for (int ls = 0; ls < 30; ++ls, lambda *= 0.5) {
        std::vector<double> xt = x;
        for (Eigen::Index j = 0; j < n; ++j) xt[static_cast<std::size_t>(unknown[j])] += lambda * dx[j];
        if (eval(xt, speed, r_trial) && r_trial.norm() < r.norm()) {
          x = xt;
          r = r_trial;
          improved = true;
          break;
        }
      }
      if (!improved) break;
    }
    out.residual = r.lpNorm<Eigen::Infinity>();
    out.converged = out.residual < kStallTol;  // stalled at the geometry's resolution
    return out;
  };

  const double nan = std::numeric_limits<double>::quiet_NaN();
  // 1. Newton from the given start, or from rest with the wheelsets lowered onto the rails.
  std::vector<double> x = start.empty() ? guess : std::vector<double>(start.begin(), start.end());
  const NewtonOutcome direct = newton(x, nan, 200);
  if (direct.converged) return x;

  // 2. Continuation in speed. The residual is not smooth: the wheel-rail contact changes its
  // points (tread, flange root, flange: kinks where a point appears or fades in), and a bump
  // stop's table has kinks; Newton from rest can end against such a kink or step with
  // a large residual, typically a sharp curve at speed where the wheelsets roll on their flanges
  // and the secondary lateral suspension takes the car body's versine. At V = 0 the creepages
  // vanish (no sliding velocity) and the equilibrium is that of the elastic suspension, gravity,
  // cant and normal contact alone, which Newton finds from rest. From there the speed is raised
  // in steps, each Newton started from the previous equilibrium extrapolated along the path:
  // first to the regularisation speed, over which the creep forces grow from zero to their
  // rolling values (creepages are the sliding velocity over max(V, regularisation_speed)), then
  // to the target speed (centrifugal force, cant deficiency). A step whose Newton fails is
  // halved; the criteria are those of the direct solve.
  x = guess;
  const NewtonOutcome at_rest = newton(x, 0.0, 200);
  if (!at_rest.converged) {
    throw std::runtime_error(fmt::format(
        "static_equilibrium: Newton did not converge (largest residual {:.3g} of the weight; at "
        "V = 0, the start of the continuation in speed: {:.3g})",
        direct.residual, at_rest.residual));
  }
  const double v_target = m.in.speed.speed(t);
  const double v_reg = m.in.config.wheel_rail.regularisation_speed;
  // Iterations a continuation step may take before it is halved, and the smallest step [m/s].
  constexpr int kStepIterations = 30;
  const double min_step = 1e-6 * std::max(v_target, v_reg);
  std::vector<double> x_prev = x;  // the accepted point before x, for the secant predictor
  double v = 0.0, v_prev = 0.0;
  double last_residual = 0.0;
  for (const double v_end : {std::min(v_target, v_reg), v_target}) {
    double h = v_end - v;
    while (v < v_end) {
      const double v_try = v_end - v <= h * (1.0 + 1e-12) ? v_end : v + h;
      bool accepted = false;
      // Secant predictor along the path first, then the previous equilibrium as it is.
      for (const bool predict : {v > v_prev, false}) {
        std::vector<double> xt = x;
        if (predict) {
          const double ratio = (v_try - v) / (v - v_prev);
          for (const int k : unknown) {
            const auto i = static_cast<std::size_t>(k);
            xt[i] += ratio * (x[i] - x_prev[i]);
          }
        }
        const NewtonOutcome o = newton(xt, v_try, kStepIterations);
        last_residual = o.residual;
        if (o.converged) {
          x_prev = std::move(x);
          x = std::move(xt);
          v_prev = v;
          v = v_try;
          // A step that converged quickly may double (within its segment).
          if (o.iterations <= kStepIterations / 4) h *= 2.0;
          accepted = true;
          break;
        }
      }
      if (accepted) continue;
      h *= 0.5;
      if (h < min_step) {
        throw std::runtime_error(fmt::format(
            "static_equilibrium: Newton did not converge (largest residual {:.3g} of the weight "
            "from rest); the continuation in speed from V = 0 stopped at {:.6g} m/s of {:.6g} "
            "(largest residual {:.3g})",
            direct.residual, v, v_target, last_residual));
      }
    }
  }
  return x;
}

// ---------------------------------------------------------------------------------------------

std::shared_ptr<const contact::ContactGeometrySource> make_geometry_source(
    const WheelRailSpec& spec, const std::string& base_dir) {
  const auto resolve = [&base_dir](const std::string& path) {
    if (path.empty() || path.front() == '/' || base_dir.empty()) return path;
    return base_dir + "/" + path;
  };
  require(finite_positive(spec.nominal_radius),
          "wheel_rail.nominal_radius: the wheels' nominal rolling radius must be > 0 m");
  contact::ContactSourceSpec cs;
  cs.kind = spec.geometry;
  if (spec.geometry == "conical") {
    cs.conical.conicity = spec.conicity;
    cs.conical.contact_half_distance = spec.contact_half_distance;
    cs.conical.nominal_radius = spec.nominal_radius;
    cs.conical.curvature_a = spec.conical_curvature_a;
    cs.conical.curvature_b = spec.conical_curvature_b;
  } else if (spec.geometry == "search" || spec.geometry == "table") {
    require(!spec.wheel_profile.empty(),
            fmt::format("wheel_rail.wheel_profile: required by geometry {}", spec.geometry));
    require(!spec.rail_profile.empty(),
            fmt::format("wheel_rail.rail_profile: required by geometry {}", spec.geometry));
    cs.wheel_profile = resolve(spec.wheel_profile);
    cs.rail_profile = resolve(spec.rail_profile);
    cs.pair.track_gauge = spec.track_gauge;
    cs.pair.flange_back_distance = spec.flange_back_distance;
    cs.pair.flange_back_y = spec.flange_back_y;
    cs.pair.nominal_radius = spec.nominal_radius;
    cs.pair.rail_inclination = spec.rail_inclination;
    cs.table_file = resolve(spec.table_file);
    if (std::isfinite(spec.wheel_tread_conicity)) {
      require(std::isfinite(spec.wheel_tread_join_y),
              "wheel_rail.wheel_tread_join_y: required with wheel_tread_conicity [m]");
      cs.wheel_tread_conicity = spec.wheel_tread_conicity;
      cs.wheel_tread_join_y = spec.wheel_tread_join_y;
    }
  } else if (spec.geometry == "imported") {
    require(!spec.imported_table.empty(),
            "wheel_rail.imported_table: required by geometry imported");
    cs.imported_table = resolve(spec.imported_table);
  } else {
    throw std::invalid_argument(fmt::format(
        "wheel_rail.geometry: '{}' is not one of table, search, imported, conical",
        spec.geometry));
  }
  try {
    return contact::make_contact_source(cs);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(
        fmt::format("wheel_rail (geometry {}): {}", spec.geometry, e.what()));
  }
}

}  // namespace ferro::vehicle
