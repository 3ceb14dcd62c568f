#pragma once
// Builds the OdeSystem a scene describes, and its initial state.

#include <memory>
#include <string>
#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/track/track.hpp"
#include "ferro/vehicle/ode_system.hpp"
#include "ferro/vehicle/stability.hpp"

namespace ferro::scenarios {

struct ModelConfig;
struct ContactConfig;
struct Scene;

/// State names of a suspended_wheelset model, in state order.
[[nodiscard]] std::vector<std::string> state_names(const ModelConfig& model);
/// All output signal names of a suspended_wheelset model (states, then derived signals).
[[nodiscard]] std::vector<std::string> signal_names(const ModelConfig& model);

/// What a vehicle scene builds once and shares between the systems of a speed sweep: the track
/// and the contact geometry source (tables are precomputed here).
struct ModelResources {
  std::shared_ptr<const track::Track> track;
  std::shared_ptr<const contact::ContactGeometrySource> geometry;
};
[[nodiscard]] ModelResources build_resources(const Scene& scene);

/// The scene's system at a given initial forward speed [m/s] (the scene's acceleration applies).
[[nodiscard]] std::unique_ptr<vehicle::OdeSystem> build_system(const Scene& scene, double speed);
[[nodiscard]] std::unique_ptr<vehicle::OdeSystem> build_system(const Scene& scene, double speed,
                                                               const ModelResources& resources);

/// The system `ferrodyn run` integrates: build_system() plus, for a vehicle scene, the
/// output block's sensors and in-run anti-alias filters (extra states and signals).
[[nodiscard]] std::unique_ptr<vehicle::OdeSystem> build_run_system(const Scene& scene, double speed,
                                                                   const ModelResources& resources);

/// The state the system is linearised about: the static equilibrium at t = 0 for a vehicle
/// model, zero for suspended_wheelset.
[[nodiscard]] std::vector<double> equilibrium_state(const Scene& scene,
                                                    const vehicle::OdeSystem& system);

/// The scene's system at each constant speed (acceleration 0) with its equilibrium at that
/// speed: equilibrium_state() for the first speed asked, then the static equilibrium
/// warm-started from the nearest speed already solved (the equilibria are cached, so a scan and
/// its bisection each solve a short Newton). Safe to call from several threads. This is what
/// every linear stability analysis of a scene (eigenvalues against speed, the Hopf speed) uses.
[[nodiscard]] vehicle::LinearisationAtSpeed linearisation_family(const Scene& scene);

/// Initial state: equilibrium_state() plus the scene's `simulation.initial` by state name.
/// Throws YamlInputError at the `initial` key for a name the model does not have.
[[nodiscard]] std::vector<double> initial_state(const Scene& scene,
                                                const vehicle::OdeSystem& system);

}  // namespace ferro::scenarios
