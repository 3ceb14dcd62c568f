#pragma once
// Sensors of a vehicle scene's `output.sensors`: explicit ones ({name, body, point}) and the
// standard positions by name, placed from the vehicle's bodies:
//   floor_front, floor_centre, floor_rear   car body floor above the leading bogie's centre,
//                                           mid-body, above the trailing bogie's centre (EN 12299
//                                           / EN 14363 measuring points), on the centre line;
//   <floor point>_left, _right              the same 1 m to the left (+y) / right;
//   bogie_<k>_front, bogie_<k>_rear         bogie frame k above its leading / trailing wheelset,
//                                           at the frame's centre-of-mass height (lateral
//                                           acceleration anti-alias filtered only);
//   standard                                the three floor points and every bogie point.
// The floor lies at `floor_height` above the top of rail (NaN: the car body's centre of mass).

#include <limits>
#include <string>
#include <vector>

#include "ferro/vehicle/vehicle_config.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::scenarios {

/// Lateral offset of the _left / _right floor points [m].
inline constexpr double kFloorSideOffset = 1.0;

/// Names of the standard positions the vehicle has (without "standard").
[[nodiscard]] std::vector<std::string> sensor_presets(const vehicle::VehicleConfig& vehicle);

/// The sensors a name stands for ("standard" gives several). Throws std::invalid_argument
/// naming the allowed names for an unknown one.
[[nodiscard]] std::vector<vehicle::SensorSpec> preset_sensors(const vehicle::VehicleConfig& vehicle,
                                                              const std::string& name,
                                                              double floor_height);

/// The sensors of a run when the scene names none: the standard positions on the bodies the
/// model selection has states for (all of them for the whole vehicle, the bogie's for a bogie,
/// none for a wheelset).
[[nodiscard]] std::vector<vehicle::SensorSpec> default_sensors(
    const vehicle::VehicleConfig& vehicle, const vehicle::ModelSelection& selection,
    double floor_height);

}  // namespace ferro::scenarios
