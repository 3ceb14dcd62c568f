#pragma once
// Builds the OdeSystem a scene describes, and the initial state.

#include <memory>
#include <string>
#include <vector>

#include "ferro/vehicle/ode_system.hpp"

namespace ferro::scenarios {

struct ModelConfig;
struct ContactConfig;
struct Scene;

/// State names of a model type, in state order.
[[nodiscard]] std::vector<std::string> state_names(const ModelConfig& model);
/// All output signal names (states, then derived signals).
[[nodiscard]] std::vector<std::string> signal_names(const ModelConfig& model);

/// The scene's system at a given forward speed [m/s].
[[nodiscard]] std::unique_ptr<vehicle::OdeSystem> build_system(const Scene& scene, double speed);

/// Initial state from the scene's `simulation.initial` (zeros elsewhere).
[[nodiscard]] std::vector<double> initial_state(const Scene& scene,
                                                const vehicle::OdeSystem& system);

}  // namespace ferro::scenarios
