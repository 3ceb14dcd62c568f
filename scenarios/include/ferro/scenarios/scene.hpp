#pragma once
// A scene: the top-level YAML file of a run. It names or embeds five parts -- model, track,
// contact, solver, output -- plus the simulation and analysis settings. Each part may be written
// inline or given as a file name (relative to the scene), and every file carries
// `schema_version`. Layout and keys: docs/SCENES.md.

#include <limits>
#include <map>
#include <string>
#include <vector>

#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/suspended_wheelset.hpp"

namespace ferro::scenarios {

inline constexpr int kSceneSchemaVersion = 1;

struct ModelConfig {
  std::string type = "suspended_wheelset";  ///< the only model type so far
  vehicle::SuspendedWheelsetParams wheelset;
};

struct TrackConfig {
  std::string type = "straight";  ///< straight, tangent track without irregularities
};

struct ContactConfig {
  vehicle::LinearCreepParams creep;  ///< ellipse, materials, coefficient source, K11, K22
};

struct SimulationConfig {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double speed = kNaN;                    ///< forward speed V [m/s]
  double t_end = kNaN;                    ///< end time [s]
  std::map<std::string, double> initial;  ///< initial state by state name (others 0) [SI]
};

struct OutputConfig {
  std::string file = "out/run.h5";  ///< HDF5 path (relative to the working directory)
  double interval = 1e-3;           ///< output sampling interval [s]
  double flush_seconds = 0.5;       ///< flush to disk at least this often (wall clock) [s]
  std::vector<std::string> csv;     ///< signals also written to CSV ("all" for every one)
  std::vector<std::string> plots;   ///< signals plotted by `ferrodyn run` (empty: the states)
};

struct EigenConfig {
  double speed_min = 1.0;    ///< [m/s]
  double speed_max = 150.0;  ///< [m/s]
  int points = 150;          ///< speeds in the sweep
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
};

/// Loads and validates a scene. Throws YamlInputError (file:line:col: key: message) for any bad
/// input, including values that fail the parameter structs' validate().
[[nodiscard]] Scene load_scene(const std::string& path);

}  // namespace ferro::scenarios
