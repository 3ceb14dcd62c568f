#include "model_errors.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ferro/scenarios/scene.hpp"
#include "ferro/scenarios/yaml_reader.hpp"

namespace ferro::scenarios::detail {
namespace {

namespace fs = std::filesystem;

// One YAML mapping that may hold the key: its file and node.
struct Place {
  std::string file;
  YAML::Node node;
  std::string prefix;  // key path of `node` in messages ("" at a file's top)
};

// The node at `path` ("a.b.c") under `node`, if every part exists. Read through const nodes
// and copies only: assigning a yaml-cpp node would rebind the tree it came from.
std::optional<YAML::Node> find(const YAML::Node& node, const std::string& path) {
  if (!node.IsMap()) return std::nullopt;
  const auto dot = path.find('.');
  const YAML::Node child = node[path.substr(0, dot)];
  if (!child.IsDefined()) return std::nullopt;
  if (dot == std::string::npos) return child;
  return find(child, path.substr(dot + 1));
}

// The scene's files as YAML: the scene, its contact and track parts (inline or included), the
// vehicle file.
struct SceneFiles {
  std::vector<Place> contact;  // where wheel_rail values may be set, latest first
  std::optional<Place> track, output, model, simulation, vehicle;

  explicit SceneFiles(const Scene& scene) {
    const YamlFile top = load_yaml_file(scene.path);
    const auto part = [&](const std::string& key) -> std::optional<Place> {
      if (!top.root[key].IsDefined()) return std::nullopt;
      if (top.root[key].IsScalar()) {
        const std::string file =
            (fs::path(scene.path).parent_path() / top.root[key].Scalar()).lexically_normal().string();
        return Place{file, load_yaml_file(file).root, key};
      }
      return Place{scene.path, top.root[key], key};
    };
    track = part("track");
    output = part("output");
    model = part("model");
    simulation = part("simulation");
    if (auto c = part("contact")) contact.push_back(*c);
    if (track) contact.push_back(*track);  // gauge, rail_inclination
    if (!scene.model.vehicle_file.empty()) {
      const YamlFile v = load_yaml_file(scene.model.vehicle_file);
      vehicle = Place{scene.model.vehicle_file, v.root, ""};
    } else if (model && std::as_const(model->node)["vehicle"].IsMap()) {
      vehicle = Place{model->file, std::as_const(model->node)["vehicle"], model->prefix + ".vehicle"};
    }
  }

  // The first place among `candidates` ({place, key path}) that sets the key.
  static std::optional<std::pair<Place, std::string>> first(
      const std::vector<std::pair<std::optional<Place>, std::string>>& candidates) {
    for (const auto& [place, key] : candidates) {
      if (place && find(place->node, key)) return std::pair{*place, key};
    }
    return std::nullopt;
  }
};

[[noreturn]] void fail_at(const Place& place, const std::string& key, const std::string& message) {
  const auto node = find(place.node, key);
  const auto [line, column] = position_of(node ? *node : place.node);
  throw YamlInputError(place.file, line, column,
                       place.prefix.empty() ? key : place.prefix + "." + key, message);
}

bool contains(const std::string& text, const std::string& word) {
  return !word.empty() && text.find(word) != std::string::npos;
}

}  // namespace

void rethrow_located(const Scene& scene, const std::exception_ptr& error) {
  std::string message;
  try {
    std::rethrow_exception(error);
  } catch (const YamlInputError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    message = e.what();
  }
  const SceneFiles files(scene);
  // Where a wheel_rail value may come from, latest first: the scene's contact part (and its track
  // part for gauge and inclination), then the vehicle file.
  const auto wheel_rail_key = [&](const std::vector<std::string>& vehicle_keys,
                                  const std::string& scene_key) {
    std::vector<std::pair<std::optional<Place>, std::string>> c;
    for (const auto& p : files.contact) c.emplace_back(p, scene_key);
    for (const auto& k : vehicle_keys) c.emplace_back(files.vehicle, k);
    return SceneFiles::first(c);
  };
  const auto report = [&](const std::optional<std::pair<Place, std::string>>& at) {
    if (at) fail_at(at->first, at->second, message);
  };
  // The contact geometry's wheel-rail pair.
  const auto& wr = scene.model.vehicle.wheel_rail;
  // The gauge: the scene's contact part, then its track part, then the vehicle file.
  const auto gauge_key = [&] {
    std::vector<std::pair<std::optional<Place>, std::string>> c;
    for (const auto& p : files.contact) c.emplace_back(p, "track_gauge");
    c.emplace_back(files.track, "gauge");
    c.emplace_back(files.vehicle, "wheel_rail.track_gauge");
    c.emplace_back(files.vehicle, "geometry.track_gauge");
    return SceneFiles::first(c);
  };
  if (contains(message, "WheelRailPairParams.flange_back_distance")) {
    // Out of (0.5 m, track_gauge): the distance itself, or a gauge narrower than it. A nominal
    // gauge of the world's railways (1000 to 1668 mm) is taken as meant, another one as the
    // slip.
    const bool nominal_gauge = [&] {
      for (const double g : {1.000, 1.067, 1.435, 1.520, 1.524, 1.600, 1.668})
        if (std::abs(wr.track_gauge - g) < 1e-3) return true;
      return false;
    }();
    if (wr.flange_back_distance > 0.5 && !nominal_gauge) report(gauge_key());
    report(wheel_rail_key({"wheel_rail.flange_back_distance", "wheelset.flange_back_distance"},
                          "flange_back_distance"));
  }
  if (contains(message, "WheelRailPairParams.track_gauge")) report(gauge_key());
  if (contains(message, "WheelRailPairParams.nominal_radius"))
    report(SceneFiles::first({{files.vehicle, "wheelset.nominal_rolling_radius"}}));
  if (contains(message, "WheelRailPairParams.rail_inclination")) {
    report(wheel_rail_key({"wheel_rail.rail_inclination"}, "rail_inclination"));
    report(SceneFiles::first({{files.track, "rail_inclination"}}));
  }
  if (contains(message, "WheelRailPairParams.flange_back_y"))
    report(wheel_rail_key({"wheel_rail.flange_back_y"}, "flange_back_y"));
  if (contains(message, "splice_conical_tread")) {
    report(wheel_rail_key({"wheel_rail.wheel_conical_tread.join_y"},
                          "wheel_conical_tread.join_y"));
  }
  // A file named in the scene that could not be read: the key naming it.
  const auto& w = wr;
  const std::vector<std::tuple<std::string, std::string, std::string>> named = {
      {w.wheel_profile, "wheel_rail.wheel_profile", "wheel_profile"},
      {w.rail_profile, "wheel_rail.rail_profile", "rail_profile"},
      {w.imported_table, "wheel_rail.imported_table", "imported_table"},
      {w.table_file, "wheel_rail.table_file", "table_file"},
  };
  if (contains(message, "K_ij table") && !w.reduction_table_point.empty())
    report(wheel_rail_key({"wheel_rail.reduction_table_point"}, "reduction_table_point"));
  if (contains(message, "reduction_table"))
    report(wheel_rail_key({"wheel_rail.reduction_table"}, "reduction_table"));
  for (const auto& [path, vehicle_key, scene_key] : named) {
    if (path.empty()) continue;
    const std::string shown = fs::path(path).lexically_normal().string();
    if (contains(message, shown + ":") || contains(message, "'" + shown + "'"))
      report(wheel_rail_key({vehicle_key}, scene_key));
  }
  for (std::size_t i = 0; i < scene.track.irregularities.size(); ++i) {
    const std::string& file = scene.track.irregularities[i].measured_file;
    if (!file.empty() && contains(message, fs::path(file).lexically_normal().string() + ":") &&
        files.track) {
      const YAML::Node& track_node = files.track->node;
      const YAML::Node items = track_node["irregularities"];
      if (items.IsSequence() && i < items.size()) {
        fail_at(Place{files.track->file, items[i], files.track->prefix + fmt::format(
                                                                              ".irregularities[{}]", i)},
                "file", message);
      }
    }
  }
  // Values the model checks itself.
  if (message.rfind("gravity:", 0) == 0) report(SceneFiles::first({{files.vehicle, "gravity"}}));
  if (message.rfind("selection.frozen", 0) == 0) report(SceneFiles::first({{files.model, "frozen"}}));
  if (message.rfind("output.plots", 0) == 0) report(SceneFiles::first({{files.output, "plots"}}));
  if (message.rfind("output.csv", 0) == 0) report(SceneFiles::first({{files.output, "csv"}}));
  // Nothing more precise: the scene's model key.
  if (files.model) fail_at(*files.model, "type", message);
  throw YamlInputError(scene.path, 0, 0, "model", message);
}

}  // namespace ferro::scenarios::detail
