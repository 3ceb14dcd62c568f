#include "ferro/scenarios/analysis/scene_analysis.hpp"

#include <fmt/format.h>

#include <memory>
#include <stdexcept>

#include "ferro/scenarios/model_factory.hpp"

namespace ferro::scenarios::analysis {

Scene with_reduction(Scene scene, const contact::ReductionFactors& k) {
  for (const auto& [name, v] : {std::pair{"k11", k.k11}, std::pair{"k22", k.k22},
                                std::pair{"k23", k.k23}, std::pair{"k33", k.k33}}) {
    if (!(v > 0.0 && v <= 1.0))
      throw std::invalid_argument(fmt::format("reduction factor {} = {}: allowed (0, 1]", name, v));
  }
  scene.contact.creep.reduction = k;
  scene.model.vehicle.wheel_rail.reduction = k;
  return scene;
}

vehicle::SystemAtSpeed speed_family(const Scene& scene) {
  Scene constant = scene;
  constant.simulation.acceleration = 0.0;
  auto resources = std::make_shared<const ModelResources>(build_resources(constant));
  return [constant, resources](double v) { return build_system(constant, v, *resources); };
}

LateralStates lateral_states(const vehicle::OdeSystem& system) {
  const auto info = system.state_info();
  LateralStates out;
  for (int i = 1;; ++i) {
    const std::string name = fmt::format("wheelset_{}.y", i);
    bool found = false;
    for (std::size_t j = 0; j < info.size(); ++j) {
      if (info[j].name == name) {
        out.index.push_back(j);
        out.name.push_back(name);
        found = true;
      }
    }
    if (!found) break;
  }
  if (out.index.empty()) {
    for (std::size_t j = 0; j < info.size(); ++j) {
      if (info[j].name == "wheelset.y") {
        out.index.push_back(j);
        out.name.push_back(info[j].name);
      }
    }
  }
  if (out.index.empty())
    throw std::invalid_argument(
        "the model has no wheelset lateral displacement state (wheelset_1.y or wheelset.y)");
  return out;
}

std::vector<double> disturbed_state(const Scene& scene, const vehicle::OdeSystem& system,
                                    double lateral_offset) {
  auto x = initial_state(scene, system);
  x[lateral_states(system).index.front()] += lateral_offset;
  return x;
}

}  // namespace ferro::scenarios::analysis
