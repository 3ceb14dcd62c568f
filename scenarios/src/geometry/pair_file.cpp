// Wheel-rail pair files (YAML, mm) through the strict MapReader.
#include "ferro/scenarios/pair_file.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "ferro/contact/geometry/profile.hpp"
#include "ferro/scenarios/yaml_reader.hpp"

namespace ferro::scenarios {
namespace {

// A required length in mm, finite and > 0.
double positive_mm(MapReader& r, const std::string& key) {
  const double v = r.number(key);
  if (!(v > 0.0)) r.fail(key, fmt::format("must be > 0 mm, got {}", v));
  return v;
}

}  // namespace

double parse_inclination(const std::string& text, const std::string& where) {
  const auto colon = text.find(':');
  auto number = [&](const std::string& part) {
    std::size_t used = 0;
    const double v = std::stod(part, &used);
    if (used != part.size() || !std::isfinite(v)) throw std::invalid_argument(part);
    return v;
  };
  try {
    if (colon != std::string::npos) {
      const double a = number(text.substr(0, colon));
      const double b = number(text.substr(colon + 1));
      if (a == 0.0) return 0.0;
      if (b == 0.0) throw std::invalid_argument(text);
      return std::atan(a / b);
    }
    return number(text);
  } catch (const std::exception&) {
    throw std::invalid_argument(fmt::format(
        "{}: '{}' is not an inclination; use a ratio like 1:40, 0, or a finite angle in rad", where,
        text));
  }
}

PairFile load_pair_file(const std::string& path) {
  const YamlFile file = load_yaml_file(path);
  MapReader top(file.root, path, "");
  if (top.has("schema_version")) {
    const long version = top.integer_or("schema_version", kPairSchemaVersion);
    if (version != kPairSchemaVersion) {
      top.fail("schema_version",
               fmt::format("unsupported version {}; supported: {}", version, kPairSchemaVersion));
    }
  }
  top.allow("schema_version");
  PairFile out;
  out.path = path;
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  contact::WheelRailPairParams& p = out.params;

  MapReader track = top.map("track");
  p.track_gauge = positive_mm(track, "gauge") * 1e-3;
  const double gauge_height = track.number_or("gauge_height", p.gauge_depth * 1e3);
  if (!(gauge_height >= 0.0)) {
    track.fail("gauge_height", fmt::format("must be >= 0 mm, got {}", gauge_height));
  }
  p.gauge_depth = gauge_height * 1e-3;
  out.rail_profile = (base / track.string("rail_profile")).string();
  if (track.has("rail_inclination")) {
    const std::string text = track.string("rail_inclination");
    try {
      p.rail_inclination = parse_inclination(text, "rail_inclination");
    } catch (const std::invalid_argument&) {
      track.fail("rail_inclination",
                 fmt::format("'{}' is not an inclination; use a ratio like 1:40, 0, or an "
                             "angle in rad",
                             text));
    }
  }
  track.allow("cant");
  track.finish();

  MapReader ws = top.map("wheelset");
  p.flange_back_distance = positive_mm(ws, "flange_back_distance") * 1e-3;
  p.flange_back_y =
      ws.number_or("flange_back_position", std::numeric_limits<double>::quiet_NaN()) * 1e-3;
  p.nominal_radius = positive_mm(ws, "nominal_radius") * 1e-3;
  out.wheel_profile = (base / ws.string("wheel_profile")).string();
  ws.allow("vertical_load_per_wheel");
  ws.allow("forward_speed");
  ws.finish();

  for (const char* key : {"material", "friction", "discretisation_hint", "cases"}) top.allow(key);
  top.finish();
  try {
    p.validate();
  } catch (const std::invalid_argument& e) {
    throw YamlInputError(path, 0, 0, "(pair)", e.what());
  }
  return out;
}

contact::WheelRailPair make_wheel_rail_pair(const PairFile& pair) {
  return contact::WheelRailPair(
      contact::read_profile(pair.wheel_profile, contact::ProfileKind::wheel),
      contact::read_profile(pair.rail_profile, contact::ProfileKind::rail), pair.params);
}

}  // namespace ferro::scenarios
