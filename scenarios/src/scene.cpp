#include "ferro/scenarios/scene.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/run.hpp"
#include "ferro/scenarios/sensors.hpp"
#include "ferro/scenarios/vehicle_file.hpp"
#include "ferro/scenarios/yaml_reader.hpp"
#include "located.hpp"
#include "yaml_values.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;

// The files a scene reads beside its own (kept alive while it is read), and the values given by
// key in place of theirs.
struct Parts {
  std::vector<YamlFile> files;
  std::vector<KeyOverride> overrides;
  std::vector<bool> applied;  // per override
};

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    parts.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

// Sets the overrides under `prefix` (the key path of `root` in the scene; "" for the scene's
// own root). A path that meets a file name stops there: that file takes it when it is read.
void apply_overrides(YAML::Node root, Parts& parts, const std::string& prefix,
                     const std::string& file) {
  for (std::size_t k = 0; k < parts.overrides.size(); ++k) {
    const KeyOverride& o = parts.overrides[k];
    if (!prefix.empty() && o.key.rfind(prefix + ".", 0) != 0) continue;
    const auto keys = split_key(prefix.empty() ? o.key : o.key.substr(prefix.size() + 1));
    YAML::Node node = root;
    bool reaches = true;
    for (std::size_t i = 0; i + 1 < keys.size() && reaches; ++i) {
      if (node[keys[i]].IsScalar()) {
        reaches = false;  // a file name (or a value: reported once reading is done)
      } else {
        if (!node[keys[i]].IsMap()) node[keys[i]] = YAML::Node(YAML::NodeType::Map);
        node.reset(node[keys[i]]);
      }
    }
    if (!reaches) continue;
    try {
      node[keys.back()] = YAML::Load(o.value);
    } catch (const YAML::Exception& e) {
      throw YamlInputError(file, 0, 0, o.key,
                           fmt::format("override value '{}' is not YAML: {}", o.value, e.msg));
    }
    parts.applied[k] = true;
  }
}

template <class F>
void validated(const MapReader& reader, F&& check) {
  detail::located(reader, std::forward<F>(check));
}

// A part is either written inline (a mapping) or named by a file relative to the scene. An
// included file carries its own schema_version; its text is appended to the scene's text.
MapReader open_part(MapReader& scene, const std::string& key, Scene& out, Parts& parts) {
  if (scene.has(key) && scene.yaml()[key].IsScalar()) {
    const YAML::Node ref = scene.node(key);
    const fs::path base = fs::path(scene.file()).parent_path();
    const std::string file = (base / ref.Scalar()).string();
    std::error_code ec;
    const fs::file_status st = fs::status(file, ec);
    if (!fs::exists(st)) {
      scene.fail(key, fmt::format("included file '{}' does not exist (looked for {}{})",
                                  ref.Scalar(), file, ec ? ": " + ec.message() : std::string()));
    }
    if (fs::is_directory(st)) {
      scene.fail(key, fmt::format("included file '{}' is a directory (looked for {}); name a "
                                  "YAML file",
                                  ref.Scalar(), file));
    }
    parts.files.push_back(load_yaml_file(file));
    apply_overrides(parts.files.back().root, parts, key, file);
    out.text += fmt::format("\n# ---- included: {} ----\n{}", file, parts.files.back().text);
    MapReader part(parts.files.back().root, file, key);
    const long version = part.integer_or("schema_version", -1);
    if (version != kSceneSchemaVersion) {
      part.fail("schema_version",
                fmt::format("required in every included file; supported: {}, got {}",
                            kSceneSchemaVersion, version));
    }
    return part;
  }
  return scene.map(key);
}

void read_material(MapReader r, contact::Material& m) {
  m.shear_modulus = r.number_or("shear_modulus", m.shear_modulus);
  m.poisson = r.number_or("poisson", m.poisson);
  r.finish();
}

// Track margin beyond the outermost wheelsets, for the contact look-up around them [m].
constexpr double kTrackMargin = 1.0;

// The `vehicle` model: a vehicle file (or inline description) and what of it to model.
void read_vehicle_model(MapReader& m, Scene& scene, Parts& parts) {
  auto& model = scene.model;
  if (m.has("vehicle") && m.yaml()["vehicle"].IsScalar()) {
    const std::string name = m.string("vehicle");
    const fs::path file = (fs::path(m.file()).parent_path() / name).lexically_normal();
    if (!fs::exists(file)) {
      m.fail("vehicle", fmt::format("vehicle file '{}' does not exist (looked for {})", name,
                                    file.string()));
    }
    model.vehicle_file = file.string();
    parts.files.push_back(load_yaml_file(model.vehicle_file));
    apply_overrides(parts.files.back().root, parts, m.key_path("vehicle"), model.vehicle_file);
    model.vehicle = read_vehicle_file(parts.files.back(), &model.category);
    scene.text += fmt::format("\n# ---- included: {} ----\n{}", model.vehicle_file,
                              parts.files.back().text);
  } else {
    MapReader v = m.map("vehicle");
    model.vehicle = read_vehicle(v, &model.category);
  }
  auto& sel = model.selection;
  sel.scope = m.string_or("scope", sel.scope, {"vehicle", "bogie", "wheelset"});
  const long index = m.integer_or("index", 0);
  const long count = sel.scope == "bogie" ? 2 : sel.scope == "wheelset" ? 4 : 1;
  if (index < 0 || index >= count) {
    m.fail("index", fmt::format("must lie in 0..{} for scope '{}' (0 = front), got {}", count - 1,
                                sel.scope, index));
  }
  sel.index = static_cast<int>(index);
  sel.frozen = m.string_list_or("frozen", {});
  const std::set<std::string> dofs(vehicle::kDofNames.begin(), vehicle::kDofNames.end());
  for (const auto& f : sel.frozen) {
    const auto dot = f.find('.');
    const std::string body = dot == std::string::npos ? "" : f.substr(0, dot);
    const std::string dof = dot == std::string::npos ? f : f.substr(dot + 1);
    if (!body.empty() && body_index(model.vehicle, body) < 0) {
      std::set<std::string> names;
      for (const auto& b : model.vehicle.bodies) names.insert(b.name);
      m.fail("frozen", fmt::format("unknown body '{}' in '{}'; bodies: {}", body, f,
                                   fmt::join(names, ", ")));
    }
    if (dof == "spin") {
      m.fail("frozen", fmt::format("'{}': the spin is not frozen here; a wheelset's spin "
                                   "perturbation is a state only when its `dofs` in the vehicle "
                                   "file list `spin` (leave it out there); allowed: x, y, z, roll, "
                                   "pitch, yaw (optionally as body.dof)",
                                   f));
    }
    if (dofs.count(dof) == 0) {
      m.fail("frozen", fmt::format("unknown degree of freedom '{}' in '{}'; allowed: x, y, z, "
                                   "roll, pitch, yaw (optionally as body.dof)",
                                   dof, f));
    }
  }
  m.finish();
}

// The output block's sensors and anti-alias filter of a vehicle scene.
void read_sensors(MapReader& o, Scene& scene) {
  auto& v = scene.output;
  v.anti_alias_frequency = o.number_or("anti_alias_frequency", v.anti_alias_frequency);
  if (!(v.anti_alias_frequency >= 0.0))
    o.fail("anti_alias_frequency", "must be >= 0 Hz (0: no anti-alias filters)");
  v.anti_alias_order = static_cast<int>(o.integer_or("anti_alias_order", v.anti_alias_order));
  v.contact_points = o.boolean_or("contact_points", v.contact_points);
  if (v.anti_alias_order < 2 || v.anti_alias_order > 8 || v.anti_alias_order % 2 != 0)
    o.fail("anti_alias_order", fmt::format("allowed 2, 4, 6, 8, got {}", v.anti_alias_order));

  v.floor_height = o.number_or("floor_height", v.floor_height, true);
  if (!std::isnan(v.floor_height) && !(v.floor_height > 0.0))
    o.fail("floor_height", "must be > 0 m above the top of rail");
  const auto& vehicle = scene.model.vehicle;
  const YAML::Node n = o.node("sensors");
  if (!n.IsDefined() || n.IsNull()) {
    v.sensors = default_sensors(vehicle, scene.model.selection, v.floor_height);
    return;
  }
  if (!n.IsSequence())
    detail::fail_at(o, n, "sensors",
                    "expected a list of standard positions (e.g. floor_front) or {name, body, "
                    "point: [x, y, z]} mappings");
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string key = fmt::format("sensors[{}]", i);
    if (n[i].IsScalar()) {
      try {
        const auto s = preset_sensors(vehicle, n[i].Scalar(), v.floor_height);
        v.sensors.insert(v.sensors.end(), s.begin(), s.end());
      } catch (const std::invalid_argument& e) {
        detail::fail_at(o, n[i], key, e.what());
      }
      continue;
    }
    if (!n[i].IsMap())
      detail::fail_at(o, n[i], key, "expected a standard position name or {name, body, point}");
    MapReader s(n[i], o.file(), o.key_path(key));
    vehicle::SensorSpec spec;
    spec.name = s.string("name");
    spec.body = s.string("body");
    if (body_index(vehicle, spec.body) < 0) {
      std::vector<std::string> names;
      for (const auto& b : vehicle.bodies) names.push_back(b.name);
      s.fail("body", fmt::format("no body '{}'; bodies: {}", spec.body, fmt::join(names, ", ")));
    }
    spec.point = detail::vector3(s, "point");
    const auto axes = s.string_list_or("filtered_axes", {"x", "y", "z"});
    spec.filtered_axes.clear();
    for (const auto& a : axes) {
      if (a != "x" && a != "y" && a != "z")
        s.fail("filtered_axes", fmt::format("'{}': allowed x, y, z", a));
      spec.filtered_axes += a;
    }
    s.finish();
    v.sensors.push_back(spec);
  }
  for (std::size_t i = 0; i < v.sensors.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (v.sensors[i].name == v.sensors[j].name)
        detail::fail_at(o, n, "sensors", fmt::format("sensor '{}' appears twice", v.sensors[i].name));
}

// The vehicle must stay on the designed track for the whole run.
void check_track_extent(const Scene& scene, MapReader& sim) {
  const auto& s = scene.simulation;
  const auto& d = scene.track.design;
  double back = 0.0;
  for (const auto& b : scene.model.vehicle.bodies) back = std::min(back, b.position.x());
  if (s.start_position + back - kTrackMargin < d.start_s) {
    sim.fail("start_position",
             fmt::format("the rear of the vehicle ({:.3f} m behind its centre) starts before the "
                         "track begins at s = {} m; start_position must be >= {:.3f} m",
                         -back, d.start_s, d.start_s - back + kTrackMargin));
  }
  if (const std::string problem = track_extent_problem(scene, s.t_end); !problem.empty()) {
    sim.fail(sim.has("t_end") ? "t_end" : "speed", problem);
  }
}

}  // namespace

YAML::Node scene_value(const YamlFile& scene_file, const std::string& key) {
  const auto keys = split_key(key);
  std::vector<YamlFile> files = {scene_file};  // the files the path runs through
  YAML::Node node = files.back().root;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (!node.IsMap()) return {};
    const YAML::Node& map = node;
    YAML::Node next = map[keys[i]];
    if (!next.IsDefined()) return {};
    if (next.IsScalar() && i + 1 < keys.size()) {  // a part or vehicle given by file name
      const fs::path folder = fs::path(files.back().path).parent_path();
      files.push_back(load_yaml_file((folder / next.Scalar()).string()));
      next.reset(files.back().root);
    }
    node.reset(next);
  }
  return node.IsDefined() ? YAML::Clone(node) : YAML::Node();
}

std::string track_extent_problem(const Scene& scene, double t_end) {
  if (scene.model.type != "vehicle" || scene.track.type != "design") return {};
  double front = 0.0;
  for (const auto& b : scene.model.vehicle.bodies) front = std::max(front, b.position.x());
  const auto& s = scene.simulation;
  double distance = s.speed * t_end + 0.5 * s.acceleration * t_end * t_end;
  if (s.acceleration < 0.0) {
    const double t_stop = s.speed / -s.acceleration;
    if (t_stop < t_end) distance = 0.5 * s.speed * t_stop;
  }
  const auto& d = scene.track.design;
  const double end = d.start_s + d.total_length();
  if (s.start_position + front + distance + kTrackMargin <= end) return {};
  return fmt::format("the vehicle runs off the track: it covers {:.1f} m in {} s from s = {} m "
                     "(front {:.3f} m ahead of its centre) but the track ends at s = {:.1f} m; "
                     "lengthen the track (track.length) or shorten the run",
                     distance, t_end, s.start_position, front, end);
}

namespace {

// The model part: a suspended wheelset inline, or a vehicle.
void read_model_part(MapReader& top, Scene& scene, Parts& included) {
  MapReader m = open_part(top, "model", scene, included);
  scene.model.type = m.string("type", {"suspended_wheelset", "vehicle"});
  if (scene.model.type == "vehicle") {
    read_vehicle_model(m, scene, included);
  } else {
    auto& w = scene.model.wheelset;
    w.mass = m.number("mass");
    w.yaw_inertia = m.number("yaw_inertia");
    w.half_gauge = m.number("half_gauge");
    w.rolling_radius = m.number("rolling_radius");
    w.conicity = m.number("conicity");
    w.primary_stiffness_x = m.number("primary_stiffness_x");
    w.primary_stiffness_y = m.number("primary_stiffness_y");
    w.primary_damping_x = m.number_or("primary_damping_x", 0.0);
    w.primary_damping_y = m.number_or("primary_damping_y", 0.0);
    w.primary_semi_spacing = m.number_or("primary_semi_spacing", w.primary_semi_spacing);
    m.finish();
    validated(m, [&] { w.validate(m.path()); });
  }
}

// The track part: a designed or measured track for a vehicle, straight for the wheelset.
void read_track_part(MapReader& top, Scene& scene, Parts& included) {
  MapReader t = open_part(top, "track", scene, included);
  if (scene.model.type == "vehicle") {
    scene.track = read_track(t);
    auto& wr = scene.model.vehicle.wheel_rail;
    if (!std::isnan(scene.track.gauge)) wr.track_gauge = scene.track.gauge;
    scene.track.design.gauge = wr.track_gauge;
    if (!std::isnan(scene.track.rail_inclination))
      wr.rail_inclination = scene.track.rail_inclination;
  } else {
    scene.track.type = t.string_or("type", "straight", {"straight"});
    t.finish();
  }
}

// The contact part: optional for a vehicle (its file's wheel_rail block holds the defaults).
void read_contact_part(MapReader& top, Scene& scene, Parts& included) {
  const bool vehicle_model = scene.model.type == "vehicle";
  if (vehicle_model) {
    // Optional: the vehicle file's wheel_rail block holds the defaults.
    if (top.has("contact")) {
      MapReader c = open_part(top, "contact", scene, included);
      read_wheel_rail(c, scene.model.vehicle.wheel_rail);
      c.finish();
      check_wheel_rail(c, scene.model.vehicle.wheel_rail);
    } else {
      top.allow("contact");
    }
  } else {
    MapReader c = open_part(top, "contact", scene, included);
    auto& cr = scene.contact.creep;
    (void)c.string_or("tangential", "kalker_linear", {"kalker_linear"});
    cr.semi_axis_a = c.number("semi_axis_a");
    cr.semi_axis_b = c.number("semi_axis_b");
    cr.coefficients = c.string_or("coefficients", cr.coefficients, {"kalker_table", "equal"});
    cr.reduction.k11 = c.number_or("k11", cr.reduction.k11);
    cr.reduction.k22 = c.number_or("k22", cr.reduction.k22);
    // Reduction factors (docs/SCENES.md): (0, 1], as for vehicles.
    for (const auto& [key, k] :
         {std::pair{"k11", cr.reduction.k11}, std::pair{"k22", cr.reduction.k22}}) {
      if (!(k > 0.0 && k <= 1.0)) c.fail(key, fmt::format("must lie in (0, 1], got {}", k));
    }
    read_material(c.map_or_empty("wheel"), cr.wheel);
    read_material(c.map_or_empty("rail"), cr.rail);
    c.finish();
    validated(c, [&] { cr.validate(c.path()); });
  }
}

// The simulation settings: speed, duration, initial state; the run must stay on the track.
void read_simulation(MapReader& top, Scene& scene) {
  const bool vehicle_model = scene.model.type == "vehicle";
  MapReader s = top.map("simulation");
  const bool kmh = s.has("speed_kmh");
  if (kmh && s.has("speed")) s.fail("speed_kmh", "give either speed [m/s] or speed_kmh, not both");
  scene.simulation.speed = kmh ? s.number("speed_kmh") / 3.6 : s.number("speed");
  if (!kmh)
    s.allow("speed_kmh");
  else
    s.allow("speed");
  const char* speed_key = kmh ? "speed_kmh" : "speed";
  if (vehicle_model) {
    if (!(scene.simulation.speed >= 0.0)) s.fail(speed_key, "must be >= 0");
    scene.simulation.acceleration = s.number_or("acceleration", 0.0);
    scene.simulation.start_position = s.number_or("start_position", 0.0);
  } else if (!(scene.simulation.speed > 0.0)) {
    s.fail(speed_key, "must be > 0");
  }
  scene.simulation.t_end = s.number("t_end");
  if (!(scene.simulation.t_end > 0.0))
    s.fail("t_end", fmt::format("must be > 0 s, got {}", scene.simulation.t_end));
  MapReader init = s.map_or_empty("initial");
  if (vehicle_model) {
    // State names are the model's; they are checked when the model is built.
    for (const auto& kv : init.yaml()) {
      const std::string name = kv.first.as<std::string>();
      scene.simulation.initial[name] = init.number(name);
      scene.simulation.initial_position[name] = position_of(kv.first);
    }
  } else {
    const auto states = state_names(scene.model);
    for (const auto& kv : init.yaml()) {
      const std::string name = kv.first.as<std::string>();
      if (std::find(states.begin(), states.end(), name) != states.end()) {
        scene.simulation.initial[name] = init.number(name);
      }
    }
    for (const auto& n : states) init.allow(n);
  }
  init.finish();
  if (vehicle_model && scene.track.type == "design") {
    check_track_extent(scene, s);
  } else {
    s.allow("acceleration");
    s.allow("start_position");
  }
  s.finish();
}

void read_solver_part(MapReader& top, Scene& scene, Parts& included) {
  MapReader r = open_part(top, "solver", scene, included);
  auto& v = scene.solver;
  v.method = r.string_or("integrator", v.method, vehicle::available_integrators());
  v.rtol = r.number_or("rtol", v.rtol);
  v.atol = r.number_or("atol", v.atol);
  v.max_step = r.number_or("max_step", v.max_step, /*allow_infinite=*/true);
  v.initial_step = r.number_or("initial_step", v.initial_step);
  v.linear_solver = r.string_or("linear_solver", v.linear_solver, {"dense", "band"});
  v.max_steps = r.integer_or("max_steps", v.max_steps);
  v.erk_order = static_cast<int>(r.integer_or("erk_order", v.erk_order));
  v.max_order = static_cast<int>(r.integer_or("max_order", v.max_order));
  v.stability_limit_detection =
      r.boolean_or("stability_limit_detection", v.stability_limit_detection);
  v.jacobian_max_steps = r.integer_or("jacobian_max_steps", v.jacobian_max_steps);
  v.fixed_step = r.number_or("fixed_step", v.fixed_step);
  r.finish();
  validated(r, [&] { v.validate(r.path()); });
}

// The output part: file, sampling, flushing, CSV and plotted signals.
void read_output_part(MapReader& top, Scene& scene, Parts& included) {
  const bool vehicle_model = scene.model.type == "vehicle";
  MapReader o = open_part(top, "output", scene, included);
  auto& v = scene.output;
  v.file = o.string_or("file", v.file);
  v.interval = o.number_or("interval", v.interval);
  if (!(v.interval > 0.0)) o.fail("interval", fmt::format("must be > 0 s, got {}", v.interval));
  validated(o, [&] { (void)output_sample_count(scene.simulation.t_end, v.interval, "interval"); });
  validated(o, [&] { check_output_on_steps(v.interval, scene.solver, "interval"); });
  v.flush_seconds = o.number_or("flush_seconds", v.flush_seconds);
  if (!(v.flush_seconds > 0.0))
    o.fail("flush_seconds", fmt::format("must be > 0 s, got {}", v.flush_seconds));
  v.csv = o.string_list_or("csv", {});
  v.plots = o.string_list_or("plots", {});
  if (vehicle_model) {
    read_sensors(o, scene);
  } else {
    for (const char* k : {"sensors", "anti_alias_frequency", "anti_alias_order", "floor_height",
                          "contact_points"})
      if (o.has(k)) o.fail(k, "applies to vehicle scenes (model.type vehicle) only");
  }
  o.finish();
  const auto names = vehicle_model ? std::vector<std::string>{} : signal_names(scene.model);
  auto check_names = [&](const std::vector<std::string>& list, const char* key) {
    for (const auto& n : list) {
      if (n == "all") continue;
      if (std::find(names.begin(), names.end(), n) == names.end()) {
        const std::string near = nearest_key(n, std::set<std::string>(names.begin(), names.end()));
        o.fail(key, fmt::format("unknown signal '{}'{}; signals of this model: all, {}", n,
                                near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near),
                                fmt::join(names, ", ")));
      }
    }
  };
  // A vehicle model's signal names are checked when the model is built.
  if (!vehicle_model) {
    check_names(v.csv, "csv");
    check_names(v.plots, "plots");
  }
}

void read_analysis(MapReader& top, Scene& scene) {
  MapReader a = top.map_or_empty("analysis");
  MapReader e = a.map_or_empty("eigen");
  scene.eigen.speed_min = e.number_or("speed_min", scene.eigen.speed_min);
  scene.eigen.speed_max = e.number_or("speed_max", scene.eigen.speed_max);
  scene.eigen.points = static_cast<int>(e.integer_or("points", scene.eigen.points));
  if (!(scene.eigen.speed_min > 0.0)) e.fail("speed_min", "must be > 0 m/s");
  if (!(scene.eigen.speed_max > scene.eigen.speed_min))
    e.fail("speed_max", "must exceed speed_min");
  if (scene.eigen.points < 2 || scene.eigen.points > kMaxEigenPoints)
    e.fail("points", fmt::format("must lie in 2..{}", kMaxEigenPoints));
  e.finish();
  MapReader as = a.map_or_empty("assessment");
  scene.assessment.twist_test = as.boolean_or("twist_test", scene.assessment.twist_test);
  as.finish();
  a.finish();
}

}  // namespace

namespace {

Scene read_scene(YamlFile file, Parts& included) {
  const std::string& path = file.path;
  Scene scene;
  apply_overrides(file.root, included, "", path);
  scene.path = path;
  scene.text = file.text;
  MapReader top(file.root, path, "");

  const long version = top.integer_or("schema_version", -1);
  if (!top.has("schema_version"))
    top.fail("schema_version",
             fmt::format("missing; this program reads schema_version {}", kSceneSchemaVersion));
  if (version != kSceneSchemaVersion) {
    top.fail("schema_version",
             fmt::format("unsupported version {}; supported: {}", version, kSceneSchemaVersion));
  }
  scene.name = top.string_or("name", fs::path(path).stem().string());
  scene.description = top.string_or("description", "");

  read_model_part(top, scene, included);
  read_track_part(top, scene, included);
  read_contact_part(top, scene, included);
  read_simulation(top, scene);
  read_solver_part(top, scene, included);
  read_output_part(top, scene, included);
  read_analysis(top, scene);
  top.finish();
  for (std::size_t k = 0; k < included.overrides.size(); ++k) {
    if (!included.applied[k]) {
      throw YamlInputError(path, 0, 0, included.overrides[k].key,
                           "cannot be set: the path runs into a value that is not a mapping");
    }
  }
  return scene;
}

// Reads the scene; an error at an overridden key is located at the override.
Scene read_scene_with(YamlFile file, const std::vector<KeyOverride>& overrides) {
  Parts parts;
  parts.overrides = overrides;
  parts.applied.assign(overrides.size(), false);
  const std::string path = file.path;
  try {
    return read_scene(std::move(file), parts);
  } catch (const YamlInputError& e) {
    throw at_override(e, path, overrides);
  }
}

}  // namespace

YamlInputError at_override(const YamlInputError& e, const std::string& scene_path,
                           const std::vector<KeyOverride>& overrides) {
  for (const KeyOverride& o : overrides) {
    const bool at = e.key() == o.key || e.key().rfind(o.key + ".", 0) == 0 ||
                    e.key().rfind(o.key + "[", 0) == 0;
    if (at && e.line() > 0)
      return YamlInputError(scene_path, 0, 0, e.key(), e.message() + " (given as an override)");
  }
  return e;
}

Scene load_scene(const std::string& path) { return load_scene(path, {}); }

Scene load_scene(const std::string& path, const std::vector<KeyOverride>& overrides) {
  return read_scene_with(load_yaml_file(path), overrides);
}

Scene load_scene_text(const std::string& text, const std::string& path,
                      const std::vector<KeyOverride>& overrides) {
  return read_scene_with(parse_yaml_text(text, path), overrides);
}

std::vector<std::string> scene_inputs(const Scene& scene) {
  std::vector<std::string> files = {scene.path};
  // Included files are marked in the scene text by load_scene.
  const std::string marker = "\n# ---- included: ";
  for (auto at = scene.text.find(marker); at != std::string::npos;
       at = scene.text.find(marker, at + 1)) {
    const auto begin = at + marker.size();
    const auto end = scene.text.find(" ----\n", begin);
    if (end != std::string::npos) files.push_back(scene.text.substr(begin, end - begin));
  }
  if (!scene.model.vehicle_file.empty()) files.push_back(scene.model.vehicle_file);
  const auto& w = scene.model.vehicle.wheel_rail;
  for (const std::string* f :
       {&w.wheel_profile, &w.rail_profile, &w.imported_table, &w.table_file, &w.reduction_table}) {
    if (!f->empty()) files.push_back(*f);
  }
  if (const auto table = w.tangential_options.find("table"); table != w.tangential_options.end())
    files.push_back(table->second);
  for (const auto& irregularity : scene.track.irregularities) {
    if (!irregularity.measured_file.empty()) files.push_back(irregularity.measured_file);
  }
  return files;
}

std::vector<std::string> scene_warnings(const Scene& scene) {
  std::vector<std::string> out;
  if (scene.model.type != "vehicle") return out;
  constexpr const char* kNoGauge =
      "does not move the rails in the vehicle model (the rails are placed at the design gauge, "
      "moved only by the irregularities and the track's elasticity): it has no effect on this run";
  const auto& sections = scene.track.design.sections;
  for (std::size_t i = 0; i < sections.size(); ++i) {
    if (sections[i].gauge_widening != 0.0) {
      out.push_back(fmt::format("track.sections[{}].gauge_widening: {} m of gauge widening {}", i,
                                sections[i].gauge_widening, kNoGauge));
    }
  }
  return out;
}

void override_tangential(Scene& scene, const std::string& name, const std::string& flag,
                         const contact::ModelOptions& options) {
  if (scene.model.type != "vehicle") {
    throw std::invalid_argument(fmt::format(
        "{}: only vehicle scenes choose a tangential model (this one is {})", flag,
        scene.model.type));
  }
  const auto names = contact::tangential_model_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    throw std::invalid_argument(fmt::format("{}: unknown tangential model '{}'; allowed: {}", flag,
                                            name, fmt::join(names, ", ")));
  }
  auto& w = scene.model.vehicle.wheel_rail;
  if (w.tangential_model != name) w.tangential_options.clear();
  w.tangential_options.insert(options.begin(), options.end());  // keeps the keys already set
  w.tangential_model = name;
  try {
    (void)contact::make_tangential_model(name, w.tangential_options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: {}", flag, e.what()));
  }
}

void override_normal(Scene& scene, const std::string& name, const std::string& flag) {
  if (scene.model.type != "vehicle") {
    throw std::invalid_argument(fmt::format(
        "{}: only vehicle scenes choose a normal contact model (this one is {})", flag,
        scene.model.type));
  }
  if (name != "hertz" && name != "semi_hertz") {
    throw std::invalid_argument(
        fmt::format("{}: unknown normal model '{}'; allowed: hertz, semi_hertz", flag, name));
  }
  auto& w = scene.model.vehicle.wheel_rail;
  if (name == "semi_hertz" && w.geometry != "table" && w.geometry != "search") {
    throw std::invalid_argument(fmt::format(
        "{}: semi_hertz reads the gap of the wheel and rail profiles, which geometry '{}' does "
        "not have; allowed with it: hertz (semi_hertz needs geometry table or search)",
        flag, w.geometry));
  }
  w.normal_model = name;
}

}  // namespace ferro::scenarios
