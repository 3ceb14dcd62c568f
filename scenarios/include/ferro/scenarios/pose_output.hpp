#pragma once
// What `ferrodyn geometry search` writes: the pose and contact points of one wheelset position
// as JSON, or the CSV of a batch of positions to a file or a stream. Outputs in mm, rad, N as in
// the Manchester benchmark files, every field naming its unit.

#include <ostream>
#include <string>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/scenarios/pose_search.hpp"

namespace ferro::scenarios {

/// The pose (y, height [mm], roll, yaw [rad]) and every contact point (side, positions [mm],
/// lead [mm], contact angle [deg], rolling radius [mm], curvatures [1/m], penetration and gap
/// [mm], normal force [N], flange) as indented JSON ending in a newline.
[[nodiscard]] std::string pose_result_json(const contact::WheelRailPair& pair,
                                           const PoseResult& result);

/// search_pose_batch over the CSV file `in_path`, the rows written to `out_path` ("-":
/// `standard_output`). The file is claimed first (an existing file only with `overwrite`; the
/// input is never written), opened once the input's header is good, and given its name when
/// complete. Throws std::invalid_argument when the input cannot be opened ("--batch: ..."),
/// std::runtime_error when `standard_output` fails.
void write_pose_batch(const contact::WheelRailPair& pair, const std::string& in_path,
                      const std::string& out_path, const PoseInput& defaults, double estar,
                      bool overwrite, std::ostream& standard_output);

/// `geometry search`: the pair of `options` (make_search_pair; E* from its shear modulus and
/// Poisson ratio); with `batch` empty the contact points of `pose` as JSON (pose_result_json) on
/// `standard_output`, else write_pose_batch of the CSV file `batch` to `out_path`. Throws
/// std::invalid_argument when `pose` gives both a height and a load (named as `spelling` says).
void search_poses(const SearchPairOptions& options, const PoseInput& pose,
                  const std::string& batch, const std::string& out_path, bool overwrite,
                  std::ostream& standard_output, Spelling spelling = Spelling::key);

}  // namespace ferro::scenarios
