#pragma once
// Changes made to a loaded scene at run time: the forward speed, duration, integrator and its
// tolerances, the contact models and the eigenvalue speed range. The command line's options
// (--speed, --t-end, ...) and the Python module's keyword arguments (speed=, t_end=, ...) both
// go through apply_overrides, so both check the same limits and name the value in every error.

#include <limits>
#include <string>
#include <string_view>

#include "ferro/contact/model_options.hpp"
#include "ferro/scenarios/parameters.hpp"
#include "ferro/scenarios/scene.hpp"

namespace ferro::scenarios {

/// Run-time overrides; NaN, 0 or empty: keep the scene's value.
struct RunOverrides {
  static constexpr double kKeep = std::numeric_limits<double>::quiet_NaN();
  double t_end = kKeep;       ///< simulation.t_end [s], > 0
  double speed = kKeep;       ///< simulation.speed [m/s], >= 0 (vehicle) or > 0
  std::string integrator;     ///< solver.integrator (a method without a fixed step drops the
                              ///< scene's fixed_step unless fixed_step is given too)
  double fixed_step = kKeep;  ///< solver.fixed_step [s], >= 0 (0: adaptive steps)
  double rtol = kKeep;        ///< solver.rtol [-], in (0, 1)
  double atol = kKeep;        ///< solver.atol [state units, SI], > 0
  std::string tangential;     ///< the vehicle's tangential contact model
  std::string normal;         ///< the vehicle's normal contact model: hertz | semi_hertz
  double speed_min = kKeep;   ///< analysis.eigen.speed_min [m/s]
  double speed_max = kKeep;   ///< analysis.eigen.speed_max [m/s]
  int points = 0;             ///< analysis.eigen.points, >= 2
};

/// What the environment gives a tangential model that the user names at run time (an override's
/// `tangential`, the contact batch's model): mim_table without a "table" option gets
/// table = $FERRO_MIM_TABLE when that is set. Other models: `options` unchanged. Scene files are
/// read without it: a scene names its table itself.
[[nodiscard]] contact::ModelOptions with_environment_options(const std::string& model,
                                                            contact::ModelOptions options = {});

/// Applies the overrides to `scene`, checking each value and the scene it makes (the vehicle
/// stays on the designed track; the output sample count stays bounded). A tangential model
/// given here takes its options from with_environment_options. Throws std::invalid_argument
/// whose message starts with the value's spelled name.
void apply_overrides(Scene& scene, const RunOverrides& overrides,
                     Spelling spelling = Spelling::key);

/// The overrides as parameters (see parameters.hpp): none has a default (unset keeps the scene's).
[[nodiscard]] Parameters parameters(RunOverrides& overrides);

}  // namespace ferro::scenarios
