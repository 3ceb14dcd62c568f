#include "ferro/scenarios/model_factory.hpp"

#include <stdexcept>

#include "ferro/scenarios/scene.hpp"
#include "ferro/vehicle/suspended_wheelset.hpp"

namespace ferro::scenarios {
namespace {

// Names do not depend on parameter values: list them from a model built with unit parameters.
std::unique_ptr<vehicle::OdeSystem> probe(const ModelConfig& model) {
  if (model.type != "suspended_wheelset")
    throw std::invalid_argument("unknown model type " + model.type);
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

std::unique_ptr<vehicle::OdeSystem> build_system(const Scene& scene, double speed) {
  if (scene.model.type == "suspended_wheelset") {
    return std::make_unique<vehicle::SuspendedWheelset>(
        scene.model.wheelset, vehicle::creep_coefficients(scene.contact.creep), speed);
  }
  throw std::invalid_argument("model.type: unknown '" + scene.model.type +
                              "'; allowed: suspended_wheelset");
}

std::vector<double> initial_state(const Scene& scene, const vehicle::OdeSystem& system) {
  std::vector<double> x(system.size(), 0.0);
  const auto info = system.state_info();
  for (std::size_t i = 0; i < info.size(); ++i) {
    const auto it = scene.simulation.initial.find(info[i].name);
    if (it != scene.simulation.initial.end()) x[i] = it->second;
  }
  return x;
}

}  // namespace ferro::scenarios
