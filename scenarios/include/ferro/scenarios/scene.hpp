#pragma once
// A scene: the top-level YAML file of a run. It names or embeds five parts -- model, track,
// contact, solver, output -- plus the simulation and analysis settings. Each part may be written
// inline or given as a file name (relative to the scene), and every file carries
// `schema_version`. Layout and keys: docs/SCENES.md.

#include <limits>
#include <map>
#include <string>
#include <vector>

#include "ferro/contact/model_options.hpp"
#include "ferro/scenarios/track_config.hpp"
#include "ferro/scenarios/yaml_reader.hpp"
#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/output_signals.hpp"
#include "ferro/vehicle/suspended_wheelset.hpp"
#include "ferro/vehicle/vehicle_config.hpp"

namespace ferro::scenarios {

inline constexpr int kSceneSchemaVersion = 1;

struct ModelConfig {
  /// suspended_wheelset: the linear 2-DOF wheelset of eq. (150), parameters inline;
  /// vehicle: the multibody model of a vehicle file (whole vehicle, one bogie or one wheelset).
  std::string type = "suspended_wheelset";
  vehicle::SuspendedWheelsetParams wheelset;  ///< type suspended_wheelset
  std::string vehicle_file;                   ///< type vehicle: the file read ("" when inline)
  /// type vehicle: the expanded vehicle; its wheel_rail holds the scene's contact choices
  /// (vehicle file, then the scene's contact and track parts).
  vehicle::VehicleConfig vehicle;
  vehicle::ModelSelection selection;  ///< type vehicle
  /// type vehicle: the vehicle file's `category` (coach | locomotive | power_car | wagon; ""
  /// when not given), on which the assessment's limits depend.
  std::string category;
};

struct ContactConfig {
  vehicle::LinearCreepParams creep;  ///< ellipse, materials, coefficient source, K11, K22
};

struct SimulationConfig {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double speed = kNaN;                    ///< forward speed V at t = 0 [m/s]
  double acceleration = 0.0;              ///< dV/dt (speed ramp; V stays >= 0) [m/s^2]
  double start_position = 0.0;            ///< track arc length of the vehicle centre at t = 0 [m]
  double t_end = kNaN;                    ///< end time [s]
  /// Initial state by state name [SI]: the value itself for suspended_wheelset (others 0), a
  /// perturbation added to the static equilibrium for vehicle models.
  std::map<std::string, double> initial;
  /// Line and column of each `initial` key in the scene file (for errors found at build time).
  std::map<std::string, std::pair<int, int>> initial_position;
};

struct OutputConfig {
  std::string file = "out/run.h5";  ///< HDF5 path (relative to the working directory)
  double interval = 1e-3;           ///< output sampling interval [s]
  double flush_seconds = 0.5;       ///< flush to disk at least this often (wall clock) [s]
  std::vector<std::string> csv;     ///< signals also written to CSV ("all" for every one)
  std::vector<std::string> plots;   ///< signals plotted by `ferrodyn run` (empty: the states)
  /// Vehicle scenes: sensors of the run (standard positions resolved against the vehicle;
  /// sensors.hpp); the standard positions of the modelled bodies when the key is absent.
  std::vector<vehicle::SensorSpec> sensors;
  /// Vehicle scenes: corner of the in-run anti-alias low-pass of the wheel forces and sensor
  /// accelerations [Hz]; 0: none.
  double anti_alias_frequency = 50.0;
  int anti_alias_order = 4;  ///< of that Butterworth low-pass: 2, 4, 6 or 8
  /// Vehicle scenes: also each contact point's creep forces, places, ... (signals point_k.*).
  bool contact_points = false;
  /// Floor height of the standard floor sensors above the top of rail [m]; NaN: the car
  /// body's centre of mass.
  double floor_height = std::numeric_limits<double>::quiet_NaN();
};

struct EigenConfig {
  double speed_min = 1.0;    ///< [m/s]
  double speed_max = 150.0;  ///< [m/s]
  int points = 150;          ///< speeds in the sweep
};

/// How `ferrodyn assess` treats a run of the scene.
struct AssessmentConfig {
  /// The run is the standard's twist test: the wheel unloading dQ/Q0 is assessed too.
  bool twist_test = false;
};

struct Scene {
  std::string path;  ///< scene file
  std::string text;  ///< scene text followed by each included file's text
  int schema_version = kSceneSchemaVersion;
  std::string name;
  std::string description;
  ModelConfig model;
  TrackConfig track;
  ContactConfig contact;
  SimulationConfig simulation;
  vehicle::IntegratorSettings solver;
  OutputConfig output;
  EigenConfig eigen;
  AssessmentConfig assessment;
};

/// A value given by key in place of the file's: the dotted key path from the scene's root
/// ("simulation.speed", "solver.integrator", "model.vehicle.wheel_rail.friction"; the path runs
/// on into a part or a vehicle file given by file name) and the value as YAML text ("40",
/// "cvode_bdf", "[1, 2]", "{shear_modulus: 8e10}").
struct KeyOverride {
  std::string key;
  std::string value;
};

/// Loads and validates a scene. Throws YamlInputError (file:line:col: key: message) for any bad
/// input, including values that fail the parameter structs' validate().
[[nodiscard]] Scene load_scene(const std::string& path);
/// The same with values replaced by key before reading. An error in an overridden value names
/// the key, without a line, and says it was given as an override.
[[nodiscard]] Scene load_scene(const std::string& path, const std::vector<KeyOverride>& overrides);
/// An error located in a scene's files, moved to the override when its key is one of the
/// overrides' (or below one): no line, "(given as an override)" added. Else `e` unchanged.
[[nodiscard]] YamlInputError at_override(const YamlInputError& e, const std::string& scene_path,
                                         const std::vector<KeyOverride>& overrides);

/// A scene given as YAML text: `path` names it in messages and its folder is where relative
/// file names are looked for.
[[nodiscard]] Scene load_scene_text(const std::string& text, const std::string& path,
                                    const std::vector<KeyOverride>& overrides = {});

/// The value at a dotted key path of a scene (as KeyOverride::key, through parts and vehicle
/// files given by file name) as written in its files; a null node when absent.
[[nodiscard]] YAML::Node scene_value(const YamlFile& scene_file, const std::string& key);

/// Every file the scene reads: the scene itself, its included parts and vehicle file, profiles,
/// contact and K_ij tables, measured irregularities. Outputs never replace any of them.
[[nodiscard]] std::vector<std::string> scene_inputs(const Scene& scene);

/// What a valid scene asks for that the model does not apply (each a sentence naming the key):
/// `validate` and `run` print them, `run` writes them into its output (attribute `warnings`).
/// Vehicle models: curve gauge widening (the rails are placed at the design gauge;
/// docs/SCENES.md).
[[nodiscard]] std::vector<std::string> scene_warnings(const Scene& scene);

/// For a vehicle scene on designed track: why the run of `t_end` seconds (the scene's speed,
/// acceleration and start position) leaves the track, or empty when it stays on it. Scenes are
/// checked at load; callers that change the speed or duration check again.
[[nodiscard]] std::string track_extent_problem(const Scene& scene, double t_end);

/// Replaces the tangential contact model of a vehicle scene: a new model starts from `options`,
/// a kept one keeps its own and takes from `options` those it does not set. Throws
/// std::invalid_argument starting with `flag` for another model type, an unknown name or bad
/// options.
void override_tangential(Scene& scene, const std::string& name, const std::string& flag,
                         const contact::ModelOptions& options = {});

/// Replaces the normal contact model of a vehicle scene (hertz | semi_hertz). Throws
/// std::invalid_argument starting with `flag` for another model type, an unknown name, or
/// semi_hertz with a geometry that has no profiles (imported, conical).
void override_normal(Scene& scene, const std::string& name, const std::string& flag);

}  // namespace ferro::scenarios
