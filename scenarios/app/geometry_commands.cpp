// `ferrodyn geometry search`: wheel-rail contact points of a wheelset position as JSON (or CSV in
// batch); `ferrodyn geometry PAIR.yaml`: contact table (HDF5), contact-point diagram data,
// delta_r(y) and equivalent conicity (CSV), plots via tools/geometry_plot.py.
//
// Units on the command line and in the outputs: mm, rad, N (as in the Manchester benchmark
// files); every option and field says its unit in its name.

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ferro/contact/geometry/contact_table.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/scenarios/pair_file.hpp"
#include "ferro/scenarios/plotting.hpp"

namespace ferro::cli {
namespace {

namespace fc = ferro::contact;

struct PairOptions {
  std::string wheel, rail;
  double gauge_mm = 1435.0, gauge_depth_mm = 14.0, flange_back_mm = 1360.0;
  double flange_back_y_mm = std::numeric_limits<double>::quiet_NaN();
  double radius_mm = 460.0;
  std::string inclination = "0";
  double section_step_mm = 0.5;
};

fc::WheelRailPair make_pair(const PairOptions& o) {
  fc::WheelRailPairParams p;
  p.track_gauge = o.gauge_mm * 1e-3;
  p.gauge_depth = o.gauge_depth_mm * 1e-3;
  p.flange_back_distance = o.flange_back_mm * 1e-3;
  p.flange_back_y = o.flange_back_y_mm * 1e-3;
  p.nominal_radius = o.radius_mm * 1e-3;
  p.rail_inclination = scenarios::parse_inclination(o.inclination, "--inclination");
  p.section_step = o.section_step_mm * 1e-3;
  return fc::WheelRailPair(fc::read_profile(o.wheel, fc::ProfileKind::wheel),
                           fc::read_profile(o.rail, fc::ProfileKind::rail), p);
}

struct PoseInput {
  double y_mm = 0.0, roll_rad = 0.0, yaw_rad = 0.0;
  double height_mm = std::numeric_limits<double>::quiet_NaN();  // axle drop, + down
  double load_n = std::numeric_limits<double>::quiet_NaN();     // total vertical load
};

struct PoseResult {
  fc::WheelsetPose pose;
  std::vector<fc::ContactPoint> points;
};

PoseResult solve_pose(const fc::WheelRailPair& pair, const PoseInput& in, double estar) {
  fc::WheelsetPose pose{in.y_mm * 1e-3, 0.0, in.roll_rad, in.yaw_rad};
  if (std::isfinite(in.load_n)) {
    const fc::LoadedWheelset lw = fc::solve_vertical_load(pair, pose, in.load_n, estar);
    return {lw.pose, lw.points};
  }
  if (std::isfinite(in.height_mm)) {
    pose.vertical = in.height_mm * 1e-3;
    return {pose, fc::search_contacts(pair, pose)};
  }
  // Neither: rigid contact (just touching; roll solved unless given non-zero).
  if (in.roll_rad == 0.0) {
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

double lead_of(const fc::WheelRailPair& pair, const fc::WheelsetPose& pose,
               const fc::ContactPoint& p) {
  const double sgn = p.side == fc::Side::right ? 1.0 : -1.0;
  const double Y = sgn * (pair.wheel_offset() + p.wheel_y);
  return p.x + std::sin(pose.yaw) * std::cos(pose.roll) * Y;
}

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
      p.y * 1e3, p.z * 1e3, lead_of(pair, pose, p) * 1e3,
      p.contact_angle * 180.0 / std::numbers::pi, p.rolling_radius * 1e3, p.curvature_a,
      p.curvature_b, p.penetration * 1e3, p.vertical_gap * 1e3, p.normal_force,
      p.on_flange() ? 1 : 0);
}

std::string result_json(const fc::WheelRailPair& pair, const PoseResult& r) {
  std::ostringstream os;
  os << fmt::format(
      "{{\n  \"pose\": {{\"y_mm\": {:.6f}, \"height_mm\": {:.6f}, \"roll_rad\": {:.9g}, "
      "\"yaw_rad\": {:.9g}}},\n  \"points\": [",
      r.pose.lateral * 1e3, r.pose.vertical * 1e3, r.pose.roll, r.pose.yaw);
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const fc::ContactPoint& p = r.points[i];
    os << (i ? ",\n" : "\n")
       << fmt::format(
              "    {{\"side\": \"{}\", \"wheel_y_mm\": {:.6f}, \"rail_y_mm\": {:.6f}, "
              "\"track_x_mm\": {:.6f}, \"track_y_mm\": {:.6f}, \"track_z_mm\": {:.6f}, "
              "\"lead_mm\": {:.6f}, "
              "\"contact_angle_deg\": {:.6f}, \"rolling_radius_mm\": {:.6f}, "
              "\"curvature_a_per_m\": {:.6g}, \"curvature_b_per_m\": {:.6g}, "
              "\"penetration_mm\": {:.6e}, \"vertical_gap_mm\": {:.6e}, "
              "\"normal_force_n\": {:.3f}, \"flange\": {}}}",
              p.side == fc::Side::left ? "left" : "right", p.wheel_y * 1e3, p.rail_y * 1e3,
              p.x * 1e3, p.y * 1e3, p.z * 1e3, lead_of(pair, r.pose, p) * 1e3,
              p.contact_angle * 180.0 / std::numbers::pi, p.rolling_radius * 1e3, p.curvature_a,
              p.curvature_b, p.penetration * 1e3, p.vertical_gap * 1e3, p.normal_force,
              p.on_flange() ? "true" : "false");
  }
  os << "\n  ]\n}\n";
  return os.str();
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) {
    const auto b = cell.find_first_not_of(" \t\r");
    const auto e = cell.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
  }
  return out;
}

int run_batch(const fc::WheelRailPair& pair, const std::string& in_path,
              const std::string& out_path, const PoseInput& defaults, double estar) {
  std::ifstream in(in_path);
  if (!in) throw std::invalid_argument(fmt::format("--batch: cannot open '{}'", in_path));
  std::string line;
  int line_no = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line[0] != '#') header = split_csv(line);
  }
  const std::map<std::string, double PoseInput::*> known{{"y_mm", &PoseInput::y_mm},
                                                         {"roll_rad", &PoseInput::roll_rad},
                                                         {"yaw_rad", &PoseInput::yaw_rad},
                                                         {"height_mm", &PoseInput::height_mm},
                                                         {"load_n", &PoseInput::load_n}};
  std::vector<double PoseInput::*> cols;
  bool has_y = false;
  for (const auto& h : header) {
    const auto it = known.find(h);
    cols.push_back(it == known.end() ? nullptr : it->second);
    has_y = has_y || h == "y_mm";
  }
  if (!has_y) {
    throw std::invalid_argument(fmt::format(
        "{}:{}: header needs a 'y_mm' column (known: y_mm, roll_rad, yaw_rad, height_mm, "
        "load_n; other columns are copied to the output)",
        in_path, line_no));
  }
  std::ofstream out_file;
  if (out_path != "-") {
    out_file.open(out_path);
    if (!out_file) throw std::runtime_error(fmt::format("--out: cannot write '{}'", out_path));
  }
  std::ostream& out = out_path == "-" ? std::cout : out_file;
  std::string echo_header;
  for (const auto& h : header) echo_header += h + ",";
  out << echo_header << "solved_height_mm,solved_roll_rad," << kCsvPointHeader << "\n";
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    const auto cells = split_csv(line);
    if (cells.size() != header.size()) {
      throw std::invalid_argument(fmt::format("{}:{}: expected {} columns, got {}", in_path,
                                              line_no, header.size(), cells.size()));
    }
    PoseInput pin = defaults;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (!cols[c]) continue;
      try {
        pin.*cols[c] = std::stod(cells[c]);
      } catch (const std::exception&) {
        throw std::invalid_argument(fmt::format("{}:{}: column '{}': '{}' is not a number", in_path,
                                                line_no, header[c], cells[c]));
      }
      if (!std::isfinite(pin.*cols[c])) {
        throw std::invalid_argument(fmt::format("{}:{}: column '{}': '{}' is not a finite number",
                                                in_path, line_no, header[c], cells[c]));
      }
    }
    const PoseResult r = solve_pose(pair, pin, estar);
    std::string echo;
    for (const auto& c : cells) echo += c + ",";
    const std::string solved = fmt::format("{:.6f},{:.9g},", r.pose.vertical * 1e3, r.pose.roll);
    if (r.points.empty()) out << echo << solved << "none" << std::string(14, ',') << "\n";
    for (const auto& p : r.points) out << echo << solved << point_csv(pair, r.pose, p) << "\n";
  }
  return kExitOk;
}

// --- PAIR.yaml: tables, diagram data, conicity, plots -------------------------------------

int run_pair_report(const std::string& yaml_path, const std::string& out_dir, bool plot) {
  const fc::WheelRailPair pair =
      scenarios::make_wheel_rail_pair(scenarios::load_pair_file(yaml_path));
  std::filesystem::create_directories(out_dir);
  const std::filesystem::path dir(out_dir);

  fc::ContactTableParams tp;
  tp.lateral_min = -12e-3;
  tp.lateral_max = 12e-3;
  tp.lateral_step = 0.1e-3;
  const fc::ContactTable table = fc::ContactTable::build(pair, tp);
  table.save_hdf5((dir / "contact_table.h5").string());

  // Contact-point diagram and delta_r(y).
  std::ofstream diag(dir / "contact_points.csv");
  diag << "y_mm,delta_r_mm,roll_rad,left_wheel_y_mm,left_rail_y_mm,left_angle_deg,"
          "right_wheel_y_mm,right_rail_y_mm,right_angle_deg,right_radius_mm,left_radius_mm\n";
  std::vector<double> ys, dr;
  for (std::size_t i = 0; i < table.lateral().size(); ++i) {
    const double y = table.lateral()[i];
    const fc::ContactTableEntry e = table.lookup(y);
    ys.push_back(y);
    dr.push_back(e.delta_r);
    diag << fmt::format(
        "{:.4f},{:.6f},{:.9g},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f}\n", y * 1e3,
        e.delta_r * 1e3, e.roll, e.wheel_y[0] * 1e3, e.rail_y[0] * 1e3,
        e.contact_angle[0] * 180.0 / std::numbers::pi, e.wheel_y[1] * 1e3, e.rail_y[1] * 1e3,
        e.contact_angle[1] * 180.0 / std::numbers::pi, e.rolling_radius[1] * 1e3,
        e.rolling_radius[0] * 1e3);
  }
  std::ofstream con(dir / "conicity.csv");
  con << "amplitude_mm,equivalent_conicity\n";
  for (int k = 1; k <= 20; ++k) {
    const double a = 0.5e-3 * k;
    con << fmt::format("{:.2f},{:.6f}\n", a * 1e3, fc::equivalent_conicity(ys, dr, a));
  }
  // Profiles in track coordinates for the diagram (right side).
  std::ofstream prof(dir / "profiles.csv");
  prof << "kind,y_mm,z_mm\n";
  for (std::size_t i = 0; i < pair.wheel_profile().size(); ++i) {
    prof << fmt::format("wheel,{:.5f},{:.5f}\n", pair.wheel_profile().y[i] * 1e3,
                        pair.wheel_profile().z[i] * 1e3);
  }
  for (std::size_t i = 0; i < pair.rail_profile().size(); ++i) {
    prof << fmt::format("rail,{:.5f},{:.5f}\n", pair.rail_profile().y[i] * 1e3,
                        (pair.rail_profile().z[i] - pair.rail_reference().top_z) * 1e3);
  }
  diag.close();
  con.close();
  prof.close();
  fmt::print("wrote {}/contact_table.h5, contact_points.csv, conicity.csv, profiles.csv\n",
             out_dir);
  std::fflush(stdout);
  if (plot) {
    if (scenarios::run_python_tool("geometry_plot.py", {out_dir}) != 0) {
      throw std::runtime_error(fmt::format(
          "plotting failed ({} tools/geometry_plot.py {}); the CSV files are written",
          scenarios::python_program(), out_dir));
    }
  }
  return kExitOk;
}

// Numeric options must be finite: "nan" or "inf" is bad input, not a position.
const CLI::Validator kFiniteNumber(
    [](std::string& text) {
      try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used == text.size() && std::isfinite(v)) return std::string();
      } catch (const std::exception&) {
      }
      return fmt::format("expected a finite number, got '{}'", text);
    },
    "FINITE");

}  // namespace

void add_geometry_commands(CLI::App& app, VerbHandler& handler) {
  CLI::App* geo =
      app.add_subcommand("geometry",
                         "Wheel-rail contact geometry: 'geometry PAIR.yaml' (tables, diagram, "
                         "conicity, plots) or 'geometry search'");
  geo->require_subcommand(0, 1);
  auto pair_yaml = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>("geometry_out");
  auto no_plot = std::make_shared<bool>(false);
  geo->add_option("pair", *pair_yaml,
                  "PAIR.yaml (track: gauge, gauge_height, rail_profile, [rail_inclination]; "
                  "wheelset: wheel_profile, flange_back_distance, flange_back_position, "
                  "nominal_radius; mm; the Manchester benchmark file works as is)");
  geo->add_option("--out-dir", *out_dir, "output directory")->capture_default_str();
  geo->add_flag("--no-plot", *no_plot, "write the data files only");

  CLI::App* search = geo->add_subcommand(
      "search", "Every wheel-rail contact point of one wheelset position, as JSON");
  auto po = std::make_shared<PairOptions>();
  auto pin = std::make_shared<PoseInput>();
  auto batch = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>("-");
  auto shear_mpa = std::make_shared<double>(82000.0);
  auto poisson = std::make_shared<double>(0.28);
  search->add_option("--wheel", po->wheel, "wheel profile (.prw or two-column mm)")->required();
  search->add_option("--rail", po->rail, "rail profile (.prr or two-column mm)")->required();
  search->add_option("--gauge-mm", po->gauge_mm, "track gauge")
      ->check(kFiniteNumber)
      ->capture_default_str();
  search->add_option("--gauge-depth-mm", po->gauge_depth_mm, "gauge measured below top of rail")
      ->check(kFiniteNumber)
      ->capture_default_str();
  search
      ->add_option("--inclination", po->inclination,
                   "rail inclination applied to the rail file: 1:40, 1:20, 0 or an angle in rad")
      ->capture_default_str();
  search->add_option("--flange-back-mm", po->flange_back_mm, "flange-back distance")
      ->check(kFiniteNumber)
      ->capture_default_str();
  search
      ->add_option("--flange-back-y-mm", po->flange_back_y_mm,
                   "flange-back position in wheel-profile coordinates (default: first point)")
      ->check(kFiniteNumber);
  search->add_option("--radius-mm", po->radius_mm, "nominal wheel radius at the taping line")
      ->check(kFiniteNumber)
      ->capture_default_str();
  search->add_option("--section-step-mm", po->section_step_mm, "wheel section spacing")
      ->check(kFiniteNumber)
      ->capture_default_str();
  search->add_option("--y-mm", pin->y_mm, "lateral shift, + to the right")
      ->check(kFiniteNumber)
      ->capture_default_str();
  search
      ->add_option("--roll-rad", pin->roll_rad,
                   "roll, + lowers the right wheel (0 with "
                   "neither --height-mm nor --load-n: solved for rigid contact)")
      ->check(kFiniteNumber);
  search->add_option("--yaw-rad", pin->yaw_rad, "yaw, + turns the front to the right")
      ->check(kFiniteNumber);
  auto* h =
      search->add_option("--height-mm", pin->height_mm, "axle-centre drop below nominal (+ down)")
          ->check(kFiniteNumber);
  search->add_option("--load-n", pin->load_n, "total vertical load: solve the height (Hertz)")
      ->check(kFiniteNumber)
      ->excludes(h);
  search->add_option("--shear-modulus-mpa", *shear_mpa, "for --load-n")
      ->check(kFiniteNumber)
      ->capture_default_str();
  search->add_option("--poisson", *poisson, "for --load-n")
      ->check(kFiniteNumber)
      ->capture_default_str();
  search->add_option("--batch", *batch,
                     "CSV in (header with y_mm and optional roll_rad, yaw_rad, height_mm, "
                     "load_n): one CSV row per contact point out");
  search->add_option("--out", *out, "batch output CSV ('-' = stdout)")->capture_default_str();

  search->callback([&handler, po, pin, batch, out, shear_mpa, poisson] {
    handler = [po, pin, batch, out, shear_mpa, poisson] {
      const double e = 2.0 * (*shear_mpa) * 1e6 * (1.0 + *poisson);
      const double estar = e / (2.0 * (1.0 - (*poisson) * (*poisson)));
      const fc::WheelRailPair pair = make_pair(*po);
      if (!batch->empty()) return run_batch(pair, *batch, *out, *pin, estar);
      fmt::print("{}", result_json(pair, solve_pose(pair, *pin, estar)));
      return kExitOk;
    };
  });
  geo->callback([&handler, geo, search, pair_yaml, out_dir, no_plot] {
    if (search->parsed()) return;
    if (pair_yaml->empty()) {
      throw CLI::ValidationError("geometry", "give PAIR.yaml or the 'search' subcommand");
    }
    handler = [pair_yaml, out_dir, no_plot] {
      return run_pair_report(*pair_yaml, *out_dir, !*no_plot);
    };
    (void)geo;
  });
}

}  // namespace ferro::cli
