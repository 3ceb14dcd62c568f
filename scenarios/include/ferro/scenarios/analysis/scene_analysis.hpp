#pragma once
// Glue between scenes and the analyses: the system family over speed, the lateral states the
// analyses watch, the Kalker reduction factors applied to a scene, the disturbed start state.
// Works on whatever OdeSystem scenarios::build_system makes of the scene.

#include <cmath>
#include <string>
#include <vector>

#include "ferro/contact/kij/reduction_factors.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/vehicle/stability.hpp"

namespace ferro::scenarios::analysis {

/// The scene with its reduction factors replaced: the linear wheelset's contact.k11/k22 (its
/// linear theory has no spin) and the vehicle's wheel_rail.reduction (K11, K22, K23, K33; the
/// studies set K11 and K22 with ReductionFactors::following_k22()). Throws
/// std::invalid_argument when a factor is not in (0, 1].
[[nodiscard]] Scene with_reduction(Scene scene, const contact::ReductionFactors& k);

/// build_system(scene, V) at constant speed (the scene's acceleration set to 0) as a factory
/// over speed; the track and contact geometry are built once, here.
[[nodiscard]] vehicle::SystemAtSpeed speed_family(const Scene& scene);

/// Lateral displacement states of the wheelsets, front first: "wheelset_<i>.y" (i = 1, 2, ...),
/// or the single "wheelset.y". Throws std::invalid_argument when there is none.
struct LateralStates {
  std::vector<std::size_t> index;  ///< state indices
  std::vector<std::string> name;   ///< state names
};
[[nodiscard]] LateralStates lateral_states(const vehicle::OdeSystem& system);

/// Shape input of the modes of a scene's system (vehicle::ModeShapeInput): each velocity state's
/// generalised mass from the scene's model description (a vehicle's bodies: mass for x, y, z,
/// the inertia about the axis for roll, pitch, yaw, the wheelset's spin inertia for its spin
/// perturbation; the suspended wheelset's mass and yaw inertia; on a flexible track the
/// co-running track's rail and sleeper masses and roll inertias, track::co_running_equivalent);
/// states the description does not weigh take vehicle::mode_shape_input()'s fallback.
[[nodiscard]] vehicle::ModeShapeInput mode_shapes(const Scene& scene,
                                                  const vehicle::OdeSystem& system);

/// The family with the shape input of each speed's system attached: its modes come classified
/// and vehicle::critical_speed looks at the hunting modes.
[[nodiscard]] vehicle::LinearisationAtSpeed with_mode_shapes(const Scene& scene,
                                                             vehicle::LinearisationAtSpeed family);

/// The scene's initial state, plus `lateral_offset` [m] added to the leading wheelset's lateral
/// displacement.
[[nodiscard]] std::vector<double> disturbed_state(const Scene& scene,
                                                  const vehicle::OdeSystem& system,
                                                  double lateral_offset);

}  // namespace ferro::scenarios::analysis
