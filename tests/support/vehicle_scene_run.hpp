#pragma once
// Runs a vehicle scene in-process the way `ferrodyn run` does (the scene's system, its static
// equilibrium plus `simulation.initial`, its solver, its output grid) and keeps every channel
// (states, then derived signals) at every output time, for tests that check a whole run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/vehicle/integrator.hpp"

namespace ferro::scenarios::test {

struct SceneRun {
  vehicle::IntegrationResult result;
  std::vector<std::string> names;            ///< states, then derived signals
  std::vector<double> time;                  ///< output times reached [s]
  std::vector<std::vector<double>> samples;  ///< per output time, one value per name

  /// Column index of a channel (fails the test and returns 0 when absent).
  [[nodiscard]] std::size_t index(const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
      ADD_FAILURE() << "no channel " << name;
      return 0;
    }
    return static_cast<std::size_t>(it - names.begin());
  }
  [[nodiscard]] double at(std::size_t sample, const std::string& name) const {
    return samples[sample][index(name)];
  }
};

inline Scene load_test_scene(const std::string& relative_path) {
  return load_scene(std::string(FERRO_SOURCE_DIR) + "/" + relative_path);
}

inline SceneRun run_scene_in_memory(const Scene& scene) {
  const auto system = build_system(scene, scene.simulation.speed);
  const std::vector<double> x0 = initial_state(scene, *system);
  SceneRun run;
  for (const auto& s : system->state_info()) run.names.push_back(s.name);
  const auto derived = system->signal_info();
  for (const auto& s : derived) run.names.push_back(s.name);
  std::vector<double> sig(derived.size());
  auto integrator = vehicle::make_integrator(scene.solver);
  run.result = integrator->integrate(
      *system, x0, vehicle::output_grid(0.0, scene.simulation.t_end, scene.output.interval),
      [&](double t, std::span<const double> x) {
        system->signals(t, x, sig);
        std::vector<double> row(x.begin(), x.end());
        row.insert(row.end(), sig.begin(), sig.end());
        run.time.push_back(t);
        run.samples.push_back(std::move(row));
        return true;
      });
  return run;
}

}  // namespace ferro::scenarios::test
