#pragma once
// A wheel-rail pair file (YAML, lengths in mm): the track (gauge, gauge height, rail profile,
// rail inclination) and the wheelset (wheel profile, flange-back distance and position, nominal
// radius). Read by `ferrodyn geometry PAIR.yaml` and by any caller that needs the pair.
//
// The format is that of the Manchester contact benchmark's published input file
// (data/manchester_contact_benchmark_a22.yaml). That file is external data and carries no
// schema_version, so the key is optional here; when given it must be kPairSchemaVersion. The
// benchmark's case-description keys (cant, vertical_load_per_wheel, forward_speed, material,
// friction, discretisation_hint, cases) are accepted and not used by the pair; any other
// unknown key is an error.

#include <string>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::scenarios {

inline constexpr long kPairSchemaVersion = 1;

struct PairFile {
  std::string path;
  std::string wheel_profile;            ///< resolved against the pair file's folder
  std::string rail_profile;             ///< resolved against the pair file's folder
  contact::WheelRailPairParams params;  ///< SI
};

/// "1:40" -> atan(1/40); "0" -> 0; a plain number is an angle in rad. `where` names the
/// option or key in the error message.
[[nodiscard]] double parse_inclination(const std::string& text, const std::string& where);

/// Reads and validates a pair file; YamlInputError (std::invalid_argument) names the file,
/// line and key on bad input.
[[nodiscard]] PairFile load_pair_file(const std::string& path);

/// Reads the two profiles of a pair file and builds the pair; profile errors name the profile
/// file, parameter errors the pair file.
[[nodiscard]] contact::WheelRailPair make_wheel_rail_pair(const PairFile& pair);

}  // namespace ferro::scenarios
