#include "ferro/scenarios/analysis/scene_analysis.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "ferro/scenarios/model_factory.hpp"

namespace ferro::scenarios::analysis {

Scene with_reduction(Scene scene, const Reduction& k) {
  for (const auto& [name, v] : {std::pair{"k11", k.k11}, std::pair{"k22", k.k22}}) {
    if (!(v > 0.0 && v <= 1.5))
      throw std::invalid_argument(
          fmt::format("reduction factor {} = {}: allowed (0, 1.5]", name, v));
  }
  scene.contact.creep.k11 = k.k11;
  scene.contact.creep.k22 = k.k22;
  return scene;
}

vehicle::SystemAtSpeed speed_family(const Scene& scene) {
  return [scene](double v) { return build_system(scene, v); };
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
