#pragma once
// The `track` part of a scene: design alignment (straight, clothoid transition, circular
// curve), cant, gauge, rail inclination and irregularities (stochastic from a PSD, measured
// file, isolated defects, summed), read from YAML into the track library's parameter structs and
// built into a track::Track. Keys: docs/SCENES.md.

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ferro/scenarios/yaml_reader.hpp"
#include "ferro/track/design.hpp"
#include "ferro/track/irregularity.hpp"
#include "ferro/track/stochastic_irregularity.hpp"
#include "ferro/track/track.hpp"
#include "ferro/track/track_structure.hpp"

namespace ferro::scenarios {

/// One irregularity source of the sum.
struct IrregularityConfig {
  std::string type;  ///< stochastic | measured | defect
  track::StochasticIrregularitySpec stochastic;
  std::string measured_file;  ///< resolved path of the CSV (type measured)
  track::IsolatedDefectSpec defect;
};

struct TrackConfig {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  /// straight: perfect straight track without end (no track object); design: the sections.
  std::string type = "straight";
  track::TrackDesign design;  ///< sections, start, gauge, rail spacing (type design)
  /// Nominal gauge [m] and rail inclination applied to the rail profile as read [rad]; NaN:
  /// the vehicle file's values.
  double gauge = kNaN;
  double rail_inclination = kNaN;
  std::vector<IrregularityConfig> irregularities;
  /// What the wheels run on (`track.structure`): a co-running discrete track under every
  /// wheelset with the default ballasted track unless the scene says otherwise.
  track::TrackStructureSpec structure{track::TrackStructureSpec::Kind::discrete, {}};
};

/// Reads a track part. Relative file names (measured irregularities) are resolved against the
/// directory of the file `r` reads from. Throws YamlInputError at the offending key, including
/// values the track library rejects (e.g. a curve without radius).
[[nodiscard]] TrackConfig read_track(MapReader& r);

/// The track of a design config (null for type straight: the vehicle model then runs on a
/// perfect straight track). Throws std::invalid_argument for a measured file that cannot be
/// read.
[[nodiscard]] std::shared_ptr<const track::Track> build_track(const TrackConfig& config);

}  // namespace ferro::scenarios
