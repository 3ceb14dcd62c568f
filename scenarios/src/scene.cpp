#include "ferro/scenarios/scene.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <set>

#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/yaml_reader.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;

// Runs a struct's validate(); turns its "path.field: message" into an error at the field's
// line in the YAML.
template <class F>
void validated(const MapReader& reader, F&& check) {
  try {
    check();
  } catch (const YamlInputError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    const std::string prefix = reader.path() + ".";
    const auto colon = msg.find(": ");
    std::string field = colon == std::string::npos ? std::string() : msg.substr(0, colon);
    if (field.rfind(prefix, 0) == 0) field = field.substr(prefix.size());
    // Walk to the deepest node that exists for the line number.
    YAML::Node at = reader.yaml();
    std::size_t start = 0;
    while (!field.empty() && at.IsMap()) {
      const auto dot = field.find('.', start);
      const std::string part =
          field.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
      if (!at[part].IsDefined()) break;
      at = at[part];
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
    const auto [l, c] = position_of(at);
    throw YamlInputError(reader.file(), l, c,
                         field.empty() ? reader.path() : reader.key_path(field),
                         colon == std::string::npos ? msg : msg.substr(colon + 2));
  }
}

// A part is either written inline (a mapping) or named by a file relative to the scene. An
// included file carries its own schema_version; its text is appended to the scene's text.
MapReader open_part(MapReader& scene, const std::string& key, Scene& out,
                    std::vector<YamlFile>& keep) {
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
    keep.push_back(load_yaml_file(file));
    out.text += fmt::format("\n# ---- included: {} ----\n{}", file, keep.back().text);
    MapReader part(keep.back().root, file, key);
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

}  // namespace

Scene load_scene(const std::string& path) {
  Scene scene;
  const YamlFile file = load_yaml_file(path);
  std::vector<YamlFile> included;
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

  {  // model
    MapReader m = open_part(top, "model", scene, included);
    scene.model.type = m.string("type", {"suspended_wheelset"});
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
  {  // track
    MapReader t = open_part(top, "track", scene, included);
    scene.track.type = t.string_or("type", "straight", {"straight"});
    t.finish();
  }
  {  // contact
    MapReader c = open_part(top, "contact", scene, included);
    auto& cr = scene.contact.creep;
    c.string_or("tangential", "kalker_linear", {"kalker_linear"});
    cr.semi_axis_a = c.number("semi_axis_a");
    cr.semi_axis_b = c.number("semi_axis_b");
    cr.coefficients = c.string_or("coefficients", cr.coefficients, {"kalker_table", "equal"});
    cr.k11 = c.number_or("k11", cr.k11);
    cr.k22 = c.number_or("k22", cr.k22);
    read_material(c.map_or_empty("wheel"), cr.wheel);
    read_material(c.map_or_empty("rail"), cr.rail);
    c.finish();
    validated(c, [&] { cr.validate(c.path()); });
  }
  {  // simulation
    MapReader s = top.map("simulation");
    const bool kmh = s.has("speed_kmh");
    if (kmh && s.has("speed"))
      s.fail("speed_kmh", "give either speed [m/s] or speed_kmh, not both");
    scene.simulation.speed = kmh ? s.number("speed_kmh") / 3.6 : s.number("speed");
    if (!kmh)
      s.allow("speed_kmh");
    else
      s.allow("speed");
    if (!(scene.simulation.speed > 0.0)) s.fail(kmh ? "speed_kmh" : "speed", "must be > 0");
    scene.simulation.t_end = s.number("t_end");
    if (!(scene.simulation.t_end > 0.0))
      s.fail("t_end", fmt::format("must be > 0 s, got {}", scene.simulation.t_end));
    MapReader init = s.map_or_empty("initial");
    const auto states = state_names(scene.model);
    for (const auto& kv : init.yaml()) {
      const std::string name = kv.first.as<std::string>();
      if (std::find(states.begin(), states.end(), name) != states.end()) {
        scene.simulation.initial[name] = init.number(name);
      }
    }
    for (const auto& n : states) init.allow(n);
    init.finish();
    s.finish();
  }
  {  // solver
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
    r.finish();
    validated(r, [&] { v.validate(r.path()); });
  }
  {  // output
    MapReader o = open_part(top, "output", scene, included);
    auto& v = scene.output;
    v.file = o.string_or("file", v.file);
    v.interval = o.number_or("interval", v.interval);
    if (!(v.interval > 0.0)) o.fail("interval", fmt::format("must be > 0 s, got {}", v.interval));
    v.flush_seconds = o.number_or("flush_seconds", v.flush_seconds);
    if (!(v.flush_seconds > 0.0))
      o.fail("flush_seconds", fmt::format("must be > 0 s, got {}", v.flush_seconds));
    v.csv = o.string_list_or("csv", {});
    v.plots = o.string_list_or("plots", {});
    o.finish();
    const auto names = signal_names(scene.model);
    auto check_names = [&](const std::vector<std::string>& list, const char* key) {
      for (const auto& n : list) {
        if (n == "all") continue;
        if (std::find(names.begin(), names.end(), n) == names.end()) {
          const std::string near =
              nearest_key(n, std::set<std::string>(names.begin(), names.end()));
          o.fail(key, fmt::format("unknown signal '{}'{}; signals of this model: all, {}", n,
                                  near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near),
                                  fmt::join(names, ", ")));
        }
      }
    };
    check_names(v.csv, "csv");
    check_names(v.plots, "plots");
  }
  {  // analysis (optional)
    MapReader a = top.map_or_empty("analysis");
    MapReader e = a.map_or_empty("eigen");
    scene.eigen.speed_min = e.number_or("speed_min", scene.eigen.speed_min);
    scene.eigen.speed_max = e.number_or("speed_max", scene.eigen.speed_max);
    scene.eigen.points = static_cast<int>(e.integer_or("points", scene.eigen.points));
    if (!(scene.eigen.speed_min > 0.0)) e.fail("speed_min", "must be > 0 m/s");
    if (!(scene.eigen.speed_max > scene.eigen.speed_min))
      e.fail("speed_max", "must exceed speed_min");
    if (scene.eigen.points < 2 || scene.eigen.points > 100000)
      e.fail("points", "must lie in 2..100000");
    e.finish();
    a.finish();
  }
  top.finish();
  return scene;
}

}  // namespace ferro::scenarios
