#include "ferro/scenarios/model_factory.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <map>
#include <mutex>
#include <set>
#include <stdexcept>

#include "ferro/scenarios/scene.hpp"
#include "ferro/vehicle/suspended_wheelset.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::scenarios {
namespace {

// Names do not depend on parameter values: list them from a model built with unit parameters.
std::unique_ptr<vehicle::OdeSystem> probe(const ModelConfig& model) {
  if (model.type != "suspended_wheelset")
    throw std::invalid_argument("state names are listed for suspended_wheelset models only");
  vehicle::SuspendedWheelsetParams p;
  p.mass = p.yaw_inertia = p.half_gauge = p.rolling_radius = p.conicity = 1.0;
  p.primary_stiffness_x = p.primary_stiffness_y = 1.0;
  return std::make_unique<vehicle::SuspendedWheelset>(p, vehicle::CreepCoefficients{1.0, 1.0}, 1.0);
}

}  // namespace

std::vector<std::string> state_names(const ModelConfig& model) {
  std::vector<std::string> out;
  for (const auto& s : probe(model)->state_info()) out.push_back(s.name);
  return out;
}

std::vector<std::string> signal_names(const ModelConfig& model) {
  const auto sys = probe(model);
  std::vector<std::string> out;
  for (const auto& s : sys->state_info()) out.push_back(s.name);
  for (const auto& s : sys->signal_info()) out.push_back(s.name);
  return out;
}

ModelResources build_resources(const Scene& scene) {
  ModelResources r;
  if (scene.model.type != "vehicle") return r;
  r.track = build_track(scene.track);
  r.geometry = vehicle::make_geometry_source(scene.model.vehicle.wheel_rail, "");
  return r;
}

std::unique_ptr<vehicle::OdeSystem> build_system(const Scene& scene, double speed) {
  return build_system(scene, speed, build_resources(scene));
}

namespace {

std::unique_ptr<vehicle::OdeSystem> make_system(const Scene& scene, double speed,
                                                const ModelResources& resources,
                                                bool run_outputs) {
  if (scene.model.type == "suspended_wheelset") {
    return std::make_unique<vehicle::SuspendedWheelset>(
        scene.model.wheelset, vehicle::creep_coefficients(scene.contact.creep), speed);
  }
  if (scene.model.type == "vehicle") {
    vehicle::VehicleModelInputs in;
    in.config = scene.model.vehicle;
    in.selection = scene.model.selection;
    in.track = resources.track;
    in.track_structure = scene.track.structure;
    in.geometry = resources.geometry;
    in.speed.initial = speed;
    in.speed.acceleration = scene.simulation.acceleration;
    in.start_position = scene.simulation.start_position;
    if (run_outputs) {
      in.outputs.sensors = scene.output.sensors;
      in.outputs.anti_alias_frequency = scene.output.anti_alias_frequency;
      in.outputs.anti_alias_order = scene.output.anti_alias_order;
      in.outputs.contact_point_details = scene.output.contact_points;
    }
    return std::make_unique<vehicle::VehicleModel>(std::move(in));
  }
  throw std::invalid_argument("model.type: unknown '" + scene.model.type +
                              "'; allowed: suspended_wheelset, vehicle");
}

}  // namespace

std::unique_ptr<vehicle::OdeSystem> build_system(const Scene& scene, double speed,
                                                 const ModelResources& resources) {
  return make_system(scene, speed, resources, false);
}

std::unique_ptr<vehicle::OdeSystem> build_run_system(const Scene& scene, double speed,
                                                     const ModelResources& resources) {
  return make_system(scene, speed, resources, true);
}

std::vector<double> equilibrium_state(const Scene& scene, const vehicle::OdeSystem& system) {
  if (const auto* v = dynamic_cast<const vehicle::VehicleModel*>(&system)) {
    return vehicle::static_equilibrium(*v, 0.0);
  }
  return std::vector<double>(system.size(), 0.0);
}

vehicle::LinearisationAtSpeed linearisation_family(const Scene& scene) {
  struct Shared {
    Scene scene;
    ModelResources resources;
    std::mutex mutex;
    std::map<double, std::vector<double>> equilibria;  // by speed [m/s]
  };
  auto shared = std::make_shared<Shared>();
  shared->scene = scene;
  shared->scene.simulation.acceleration = 0.0;
  shared->resources = build_resources(shared->scene);
  return [shared](double v) {
    vehicle::Linearisation lin;
    lin.system = build_system(shared->scene, v, shared->resources);
    const auto* model = dynamic_cast<const vehicle::VehicleModel*>(lin.system.get());
    std::vector<double> start;
    {
      std::lock_guard lock(shared->mutex);
      auto& eq = shared->equilibria;
      if (const auto it = eq.find(v); it != eq.end()) {
        lin.x_eq = it->second;
        return lin;
      }
      // The nearest speed solved: the first one at or above v, or the one below.
      auto near = eq.lower_bound(v);
      if (near == eq.end() || (near != eq.begin() && v - std::prev(near)->first < near->first - v))
        near = near == eq.begin() ? near : std::prev(near);
      if (near != eq.end()) start = near->second;
    }
    lin.x_eq = model == nullptr || start.empty() ? equilibrium_state(shared->scene, *lin.system)
                                                 : vehicle::static_equilibrium(*model, 0.0, start);
    std::lock_guard lock(shared->mutex);
    shared->equilibria.emplace(v, lin.x_eq);
    return lin;
  };
}

std::vector<double> initial_state(const Scene& scene, const vehicle::OdeSystem& system) {
  std::vector<double> x = equilibrium_state(scene, system);
  const auto info = system.state_info();
  for (const auto& [name, value] : scene.simulation.initial) {
    std::size_t i = 0;
    while (i < info.size() && info[i].name != name) ++i;
    if (i == info.size()) {
      std::vector<std::string> names;
      for (const auto& s : info) names.push_back(s.name);
      const std::string near = nearest_key(name, {names.begin(), names.end()});
      const auto it = scene.simulation.initial_position.find(name);
      const auto [line, col] =
          it == scene.simulation.initial_position.end() ? std::pair{0, 0} : it->second;
      throw YamlInputError(scene.path, line, col, "simulation.initial." + name,
                           fmt::format("unknown state{}; states of this model: {}",
                                       near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near),
                                       fmt::join(names, ", ")));
    }
    x[i] += value;
  }
  return x;
}

}  // namespace ferro::scenarios
