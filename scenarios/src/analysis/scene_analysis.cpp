#include "ferro/scenarios/analysis/scene_analysis.hpp"

#include <fmt/format.h>

#include <memory>
#include <optional>
#include <stdexcept>

#include "ferro/scenarios/model_factory.hpp"
#include "ferro/track/track_structure.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

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

vehicle::ModeShapeInput mode_shapes(const Scene& scene, const vehicle::OdeSystem& system) {
  // The co-running track's lumped masses, when the model runs on a flexible track.
  std::optional<track::CoRunningTrackParams> track_masses;
  if (const auto* model = dynamic_cast<const vehicle::VehicleModel*>(&system)) {
    const auto& in = model->inputs();
    if (in.track_structure.flexible()) {
      const double spacing = in.track ? in.track->alignment().design().rail_spacing : 1.5;
      track_masses = track::co_running_equivalent(in.track_structure.ballasted, spacing);
    }
  }
  const auto mass = [&scene, &track_masses](const std::string& body,
                                            const std::string& dof) -> double {
    if (body.rfind("track.", 0) == 0) {
      // "track.<wheelset>.<left_rail | right_rail | sleeper>", dof y, z or roll.
      if (!track_masses) return NAN;
      const bool rail = body.ends_with("_rail");
      if (dof == "y") return rail ? track_masses->rail_mass_lateral : track_masses->sleeper_mass_lateral;
      if (dof == "z") return rail ? track_masses->rail_mass_vertical : track_masses->sleeper_mass_vertical;
      if (dof == "roll") return rail ? track_masses->rail_roll_inertia : track_masses->sleeper_roll_inertia;
      return NAN;
    }
    if (scene.model.type == "suspended_wheelset") {
      if (body != "wheelset") return NAN;
      if (dof == "y") return scene.model.wheelset.mass;
      if (dof == "yaw") return scene.model.wheelset.yaw_inertia;
      return NAN;
    }
    for (const auto& b : scene.model.vehicle.bodies) {
      if (b.name != body) continue;
      if (dof == "x" || dof == "y" || dof == "z") return b.mass;
      if (dof == "roll") return b.inertia[0];
      if (dof == "pitch" || dof == "spin") return b.inertia[1];
      if (dof == "yaw") return b.inertia[2];
    }
    return NAN;
  };
  return vehicle::mode_shape_input(system.state_info(), mass);
}

vehicle::LinearisationAtSpeed with_mode_shapes(const Scene& scene,
                                               vehicle::LinearisationAtSpeed family) {
  return [scene, family = std::move(family)](double v) {
    auto lin = family(v);
    lin.shapes = mode_shapes(scene, *lin.system);
    return lin;
  };
}

std::vector<double> disturbed_state(const Scene& scene, const vehicle::OdeSystem& system,
                                    double lateral_offset) {
  auto x = initial_state(scene, system);
  x[lateral_states(system).index.front()] += lateral_offset;
  return x;
}

}  // namespace ferro::scenarios::analysis
