#pragma once
// Vehicle description files in the shape engineers write them (car_body, bogie_frame,
// wheelset, geometry, primary_suspension, secondary_suspension, wheel_rail blocks; see
// scenarios/vehicles/ and docs/SCENES.md), expanded into the explicit vehicle::VehicleConfig:
// seven bodies placed from the geometry block, and every suspension element with its two
// attachment points.
//
// Compact blocks give per-axlebox primary and per-side secondary springs and dampers, the
// lateral bump stop, the anti-roll bar and the bogie yaw stiffness; explicit element lists
// (`elements:` in either suspension block) give elements one by one, written for the leading
// bogie (secondary) or the leading wheelset of a bogie (primary) and mirrored fore-aft for the
// others. Relative file names are resolved against the file's directory.

#include <string>

#include "ferro/scenarios/yaml_reader.hpp"
#include "ferro/vehicle/vehicle_config.hpp"

namespace ferro::scenarios {

inline constexpr int kVehicleSchemaVersion = 1;

/// Categories of the key `category`, on which the standards' limits depend (EN 14363: the
/// track-shift factor alpha is 1 for locomotives, power cars and coaches, 0.85 for wagons).
[[nodiscard]] const std::vector<std::string>& vehicle_categories();

/// Reads a vehicle description (the mapping `r`, e.g. a file's root or an inline `vehicle:`
/// block). Throws YamlInputError at the offending key. `category` (when given) receives the
/// key `category` ("" when absent).
[[nodiscard]] vehicle::VehicleConfig read_vehicle(MapReader& r, std::string* category = nullptr);

/// Loads a vehicle file (with `schema_version: 1`).
[[nodiscard]] vehicle::VehicleConfig load_vehicle_file(const std::string& path,
                                                       std::string* category = nullptr);
/// The same from a file already parsed (e.g. with values replaced by key).
[[nodiscard]] vehicle::VehicleConfig read_vehicle_file(const YamlFile& file,
                                                       std::string* category = nullptr);

/// Reads wheel-rail keys into `spec`, changing only the keys present (so a scene's contact
/// part can override the vehicle file's wheel_rail block). Does not call r.finish(): `extra`
/// keys of the caller may follow.
void read_wheel_rail(MapReader& r, vehicle::WheelRailSpec& spec);

/// Checks what the chosen geometry needs (profiles, imported table, conicity) and the gauge;
/// errors are located at `r` (the block that set the geometry).
void check_wheel_rail(const MapReader& r, const vehicle::WheelRailSpec& spec);

/// Names of the wheel-rail keys read_wheel_rail() accepts.
[[nodiscard]] const std::vector<std::string>& wheel_rail_keys();

/// Index of a body by name in config.bodies, or -1.
[[nodiscard]] int body_index(const vehicle::VehicleConfig& config, const std::string& name);

}  // namespace ferro::scenarios
