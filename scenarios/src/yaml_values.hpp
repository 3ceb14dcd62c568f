#pragma once
// Lists, vectors and lists of mappings read through a MapReader, with errors located at the
// offending item. Private to the scene loaders.

#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "ferro/scenarios/yaml_reader.hpp"

namespace ferro::scenarios::detail {

[[noreturn]] inline void fail_at(const MapReader& r, const YAML::Node& at, const std::string& key,
                                 const std::string& message) {
  const auto [l, c] = position_of(at);
  throw YamlInputError(r.file(), l, c, r.key_path(key), message);
}

/// Optional list of finite numbers (empty when absent); allow_infinite also accepts .inf.
[[nodiscard]] inline std::vector<double> number_list(MapReader& r, const std::string& key,
                                                     bool allow_infinite = false) {
  const YAML::Node n = r.node(key);
  std::vector<double> out;
  if (!n.IsDefined() || n.IsNull()) return out;
  if (!n.IsSequence()) fail_at(r, n, key, "expected a list of numbers, e.g. [0.0, 1.0]");
  for (std::size_t i = 0; i < n.size(); ++i) {
    double v = 0.0;
    if (!n[i].IsScalar() || !YAML::convert<double>::decode(n[i], v) || std::isnan(v) ||
        (!allow_infinite && std::isinf(v))) {
      fail_at(r, n[i], fmt::format("{}[{}]", key, i),
              allow_infinite ? "expected a number (.inf allowed)" : "expected a finite number");
    }
    out.push_back(v);
  }
  return out;
}

/// Required [x, y, z] vector [m].
[[nodiscard]] inline Eigen::Vector3d vector3(MapReader& r, const std::string& key) {
  if (!r.has(key)) {
    (void)r.number(key);  // raises the located "missing required key" error
  }
  const YAML::Node n = r.yaml()[key];
  const auto v = number_list(r, key);
  if (v.size() != 3) fail_at(r, n, key, fmt::format("expected [x, y, z], got {} numbers", v.size()));
  return {v[0], v[1], v[2]};
}

/// Readers for the mappings of a list (empty when absent). `what` describes an item.
[[nodiscard]] inline std::vector<MapReader> map_list(MapReader& r, const std::string& key,
                                                     const std::string& what) {
  const YAML::Node n = r.node(key);
  std::vector<MapReader> out;
  if (!n.IsDefined() || n.IsNull()) return out;
  if (!n.IsSequence()) fail_at(r, n, key, fmt::format("expected a list of {}", what));
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsMap()) {
      fail_at(r, n[i], fmt::format("{}[{}]", key, i), fmt::format("expected {} (a mapping)", what));
    }
    out.emplace_back(n[i], r.file(), r.key_path(fmt::format("{}[{}]", key, i)));
  }
  return out;
}

}  // namespace ferro::scenarios::detail
