#include "ferro/scenarios/pose_output.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "ferro/io/text_writer.hpp"
#include "ferro/scenarios/output_file.hpp"

namespace ferro::scenarios {

namespace fc = ferro::contact;

std::string pose_result_json(const fc::WheelRailPair& pair, const PoseResult& r) {
  nlohmann::ordered_json j;
  j["pose"] = {{"y_mm", r.pose.lateral * 1e3},
               {"height_mm", r.pose.vertical * 1e3},
               {"roll_rad", r.pose.roll},
               {"yaw_rad", r.pose.yaw}};
  j["points"] = nlohmann::ordered_json::array();
  for (const fc::ContactPoint& p : r.points) {
    nlohmann::ordered_json q;
    q["side"] = p.side == fc::Side::left ? "left" : "right";
    q["wheel_y_mm"] = p.wheel_y * 1e3;
    q["rail_y_mm"] = p.rail_y * 1e3;
    q["track_x_mm"] = p.x * 1e3;
    q["track_y_mm"] = p.y * 1e3;
    q["track_z_mm"] = p.z * 1e3;
    q["lead_mm"] = contact_lead(pair, r.pose, p) * 1e3;
    q["contact_angle_deg"] = p.contact_angle * 180.0 / std::numbers::pi;
    q["rolling_radius_mm"] = p.rolling_radius * 1e3;
    q["curvature_a_per_m"] = p.curvature_a;
    q["curvature_b_per_m"] = p.curvature_b;
    q["penetration_mm"] = p.penetration * 1e3;
    q["vertical_gap_mm"] = p.vertical_gap * 1e3;
    q["normal_force_n"] = p.normal_force;
    q["flange"] = p.on_flange();
    j["points"].push_back(std::move(q));
  }
  return j.dump(2) + "\n";
}

void write_pose_batch(const fc::WheelRailPair& pair, const std::string& in_path,
                      const std::string& out_path, const PoseInput& defaults, double estar,
                      bool overwrite, std::ostream& standard_output) {
  std::ifstream in(in_path);
  if (!in) throw std::invalid_argument(fmt::format("--batch: cannot open '{}'", in_path));
  std::optional<OutputSet> outputs;
  OutputFile* claimed = nullptr;
  if (out_path != "-") {
    outputs.emplace(OutputRules{overwrite, {in_path}});
    claimed = &outputs->claim(out_path, "-o");
  }
  std::optional<io::TextWriter> out_file;  // opened once the input's header is good
  search_pose_batch(pair, in, in_path, defaults, estar, [&](const std::string& rows) {
    if (claimed != nullptr && !out_file) out_file.emplace(claimed->write_path());
    if (out_file) {
      out_file->write(rows);
    } else {
      standard_output << rows;
      if (!standard_output) throw std::runtime_error("cannot write the standard output");
    }
  });
  if (out_file) {
    out_file->close();
    claimed->commit();
  }
  standard_output.flush();
}

void search_poses(const SearchPairOptions& options, const PoseInput& pose,
                  const std::string& batch, const std::string& out_path, bool overwrite,
                  std::ostream& standard_output, Spelling spelling) {
  const std::string height = spelled("height", spelling), load = spelled("load", spelling);
  if (!std::isnan(pose.height) && !std::isnan(pose.load))
    throw std::invalid_argument(fmt::format("{}: give {} or {}, not both", height, height, load));
  const double estar = pose_search_modulus(options.shear_modulus, options.poisson);
  const contact::WheelRailPair pair =
      make_search_pair(options, spelled("inclination", spelling));
  if (batch.empty()) {
    standard_output << pose_result_json(pair, solve_pose(pair, pose, estar));
  } else {
    write_pose_batch(pair, batch, out_path, pose, estar, overwrite, standard_output);
  }
}

}  // namespace ferro::scenarios
