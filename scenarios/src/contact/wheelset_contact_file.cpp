// Reading a wheelset-contact study file: a pair file that also carries the load, speed,
// material, friction, discretisation and the prescribed wheelset positions.
//
// References: Shackleton & Iwnicki, VSD 46 (2008) (Manchester contact benchmark input).
// Known deviations: none.
#include "ferro/scenarios/wheelset_contact_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>

#include "ferro/scenarios/yaml_reader.hpp"

namespace ferro::scenarios {
namespace {

double positive(MapReader& r, const std::string& key, const char* unit) {
  const double v = r.number(key);
  if (!(v > 0.0)) r.fail(key, fmt::format("must be > 0 {}, got {}", unit, v));
  return v;
}

}  // namespace

WheelsetContactInput load_wheelset_contact_file(const std::string& path) {
  WheelsetContactInput in;
  in.pair = load_pair_file(path);
  const YamlFile file = load_yaml_file(path);
  MapReader top(file.root, path, "");
  MapReader ws = top.map("wheelset");
  in.spec.load_per_wheel = positive(ws, "vertical_load_per_wheel", "N");
  in.spec.forward_speed = positive(ws, "forward_speed", "mm/s") * 1e-3;
  MapReader mat = top.map("material");
  in.spec.material.shear_modulus = positive(mat, "shear_modulus", "N/mm^2") * 1e6;
  in.spec.material.poisson = mat.number("poisson");
  if (!(in.spec.material.poisson >= 0.0 && in.spec.material.poisson < 0.5)) {
    mat.fail("poisson", fmt::format("must lie in [0, 0.5), got {}", in.spec.material.poisson));
  }
  mat.finish();
  MapReader fr = top.map("friction");
  in.spec.friction = fr.number("mu");
  if (!(in.spec.friction >= 0.0))
    fr.fail("mu", fmt::format("must be >= 0, got {}", in.spec.friction));
  fr.finish();
  MapReader disc = top.map_or_empty("discretisation_hint");
  in.spec.dx = disc.number_or("dx", 0.2) * 1e-3;
  in.spec.ds = disc.number_or("dy", 0.2) * 1e-3;
  for (const char* key : {"dx", "dy"}) {
    const double v = (std::string(key) == "dx" ? in.spec.dx : in.spec.ds) * 1e3;
    if (!(v >= 0.02 && v <= 2.0)) {
      disc.fail(key, fmt::format("must lie in [0.02, 2] mm, got {}", v));
    }
  }
  disc.finish();
  const YAML::Node cases = top.node("cases");
  if (!cases.IsSequence() || cases.size() == 0) {
    top.fail("cases", "must be a non-empty list of {id, y, roll, yaw, pitch_rate}");
  }
  for (std::size_t i = 0; i < cases.size(); ++i) {
    MapReader k(cases[i], path, fmt::format("cases[{}]", i));
    contact::WheelsetCase c;
    c.id = static_cast<int>(k.integer_or("id", static_cast<long>(i) + 1));
    c.lateral = k.number("y") * 1e-3;
    c.roll = k.number("roll");
    c.yaw = k.number("yaw");
    c.pitch_rate = k.number("pitch_rate");
    if (std::abs(c.lateral) > 0.05) k.fail("y", "must lie within +-50 mm");
    if (std::abs(c.roll) > 0.1 || std::abs(c.yaw) > 0.1) {
      k.fail(std::abs(c.roll) > 0.1 ? "roll" : "yaw", "must lie within +-0.1 rad");
    }
    k.finish();
    in.cases.push_back(c);
  }
  return in;
}

}  // namespace ferro::scenarios
