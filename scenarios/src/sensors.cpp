// Standard sensor positions of a vehicle (see the header).
#include "ferro/scenarios/sensors.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ferro::scenarios {

namespace {

using vehicle::BodyKind;
using vehicle::RigidBodySpec;

const RigidBodySpec* find(const vehicle::VehicleConfig& v, const std::string& name) {
  for (const auto& b : v.bodies)
    if (b.name == name) return &b;
  return nullptr;
}

// Bogie frames front first.
std::vector<const RigidBodySpec*> bogies(const vehicle::VehicleConfig& v) {
  std::vector<const RigidBodySpec*> out;
  for (const auto& b : v.bodies)
    if (b.kind == BodyKind::bogie_frame) out.push_back(&b);
  std::stable_sort(out.begin(), out.end(), [](const auto* l, const auto* r) {
    return l->position.x() > r->position.x();
  });
  return out;
}

// The wheelsets of a bogie frame: those nearer to it than to any other frame, front first.
std::vector<const RigidBodySpec*> wheelsets_of(const vehicle::VehicleConfig& v,
                                               const RigidBodySpec& frame) {
  const auto frames = bogies(v);
  std::vector<const RigidBodySpec*> out;
  for (const auto& w : v.bodies) {
    if (w.kind != BodyKind::wheelset) continue;
    const RigidBodySpec* nearest = nullptr;
    for (const auto* f : frames)
      if (nearest == nullptr ||
          std::abs(f->position.x() - w.position.x()) < std::abs(nearest->position.x() - w.position.x()))
        nearest = f;
    if (nearest == &frame) out.push_back(&w);
  }
  std::stable_sort(out.begin(), out.end(), [](const auto* l, const auto* r) {
    return l->position.x() > r->position.x();
  });
  return out;
}

}  // namespace

std::vector<std::string> sensor_presets(const vehicle::VehicleConfig& v) {
  std::vector<std::string> out;
  const auto frames = bogies(v);
  if (find(v, "car_body") != nullptr && !frames.empty()) {
    for (const char* p : {"floor_front", "floor_centre", "floor_rear"}) {
      out.push_back(p);
      out.push_back(std::string(p) + "_left");
      out.push_back(std::string(p) + "_right");
    }
  }
  for (const auto* f : frames) {
    const auto ws = wheelsets_of(v, *f);
    if (ws.size() >= 1) out.push_back(f->name + "_front");
    if (ws.size() >= 2) out.push_back(f->name + "_rear");
  }
  return out;
}

std::vector<vehicle::SensorSpec> preset_sensors(const vehicle::VehicleConfig& v,
                                                const std::string& name, double floor_height) {
  const auto presets = sensor_presets(v);
  if (name == "standard") {
    std::vector<vehicle::SensorSpec> out;
    for (const auto& p : presets) {
      if (p.ends_with("_left") || p.ends_with("_right")) continue;
      auto one = preset_sensors(v, p, floor_height);
      out.insert(out.end(), one.begin(), one.end());
    }
    return out;
  }
  if (std::find(presets.begin(), presets.end(), name) == presets.end())
    throw std::invalid_argument(fmt::format("unknown sensor '{}'; standard positions: standard, {}",
                                            name, fmt::join(presets, ", ")));
  const auto frames = bogies(v);
  if (name.rfind("floor_", 0) == 0) {
    const RigidBodySpec& car = *find(v, "car_body");
    const double z = (std::isnan(floor_height) ? car.position.z() : floor_height) - car.position.z();
    double x = 0.0;
    if (name.rfind("floor_front", 0) == 0) x = frames.front()->position.x() - car.position.x();
    if (name.rfind("floor_rear", 0) == 0) x = frames.back()->position.x() - car.position.x();
    const double y = name.ends_with("_left") ? kFloorSideOffset
                     : name.ends_with("_right") ? -kFloorSideOffset
                                                : 0.0;
    return {{name, "car_body", Eigen::Vector3d(x, y, z), "xyz"}};
  }
  for (const auto* f : frames) {
    const auto ws = wheelsets_of(v, *f);
    // The stability criterion reads the lateral acceleration only.
    if (name == f->name + "_front")
      return {{name, f->name, Eigen::Vector3d(ws.front()->position.x() - f->position.x(), 0, 0), "y"}};
    if (name == f->name + "_rear")
      return {{name, f->name, Eigen::Vector3d(ws.back()->position.x() - f->position.x(), 0, 0), "y"}};
  }
  throw std::logic_error("sensor preset without a position: " + name);
}

std::vector<vehicle::SensorSpec> default_sensors(const vehicle::VehicleConfig& v,
                                                 const vehicle::ModelSelection& selection,
                                                 double floor_height) {
  std::vector<vehicle::SensorSpec> all = preset_sensors(v, "standard", floor_height);
  if (selection.scope == "vehicle") return all;
  std::vector<vehicle::SensorSpec> out;
  if (selection.scope == "bogie") {
    const auto frames = bogies(v);
    if (selection.index < 0 || static_cast<std::size_t>(selection.index) >= frames.size()) return out;
    for (const auto& s : all)
      if (s.body == frames[static_cast<std::size_t>(selection.index)]->name) out.push_back(s);
  }
  return out;
}

}  // namespace ferro::scenarios
