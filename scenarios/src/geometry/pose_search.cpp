// Contact points of prescribed wheelset positions (see the header).
#include "ferro/scenarios/pose_search.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "ferro/io/csv.hpp"
#include "ferro/scenarios/pair_file.hpp"

namespace ferro::scenarios {
namespace {

namespace fc = ferro::contact;

constexpr const char* kCsvPointHeader =
    "side,wheel_y_mm,rail_y_mm,track_x_mm,track_y_mm,track_z_mm,lead_mm,contact_angle_deg,rolling_"
    "radius_mm,"
    "curvature_a_per_m,curvature_b_per_m,penetration_mm,vertical_gap_mm,normal_force_n,flange";

std::string point_csv(const fc::WheelRailPair& pair, const fc::WheelsetPose& pose,
                      const fc::ContactPoint& p) {
  return fmt::format(
      "{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6g},{:.6g},{:.6e},{:.6e},{:."
      "3f},{}",
      p.side == fc::Side::left ? "left" : "right", p.wheel_y * 1e3, p.rail_y * 1e3, p.x * 1e3,
      p.y * 1e3, p.z * 1e3, contact_lead(pair, pose, p) * 1e3,
      p.contact_angle * 180.0 / std::numbers::pi, p.rolling_radius * 1e3, p.curvature_a,
      p.curvature_b, p.penetration * 1e3, p.vertical_gap * 1e3, p.normal_force,
      p.on_flange() ? 1 : 0);
}

// Column -> the pose parameter it sets (index into parameters(PoseInput&)) and the factor to SI:
// a parameter's key, or its former key in other units (y_mm, ...).
struct Column {
  std::size_t parameter = kNone;
  double to_si = 1.0;
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
};

std::vector<Column> pose_columns(const io::CsvReader& reader) {
  PoseInput probe;
  const Parameters known = parameters(probe);
  std::vector<Column> cols;
  for (const auto& h : reader.header()) {
    Column col;
    for (std::size_t i = 0; i < known.size(); ++i) {
      if (known[i].key == h) col = {i, 1.0};
      if (known[i].former && known[i].former->key == h) col = {i, known[i].former->to_si};
    }
    cols.push_back(col);
  }
  if (!reader.has_column("y") && !reader.has_column("y_mm")) {
    throw std::invalid_argument(reader.located(
        "header needs a 'y' [m] or 'y_mm' column (known: y, roll, yaw, height, load in SI; y_mm, "
        "roll_rad, yaw_rad, height_mm, load_n; other columns are copied to the output)"));
  }
  return cols;
}

}  // namespace

fc::WheelRailPair make_search_pair(const SearchPairOptions& o,
                                   const std::string& inclination_name) {
  // Finer wheel sections than this resolve nothing the profiles' 0.05 mm grid does not, and
  // cost memory and time in proportion [m].
  constexpr double kFinestSectionStep = 1e-5;
  if (!(o.section_step >= kFinestSectionStep)) {
    // Named as the inclination is: a command-line option or a key.
    const bool option = inclination_name.rfind("--", 0) == 0;
    throw std::invalid_argument(fmt::format(
        "{}: must be >= {} m (the profiles are resampled every 0.05 mm), got {}",
        option ? "--section-step" : "section_step", kFinestSectionStep, o.section_step));
  }
  fc::WheelRailPairParams p;
  p.track_gauge = o.gauge;
  p.gauge_depth = o.gauge_depth;
  p.flange_back_distance = o.flange_back;
  p.flange_back_y = o.flange_back_y;
  p.nominal_radius = o.radius;
  p.rail_inclination = parse_inclination(o.inclination, inclination_name);
  p.section_step = o.section_step;
  return fc::WheelRailPair(fc::read_profile(o.wheel, fc::ProfileKind::wheel),
                           fc::read_profile(o.rail, fc::ProfileKind::rail), p);
}

double pose_search_modulus(double shear_modulus, double poisson) {
  const double e = 2.0 * shear_modulus * (1.0 + poisson);
  return e / (2.0 * (1.0 - poisson * poisson));
}

Parameters parameters(SearchPairOptions& o) {
  return {
      {"wheel", "", "wheel profile (.prw or two-column mm)", &o.wheel, false},
      {"rail", "", "rail profile (.prr or two-column mm)", &o.rail, false},
      Parameter{"gauge", "m", "track gauge", &o.gauge}.formerly("gauge_mm", 1e-3),
      Parameter{"gauge_depth", "m", "gauge measured below top of rail", &o.gauge_depth}
          .formerly("gauge_depth_mm", 1e-3),
      {"inclination", "", "rail inclination applied to the rail file: 1:40, 1:20, 0 or an "
       "angle in rad", &o.inclination},
      Parameter{"flange_back", "m", "flange-back distance", &o.flange_back}.formerly(
          "flange_back_mm", 1e-3),
      Parameter{"flange_back_y", "m",
                "flange-back position in wheel-profile coordinates (default: first point)",
                &o.flange_back_y, false}
          .formerly("flange_back_y_mm", 1e-3),
      Parameter{"radius", "m", "nominal wheel radius at the taping line", &o.radius}.formerly(
          "radius_mm", 1e-3),
      Parameter{"section_step", "m", "wheel section spacing", &o.section_step}.formerly(
          "section_step_mm", 1e-3),
      Parameter{"shear_modulus", "Pa", "for a load", &o.shear_modulus}.formerly(
          "shear_modulus_mpa", 1e6),
      {"poisson", "-", "for a load", &o.poisson},
  };
}

Parameters parameters(PoseInput& in) {
  return {
      Parameter{"y", "m", "lateral shift, + to the right", &in.y}.formerly("y_mm", 1e-3),
      Parameter{"roll", "rad",
                "+ lowers the right wheel (0 with neither height nor load: solved for rigid "
                "contact)",
                &in.roll, false}
          .formerly("roll_rad"),
      Parameter{"yaw", "rad", "+ turns the front to the right", &in.yaw, false}.formerly(
          "yaw_rad"),
      Parameter{"height", "m", "axle-centre drop below nominal (+ down)", &in.height, false}
          .formerly("height_mm", 1e-3),
      Parameter{"load", "N", "total vertical load: solve the height (Hertz)", &in.load, false}
          .formerly("load_n"),
  };
}

PoseResult solve_pose(const fc::WheelRailPair& pair, const PoseInput& in, double estar) {
  fc::WheelsetPose pose{in.y, 0.0, in.roll, in.yaw};
  if (std::isfinite(in.load)) {
    const fc::LoadedWheelset lw = fc::solve_vertical_load(pair, pose, in.load, estar);
    return {lw.pose, lw.points};
  }
  if (std::isfinite(in.height)) {
    pose.vertical = in.height;
    return {pose, fc::search_contacts(pair, pose)};
  }
  // Neither: rigid contact (just touching; roll solved unless given non-zero).
  if (in.roll == 0.0) {
    const fc::RigidContact rc = fc::solve_rigid_contact(pair, pose.lateral, pose.yaw);
    return {rc.pose, rc.points};
  }
  pose = fc::touching_pose(pair, pose);
  std::vector<fc::ContactPoint> pts;
  for (fc::Side s : {fc::Side::left, fc::Side::right}) {
    for (const auto& p : fc::candidate_points(pair, pose, s)) {
      if (p.vertical_gap < 1e-9) pts.push_back(p);
    }
  }
  return {pose, pts};
}

double contact_lead(const fc::WheelRailPair& pair, const fc::WheelsetPose& pose,
                    const fc::ContactPoint& p) {
  // The point's distance ahead of its wheel section's centre, which sits Y along the axle.
  const double Y = fc::side_sign(p.side) * (pair.wheel_offset() + p.wheel_y);
  return p.x - fc::WheelsetFrame(pose, pair.params().nominal_radius).axle().x() * Y;
}

void search_pose_batch(const fc::WheelRailPair& pair, std::istream& in, const std::string& source,
                       const PoseInput& defaults, double estar,
                       const std::function<void(const std::string&)>& emit) {
  io::CsvReader reader(in, source);
  const std::vector<Column> cols = pose_columns(reader);
  std::string echo_header;
  for (const auto& h : reader.header()) echo_header += h + ",";
  emit(echo_header + "solved_height_mm,solved_roll_rad," + kCsvPointHeader + "\n");
  std::vector<std::string> cells;
  std::ostringstream out;  // one input row's lines at a time
  while (reader.next(cells)) {
    PoseInput pin = defaults;
    const Parameters fields = parameters(pin);
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (cols[c].parameter == Column::kNone) continue;
      *std::get<double*>(fields[cols[c].parameter].target) =
          reader.number(cells, c) * cols[c].to_si;
    }
    const PoseResult r = solve_pose(pair, pin, estar);
    std::string echo;
    for (const auto& c : cells) echo += c + ",";
    const std::string solved = fmt::format("{:.6f},{:.9g},", r.pose.vertical * 1e3, r.pose.roll);
    if (r.points.empty()) out << echo << solved << "none" << std::string(14, ',') << "\n";
    for (const auto& p : r.points) out << echo << solved << point_csv(pair, r.pose, p) << "\n";
    emit(out.str());
    out.str("");
  }
}

}  // namespace ferro::scenarios
