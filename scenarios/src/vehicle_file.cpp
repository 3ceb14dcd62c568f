#include "ferro/scenarios/vehicle_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "ferro/contact/tangential/tangential_model.hpp"
#include "located.hpp"
#include "yaml_values.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;
using vehicle::BodyKind;
using vehicle::Dof;
using vehicle::ElementType;
using vehicle::RigidBodySpec;
using vehicle::SuspensionElementSpec;
using vehicle::VehicleConfig;

constexpr double kStandardGravity = 9.81;  // [m/s^2], the value the data files were made with
// At-rest lines of "vector" dampers shorter than this across their axis count as aligned [m].
constexpr double kAlignmentTolerance = 1e-9;

const std::vector<std::string> kAxes = {"x", "y", "z"};
const std::vector<std::string> kRotationAxes = {"roll", "pitch", "yaw"};

Dof dof_from_name(const std::string& name) {
  for (std::size_t i = 0; i < vehicle::kDofNames.size(); ++i)
    if (name == vehicle::kDofNames[i]) return static_cast<Dof>(i);
  return Dof::x;
}

std::string resolve(const MapReader& r, const std::string& file) {
  if (file.empty()) return file;
  const fs::path p(file);
  if (p.is_absolute()) return p.lexically_normal().string();
  return (fs::path(r.file()).parent_path() / p).lexically_normal().string();
}

double positive(MapReader& r, const std::string& key, const char* unit) {
  const double v = r.number(key);
  if (!(v > 0.0)) r.fail(key, fmt::format("must be > 0 {}, got {}", unit, v));
  return v;
}

double non_negative_or(MapReader& r, const std::string& key, double fallback, const char* unit) {
  const double v = r.number_or(key, fallback);
  if (!(v >= 0.0)) r.fail(key, fmt::format("must be >= 0 {}, got {}", unit, v));
  return v;
}

double non_negative(MapReader& r, const std::string& key, const char* unit) {
  const double v = r.number(key);
  if (!(v >= 0.0)) r.fail(key, fmt::format("must be >= 0 {}, got {}", unit, v));
  return v;
}

// {x, y, z} mapping, absent components 0.
Eigen::Vector3d axis_map(MapReader m, const char* unit) {
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) v[i] = non_negative_or(m, kAxes[i], 0.0, unit);
  m.finish();
  return v;
}

// A body block of the compact form.
struct BodyBlock {
  double mass = 0.0;
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();
  double cg_height = 0.0;
  std::array<bool, 6> active{};
  bool spin = false;
  double rolling_radius = RigidBodySpec::kNaN;
  double flange_back_distance = RigidBodySpec::kNaN;
};

RigidBodySpec make_body(const std::string& name, BodyKind kind, const BodyBlock& b,
                        const Eigen::Vector3d& position) {
  RigidBodySpec s;
  s.name = name;
  s.kind = kind;
  s.mass = b.mass;
  s.inertia = b.inertia;
  s.position = position;
  s.active = b.active;
  s.nominal_rolling_radius = b.rolling_radius;
  s.spin_dof = b.spin;
  return s;
}

BodyBlock read_body(MapReader b, BodyKind kind) {
  BodyBlock out;
  out.mass = b.number("mass");
  {
    MapReader in = b.map("inertia");
    out.inertia[0] = in.number("roll");
    if (kind == BodyKind::wheelset && in.has("spin")) {
      if (in.has("pitch")) in.fail("spin", "give either pitch or spin (the axle axis), not both");
      out.inertia[1] = in.number("spin");
      in.allow("pitch");
    } else {
      out.inertia[1] = in.number("pitch");
      if (kind == BodyKind::wheelset) in.allow("spin");
    }
    out.inertia[2] = in.number("yaw");
    in.finish();
  }
  // Default degrees of freedom: every body free but the car body's x (the vehicle's
  // longitudinal position, neutral: nothing holds it lengthwise) and the wheelset's pitch (its
  // rotation about the axle is the spin). Bogie frames and wheelsets move lengthwise on the
  // secondary and primary longitudinal suspension, and the wheelsets' spin speed is free, so
  // longitudinal creep forces pass through the suspension instead of into a constraint.
  std::vector<std::string> dof_names = {"x", "y", "z", "roll", "pitch", "yaw"};
  std::vector<std::string> defaults = {"y", "z", "roll", "pitch", "yaw"};
  if (kind == BodyKind::bogie_frame) defaults = {"x", "y", "z", "roll", "pitch", "yaw"};
  if (kind == BodyKind::wheelset) {
    out.rolling_radius = b.number("nominal_rolling_radius");
    out.flange_back_distance = b.number_or("flange_back_distance", out.flange_back_distance);
    dof_names = {"x", "y", "z", "roll", "yaw", "spin", "spin_perturbation"};
    defaults = {"x", "y", "z", "roll", "yaw", "spin"};
  } else {
    // Above top of rail: a centre of mass at or below the rails is a sign slip.
    out.cg_height = positive(b, "cg_height", "m (above top of rail)");
  }
  const auto dofs = b.string_list_or("dofs", defaults);
  for (const auto& d : dofs) {
    if (std::find(dof_names.begin(), dof_names.end(), d) == dof_names.end()) {
      const std::string near = nearest_key(d, {dof_names.begin(), dof_names.end()});
      b.fail("dofs", fmt::format("unknown degree of freedom '{}'{}; allowed: {}", d,
                                 near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near),
                                 fmt::join(dof_names, ", ")));
    }
    if (d == "spin" || d == "spin_perturbation") {
      out.spin = true;
    } else {
      out.active[static_cast<int>(dof_from_name(d))] = true;
    }
  }
  b.finish();
  // The limits are RigidBodySpec::validate()'s, placed at the key they name.
  detail::located(
      b, [&] { make_body(b.path(), kind, out, Eigen::Vector3d::Zero()).validate(b.path()); },
      b.path());
  return out;
}


// Force at rest on the lower body of an element preloaded in compression by `force` along
// `axis` (pushing the bodies apart).
Eigen::Vector3d compressive_preload(const Eigen::Vector3d& upper_abs,
                                    const Eigen::Vector3d& lower_abs, int axis, double force) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  const double d0 = upper_abs[axis] - lower_abs[axis];
  f[axis] = -force * (d0 > 0.0 ? 1.0 : -1.0);
  return f;
}

struct Pair {
  int upper = -1, lower = -1;
};

// One explicit element between `pair`, written for a lower body ahead of the upper body's
// centre; mirrored fore-aft (x of the upper point negated) when the lower body is behind.
SuspensionElementSpec read_element(MapReader e, const VehicleConfig& v, Pair pair,
                                   const std::string& prefix) {
  SuspensionElementSpec s;
  s.name = prefix + e.string("name");
  const std::string type = e.string("type", {"axis_spring", "axis_damper", "vector_damper",
                                             "spring_damper", "series_damper", "bump_stop",
                                             "torsion"});
  s.body_a = pair.upper;
  s.body_b = pair.lower;
  const auto& up = v.bodies[static_cast<std::size_t>(pair.upper)];
  const auto& lo = v.bodies[static_cast<std::size_t>(pair.lower)];
  s.point_a = detail::vector3(e, "upper");
  s.point_b = detail::vector3(e, "lower");
  if (lo.position.x() < up.position.x()) s.point_a.x() = -s.point_a.x();
  const Eigen::Vector3d upper_abs = up.position + s.point_a;
  const Eigen::Vector3d lower_abs = lo.position + s.point_b;
  auto axis_of = [&](const std::vector<std::string>& allowed) {
    return e.string("axis", allowed);
  };
  if (type == "axis_spring" || type == "axis_damper") {
    s.type = ElementType::spring_damper;
    const int axis = static_cast<int>(dof_from_name(axis_of(kAxes)));
    if (type == "axis_spring") {
      s.stiffness[axis] = non_negative(e, "k", "N/m");
      const double preload = e.number_or("preload", 0.0);
      if (preload != 0.0) {
        if (upper_abs[axis] == lower_abs[axis])
          e.fail("preload", "a preload needs the two points apart along the element's axis");
        s.preload = compressive_preload(upper_abs, lower_abs, axis, preload);
      }
    } else {
      s.damping[axis] = non_negative(e, "c", "N s/m");
    }
  } else if (type == "vector_damper") {
    // Acts along the line between its points; at rest that line must lie along one axis, so
    // to first order it is a damper along that axis.
    s.type = ElementType::spring_damper;
    const Eigen::Vector3d d = upper_abs - lower_abs;
    int axis = -1;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d across = d;
      across[i] = 0.0;
      if (across.norm() <= kAlignmentTolerance && d[i] != 0.0) axis = i;
    }
    if (axis < 0) {
      e.fail("upper", fmt::format("a vector_damper must lie along x, y or z at rest; its points "
                                  "are {:.4g}, {:.4g}, {:.4g} m apart",
                                  d.x(), d.y(), d.z()));
    }
    s.damping[axis] = non_negative(e, "c", "N s/m");
  } else if (type == "spring_damper") {
    s.type = ElementType::spring_damper;
    s.stiffness = axis_map(e.map_or_empty("stiffness"), "N/m");
    s.damping = axis_map(e.map_or_empty("damping"), "N s/m");
  } else if (type == "series_damper") {
    s.type = ElementType::series_damper;
    s.axis = dof_from_name(axis_of(kAxes));
    s.k = positive(e, "k", "N/m");
    s.c = positive(e, "c", "N s/m");
  } else if (type == "bump_stop") {
    s.type = ElementType::bump_stop;
    s.axis = dof_from_name(axis_of(kAxes));
    s.clearance = non_negative(e, "clearance", "m");
    s.table_displacement = detail::number_list(e, "displacement");
    s.table_force = detail::number_list(e, "force");
  } else {
    s.type = ElementType::torsion;
    s.axis = dof_from_name(axis_of(kRotationAxes));
    s.k = non_negative_or(e, "k", 0.0, "N m/rad");
    s.c = non_negative_or(e, "c", 0.0, "N m s/rad");
  }
  e.finish();
  return s;
}

void check_bump_stop_table(MapReader& r, const SuspensionElementSpec& s, const std::string& key) {
  const auto& d = s.table_displacement;
  const auto& f = s.table_force;
  if (d.size() < 2) r.fail(key, "the bump stop table needs at least two displacements");
  if (d.size() != f.size()) {
    r.fail("force", fmt::format("displacement and force need the same length, got {} and {}",
                            d.size(), f.size()));
  }
  for (std::size_t i = 1; i < d.size(); ++i) {
    if (!(d[i] > d[i - 1])) r.fail(key, fmt::format("displacement must increase (item {})", i));
  }
  if (d.front() < s.clearance) {
    r.fail(key, fmt::format("the table starts at {} m, inside the clearance {} m", d.front(),
                            s.clearance));
  }
}

}  // namespace

const std::vector<std::string>& wheel_rail_keys() {
  static const std::vector<std::string> keys = {
      "geometry",     "wheel_profile", "rail_profile",       "imported_table", "table_file", "table_yaw",
      "track_gauge",  "flange_back_distance", "flange_back_y", "rail_inclination", "conicity",
      "contact_half_distance", "conical_curvature_a", "conical_curvature_b", "friction", "shear_modulus", "poisson",
      "normal",       "tangential",    "tangential_options", "reduction",
      "reduction_table", "reduction_table_point", "regularisation_speed", "wheel_conical_tread",
      "hunt_crossley_alpha"};
  return keys;
}

void read_wheel_rail(MapReader& r, vehicle::WheelRailSpec& w) {
  w.geometry = r.string_or("geometry", w.geometry, {"table", "search", "imported", "conical"});
  if (r.has("wheel_profile")) w.wheel_profile = resolve(r, r.string("wheel_profile"));
  if (r.has("rail_profile")) w.rail_profile = resolve(r, r.string("rail_profile"));
  if (r.has("imported_table")) w.imported_table = resolve(r, r.string("imported_table"));
  if (r.has("table_file")) w.table_file = resolve(r, r.string("table_file"));
  for (const char* key : {"wheel_profile", "rail_profile", "imported_table"}) {
    r.allow(key);
    if (r.has(key)) {
      const std::string path = key == std::string("wheel_profile")  ? w.wheel_profile
                               : key == std::string("rail_profile") ? w.rail_profile
                                                                    : w.imported_table;
      if (!fs::exists(path)) r.fail(key, fmt::format("file does not exist (looked for {})", path));
    }
  }
  w.track_gauge = r.number_or("track_gauge", w.track_gauge);
  w.flange_back_distance = r.number_or("flange_back_distance", w.flange_back_distance);
  w.flange_back_y = r.number_or("flange_back_y", w.flange_back_y);
  w.rail_inclination = r.number_or("rail_inclination", w.rail_inclination);
  if (r.has("table_yaw")) {
    // The table's yaw axis, symmetric about 0 [rad].
    MapReader t = r.map("table_yaw");
    w.table_yaw_max = t.number("max");
    w.table_yaw_step = t.number("step");
    t.finish();
  } else {
    r.allow("table_yaw");
  }
  if (r.has("wheel_conical_tread")) {
    // The thesis' S1002 with a 1/10 conical tread: the tread beyond join_y becomes a cone.
    MapReader t = r.map("wheel_conical_tread");
    w.wheel_tread_conicity = t.number("conicity");
    w.wheel_tread_join_y = t.number("join_y");
    t.finish();
  } else {
    r.allow("wheel_conical_tread");
  }
  // Each value given must make sense, whichever geometry reads it.
  w.conicity = r.number_or("conicity", w.conicity);
  if (r.has("conicity") && !(w.conicity > 0.0 && w.conicity < 1.0))
    r.fail("conicity", fmt::format("must lie in (0, 1), got {}", w.conicity));
  const auto positive_if_given = [&](const char* key, double& field, const char* unit) {
    field = r.number_or(key, field);
    if (r.has(key) && !(field > 0.0))
      r.fail(key, fmt::format("must be > 0 {}, got {}", unit, field));
  };
  positive_if_given("contact_half_distance", w.contact_half_distance, "m");
  positive_if_given("conical_curvature_a", w.conical_curvature_a, "1/m");
  positive_if_given("conical_curvature_b", w.conical_curvature_b, "1/m");
  w.friction = r.number_or("friction", w.friction);
  w.shear_modulus = r.number_or("shear_modulus", w.shear_modulus);
  w.poisson = r.number_or("poisson", w.poisson);
  w.normal_model = r.string_or("normal", w.normal_model, {"hertz", "semi_hertz"});
  w.tangential_model = r.string_or("tangential", w.tangential_model,
                                   contact::tangential_model_names());
  if (r.has("tangential_options")) {
    MapReader o = r.map("tangential_options");
    w.tangential_options.clear();
    for (const auto& kv : o.yaml()) {
      const std::string key = kv.first.as<std::string>();
      if (!kv.second.IsScalar()) o.fail(key, "expected a single value");
      std::string value = kv.second.Scalar();
      if (key == "table") value = resolve(o, value);
      w.tangential_options[key] = value;
      o.allow(key);
    }
    o.finish();
  }
  // The model and its options must be accepted by the contact layer.
  if (r.has("tangential") || r.has("tangential_options")) {
    const std::string where = r.has("tangential_options") ? "tangential_options" : "tangential";
    try {
      (void)contact::make_tangential_model(w.tangential_model, w.tangential_options);
    } catch (const std::exception& e) {
      r.fail(where, e.what());
    }
  }
  if (r.has("reduction")) {
    MapReader k = r.map("reduction");
    const std::pair<const char*, double*> factors[] = {{"k11", &w.reduction.k11},
                                                       {"k22", &w.reduction.k22},
                                                       {"k23", &w.reduction.k23},
                                                       {"k33", &w.reduction.k33}};
    for (const auto& [name, value] : factors) *value = k.number_or(name, 1.0);
    k.finish();
  } else {
    r.allow("reduction");
  }
  if (r.has("reduction_table")) {
    w.reduction_table = resolve(r, r.string("reduction_table"));
    if (!fs::exists(w.reduction_table))
      r.fail("reduction_table", fmt::format("file does not exist (looked for {})", w.reduction_table));
  } else {
    r.allow("reduction_table");
  }
  if (r.has("reduction_table_point")) {
    MapReader o = r.map("reduction_table_point");
    w.reduction_table_point.clear();
    for (const auto& kv : o.yaml()) {
      const std::string key = kv.first.as<std::string>();
      w.reduction_table_point[key] = o.number(key);
    }
    o.finish();
  } else {
    r.allow("reduction_table_point");
  }
  w.regularisation_speed = r.number_or("regularisation_speed", w.regularisation_speed);
  w.hunt_crossley_alpha = r.number_or("hunt_crossley_alpha", w.hunt_crossley_alpha);
}

void check_wheel_rail(const MapReader& r, const vehicle::WheelRailSpec& w) {
  // The limits are WheelRailSpec::validate()'s; its error is placed at the key it names.
  detail::located(r, [&] { w.validate("wheel_rail"); }, "wheel_rail");
}

int body_index(const VehicleConfig& config, const std::string& name) {
  for (std::size_t i = 0; i < config.bodies.size(); ++i)
    if (config.bodies[i].name == name) return static_cast<int>(i);
  return -1;
}

namespace {

// Body indices of the expanded vehicle: car body, bogies front first, wheelsets front first.
constexpr int kCar = 0;
constexpr int kBogie[2] = {1, 2};
constexpr int wheelset_index(int b, int w) {
  return 3 + 2 * b + w;
}

// Primary suspension: bogie frame (upper) - wheelset (lower).
void read_primary(MapReader& r, MapReader& g, VehicleConfig& v, const BodyBlock& car,
                  const BodyBlock& bogie) {
  MapReader p = r.map("primary_suspension");
  const bool compact = p.has("stiffness") || p.has("damping");
  const auto explicit_items = detail::map_list(p, "elements", "a suspension element");
  if (!compact && explicit_items.empty()) {
    p.fail("stiffness", "give per-axlebox stiffness/damping or an elements list");
  }
  if (compact) {
    const Eigen::Vector3d k = axis_map(p.map_or_empty("stiffness"), "N/m");
    const Eigen::Vector3d c = axis_map(p.map_or_empty("damping"), "N s/m");
    const double semi = positive(g, "primary_lateral_semi_spacing", "m");
    const bool preload = p.boolean_or("static_preload", false);
    // Weight carried by each axlebox spring: car body and bogie frames over 8 axleboxes.
    const double axlebox_load = (car.mass + 2.0 * bogie.mass) * v.gravity / 8.0;
    for (int b = 0; b < 2; ++b) {
      for (int w = 0; w < 2; ++w) {
        const auto& bo = v.bodies[static_cast<std::size_t>(kBogie[b])];
        const auto& ws = v.bodies[static_cast<std::size_t>(wheelset_index(b, w))];
        for (int side = 0; side < 2; ++side) {
          const double y = side == 0 ? semi : -semi;
          SuspensionElementSpec s;
          s.name = fmt::format("primary.{}.{}", ws.name, side == 0 ? "left" : "right");
          s.type = ElementType::spring_damper;
          s.body_a = kBogie[b];
          s.body_b = wheelset_index(b, w);
          s.point_a = {ws.position.x() - bo.position.x(), y, ws.position.z() - bo.position.z()};
          s.point_b = {0.0, y, 0.0};
          s.stiffness = k;
          s.damping = c;
          if (preload) s.preload = {0.0, 0.0, -axlebox_load};
          v.elements.push_back(s);
        }
      }
    }
  } else {
    p.allow("static_preload");
  }
  for (int b = 0; b < 2; ++b) {
    for (int w = 0; w < 2; ++w) {
      for (const auto& item : explicit_items) {
        const auto& ws = v.bodies[static_cast<std::size_t>(wheelset_index(b, w))];
        v.elements.push_back(read_element(item, v, {kBogie[b], wheelset_index(b, w)},
                                          fmt::format("primary.{}.", ws.name)));
      }
    }
  }
  p.finish();
}

// Secondary suspension: car body (upper) - bogie frame (lower).
void read_secondary(MapReader& r, MapReader& g, VehicleConfig& v, const BodyBlock& car) {
  MapReader s2 = r.map("secondary_suspension");
  const bool compact = s2.has("stiffness") || s2.has("damping");
  const auto explicit_items = detail::map_list(s2, "elements", "a suspension element");
  if (!compact && explicit_items.empty()) {
    s2.fail("stiffness", "give per-side stiffness/damping or an elements list");
  }
  const auto& cb = v.bodies[kCar];
  if (compact) {
    const Eigen::Vector3d k = axis_map(s2.map_or_empty("stiffness"), "N/m");
    const Eigen::Vector3d c = axis_map(s2.map_or_empty("damping"), "N s/m");
    const double semi = positive(g, "secondary_lateral_semi_spacing", "m");
    const double height = positive(g, "secondary_height", "m (above top of rail)");
    const bool preload = s2.boolean_or("static_preload", false);
    const double side_load = car.mass * v.gravity / 4.0;
    for (int b = 0; b < 2; ++b) {
      const auto& bo = v.bodies[static_cast<std::size_t>(kBogie[b])];
      for (int side = 0; side < 2; ++side) {
        const double y = side == 0 ? semi : -semi;
        SuspensionElementSpec s;
        s.name = fmt::format("secondary.{}.{}", bo.name, side == 0 ? "left" : "right");
        s.type = ElementType::spring_damper;
        s.body_a = kCar;
        s.body_b = kBogie[b];
        s.point_a = {bo.position.x() - cb.position.x(), y, height - cb.position.z()};
        s.point_b = {0.0, y, height - bo.position.z()};
        s.stiffness = k;
        s.damping = c;
        if (preload) s.preload = {0.0, 0.0, -side_load};
        v.elements.push_back(s);
      }
    }
  } else {
    s2.allow("static_preload");
  }
  // Bogie yaw stiffness (per side: both sides in one torsion element per bogie, factor 2) and
  // the anti-roll bar (per bogie): torsion elements between the car body and each bogie.
  const auto add_torsion = [&](const char* key, const char* element, Dof axis,
                               double per_bogie_factor) {
    if (!s2.has(key)) {
      s2.allow(key);
      return;
    }
    const double k = positive(s2, key, "N m/rad");
    for (int b = 0; b < 2; ++b) {
      const auto& bo = v.bodies[static_cast<std::size_t>(kBogie[b])];
      SuspensionElementSpec s;
      s.name = fmt::format("secondary.{}.{}", bo.name, element);
      s.type = ElementType::torsion;
      s.axis = axis;
      s.body_a = kCar;
      s.body_b = kBogie[b];
      s.point_a = bo.position - cb.position;
      s.k = per_bogie_factor * k;
      v.elements.push_back(s);
    }
  };
  add_torsion("bogie_yaw_stiffness", "yaw_stiffness", Dof::yaw, 2.0);
  add_torsion("anti_roll_bar", "anti_roll_bar", Dof::roll, 1.0);
  if (s2.has("lateral_bump_stop")) {
    MapReader bs = s2.map("lateral_bump_stop");
    SuspensionElementSpec proto;
    proto.type = ElementType::bump_stop;
    proto.axis = Dof::y;
    proto.clearance = non_negative(bs, "clearance", "m");
    const double height = bs.number("height");
    proto.table_displacement = detail::number_list(bs, "displacement");
    proto.table_force = detail::number_list(bs, "force");
    check_bump_stop_table(bs, proto, "displacement");
    bs.finish();
    for (int b = 0; b < 2; ++b) {
      const auto& bo = v.bodies[static_cast<std::size_t>(kBogie[b])];
      SuspensionElementSpec s = proto;
      s.name = fmt::format("secondary.{}.lateral_bump_stop", bo.name);
      s.body_a = kCar;
      s.body_b = kBogie[b];
      s.point_a = {bo.position.x() - cb.position.x(), 0.0, height - cb.position.z()};
      s.point_b = {0.0, 0.0, height - bo.position.z()};
      v.elements.push_back(s);
    }
  } else {
    s2.allow("lateral_bump_stop");
  }
  for (int b = 0; b < 2; ++b) {
    for (const auto& item : explicit_items) {
      const auto& bo = v.bodies[static_cast<std::size_t>(kBogie[b])];
      v.elements.push_back(
          read_element(item, v, {kCar, kBogie[b]}, fmt::format("secondary.{}.", bo.name)));
    }
  }
  s2.finish();
}

}  // namespace

const std::vector<std::string>& vehicle_categories() {
  static const std::vector<std::string> k{"coach", "locomotive", "power_car", "wagon"};
  return k;
}

VehicleConfig read_vehicle(MapReader& r, std::string* category) {
  VehicleConfig v;
  v.name = r.string_or("name", fs::path(r.file()).stem().string());
  const std::string cat = r.string_or("category", "", vehicle_categories());
  if (category != nullptr) *category = cat;
  r.allow("schema_version");
  r.allow("description");
  v.gravity = r.number_or("gravity", kStandardGravity);
  if (!(v.gravity > 0.0) || !std::isfinite(v.gravity))
    r.fail("gravity", fmt::format("must be a finite number > 0 m/s^2, got {}", v.gravity));

  const BodyBlock car = read_body(r.map("car_body"), BodyKind::car_body);
  const BodyBlock bogie = read_body(r.map("bogie_frame"), BodyKind::bogie_frame);
  const BodyBlock wheelset = read_body(r.map("wheelset"), BodyKind::wheelset);

  MapReader g = r.map("geometry");
  const double bogie_spacing = positive(g, "bogie_centre_spacing", "m");
  const double wheelbase = positive(g, "wheelbase", "m");
  v.wheel_rail.track_gauge = g.number_or("track_gauge", v.wheel_rail.track_gauge);
  if (!std::isnan(wheelset.flange_back_distance))
    v.wheel_rail.flange_back_distance = wheelset.flange_back_distance;
  v.wheel_rail.nominal_radius = wheelset.rolling_radius;

  // Bodies: car body at the vehicle reference point, bogies and wheelsets front first.
  v.bodies.push_back(
      make_body("car_body", BodyKind::car_body, car, {0.0, 0.0, car.cg_height}));
  const double bogie_x[2] = {0.5 * bogie_spacing, -0.5 * bogie_spacing};
  for (int b = 0; b < 2; ++b) {
    v.bodies.push_back(make_body(fmt::format("bogie_{}", b + 1), BodyKind::bogie_frame, bogie,
                                 {bogie_x[b], 0.0, bogie.cg_height}));
  }
  for (int b = 0; b < 2; ++b) {
    for (int w = 0; w < 2; ++w) {
      const double x = bogie_x[b] + (w == 0 ? 0.5 : -0.5) * wheelbase;
      v.bodies.push_back(make_body(fmt::format("wheelset_{}", 2 * b + w + 1), BodyKind::wheelset,
                                   wheelset, {x, 0.0, wheelset.rolling_radius}));
    }
  }

  read_primary(r, g, v, car, bogie);
  read_secondary(r, g, v, car);
  // Explicit bump stops: check their tables.
  for (const auto& e : v.elements) {
    if (e.type == ElementType::bump_stop && e.table_displacement.size() < 2) {
      r.fail("secondary_suspension", fmt::format("{}: bump stop without a force table", e.name));
    }
  }
  g.finish();

  {
    MapReader w = r.map("wheel_rail");
    read_wheel_rail(w, v.wheel_rail);
    w.finish();
    check_wheel_rail(w, v.wheel_rail);
  }
  r.finish();
  return v;
}

VehicleConfig load_vehicle_file(const std::string& path, std::string* category) {
  return read_vehicle_file(load_yaml_file(path), category);
}

VehicleConfig read_vehicle_file(const YamlFile& file, std::string* category) {
  MapReader r(file.root, file.path, "");
  const long version = r.integer_or("schema_version", -1);
  if (version != kVehicleSchemaVersion) {
    r.fail("schema_version", fmt::format("required in a vehicle file; supported: {}, got {}",
                                         kVehicleSchemaVersion, version));
  }
  return read_vehicle(r, category);
}

}  // namespace ferro::scenarios
