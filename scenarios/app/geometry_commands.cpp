// `ferrodyn geometry search`: wheel-rail contact points of a wheelset position as JSON (or CSV in
// batch); `ferrodyn geometry PAIR.yaml`: contact table (HDF5), contact-point diagram data,
// delta_r(y) and equivalent conicity (CSV), plots via tools/geometry_plot.py.
//
// Units: SI on the command line (m, rad, N, Pa; the former millimetre spellings --y-mm,
// --height-mm, --gauge-mm ... stay as hidden aliases) and in the batch columns y, roll, yaw, height,
// load (y_mm, height_mm, roll_rad, yaw_rad, load_n also read); the outputs are in mm, rad, N as in
// the Manchester benchmark files, every field naming its unit.

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ferro/contact/geometry/contact_table.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/io/csv.hpp"
#include "ferro/io/text_writer.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/pair_file.hpp"
#include "ferro/scenarios/plotting.hpp"

namespace ferro::cli {
namespace {

namespace fc = ferro::contact;

struct PairOptions {  // SI
  std::string wheel, rail;
  double gauge = 1.435, gauge_depth = 0.014, flange_back = 1.360;
  double flange_back_y = std::numeric_limits<double>::quiet_NaN();
  double radius = 0.460;
  std::string inclination = "0";
  double section_step = 0.5e-3;
};

// Finer wheel sections than this resolve nothing the profiles' 0.05 mm grid does not, and cost
// memory and time in proportion [m].
constexpr double kFinestSectionStep = 1e-5;

fc::WheelRailPair make_pair(const PairOptions& o) {
  if (!(o.section_step >= kFinestSectionStep)) {
    throw std::invalid_argument(fmt::format(
        "--section-step: must be >= {} m (the profiles are resampled every 0.05 mm), got {}",
        kFinestSectionStep, o.section_step));
  }
  fc::WheelRailPairParams p;
  p.track_gauge = o.gauge;
  p.gauge_depth = o.gauge_depth;
  p.flange_back_distance = o.flange_back;
  p.flange_back_y = o.flange_back_y;
  p.nominal_radius = o.radius;
  p.rail_inclination = scenarios::parse_inclination(o.inclination, "--inclination");
  p.section_step = o.section_step;
  return fc::WheelRailPair(fc::read_profile(o.wheel, fc::ProfileKind::wheel),
                           fc::read_profile(o.rail, fc::ProfileKind::rail), p);
}

struct PoseInput {  // SI
  double y = 0.0, roll = 0.0, yaw = 0.0;
  double height = std::numeric_limits<double>::quiet_NaN();  // axle drop, + down [m]
  double load = std::numeric_limits<double>::quiet_NaN();    // total vertical load [N]
};

struct PoseResult {
  fc::WheelsetPose pose;
  std::vector<fc::ContactPoint> points;
};

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

double lead_of(const fc::WheelRailPair& pair, const fc::WheelsetPose& pose,
               const fc::ContactPoint& p) {
  // The point's distance ahead of its wheel section's centre, which sits Y along the axle.
  const double Y = fc::side_sign(p.side) * (pair.wheel_offset() + p.wheel_y);
  return p.x - fc::WheelsetFrame(pose, pair.params().nominal_radius).axle().x() * Y;
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
    q["lead_mm"] = lead_of(pair, r.pose, p) * 1e3;
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

int run_batch(const fc::WheelRailPair& pair, const std::string& in_path,
              const std::string& out_path, const PoseInput& defaults, double estar,
              bool overwrite) {
  std::ifstream in(in_path);
  if (!in) throw std::invalid_argument(fmt::format("--batch: cannot open '{}'", in_path));
  io::CsvReader reader(in, in_path);
  const std::vector<std::string>& header = reader.header();
  // Column -> pose field and the factor to SI (the mm/unit-suffixed names are read as well).
  struct Column {
    double PoseInput::*field = nullptr;
    double to_si = 1.0;
  };
  const std::map<std::string, Column> known{
      {"y", {&PoseInput::y}},           {"roll", {&PoseInput::roll}},
      {"yaw", {&PoseInput::yaw}},       {"height", {&PoseInput::height}},
      {"load", {&PoseInput::load}},     {"y_mm", {&PoseInput::y, 1e-3}},
      {"roll_rad", {&PoseInput::roll}}, {"yaw_rad", {&PoseInput::yaw}},
      {"height_mm", {&PoseInput::height, 1e-3}}, {"load_n", {&PoseInput::load}}};
  std::vector<Column> cols;
  for (const auto& h : header) {
    const auto it = known.find(h);
    cols.push_back(it == known.end() ? Column{} : it->second);
  }
  if (!reader.has_column("y") && !reader.has_column("y_mm")) {
    throw std::invalid_argument(reader.located(
        "header needs a 'y' [m] or 'y_mm' column (known: y, roll, yaw, height, load in SI; y_mm, "
        "roll_rad, yaw_rad, height_mm, load_n; other columns are copied to the output)"));
  }
  std::optional<scenarios::OutputSet> outputs;
  scenarios::OutputFile* claimed = nullptr;
  if (out_path != "-") {
    outputs.emplace(scenarios::OutputRules{overwrite, {in_path}});
    claimed = &outputs->claim(out_path, "-o");
  }
  std::optional<io::TextWriter> out_file;
  if (claimed != nullptr) out_file.emplace(claimed->write_path());
  std::ostringstream out;  // one output row at a time
  const auto emit = [&] {
    if (out_file) {
      out_file->write(out.str());
    } else {
      std::cout << out.str();
      if (!std::cout) throw std::runtime_error("cannot write the standard output");
    }
    out.str("");
  };
  std::string echo_header;
  for (const auto& h : header) echo_header += h + ",";
  out << echo_header << "solved_height_mm,solved_roll_rad," << kCsvPointHeader << "\n";
  emit();
  std::vector<std::string> cells;
  while (reader.next(cells)) {
    PoseInput pin = defaults;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (cols[c].field) pin.*cols[c].field = reader.number(cells, c) * cols[c].to_si;
    }
    const PoseResult r = solve_pose(pair, pin, estar);
    std::string echo;
    for (const auto& c : cells) echo += c + ",";
    const std::string solved = fmt::format("{:.6f},{:.9g},", r.pose.vertical * 1e3, r.pose.roll);
    if (r.points.empty()) out << echo << solved << "none" << std::string(14, ',') << "\n";
    for (const auto& p : r.points) out << echo << solved << point_csv(pair, r.pose, p) << "\n";
    emit();
  }
  if (out_file) {
    out_file->close();
    claimed->commit();
  }
  std::cout.flush();
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
  io::TextWriter diag((dir / "contact_points.csv").string());
  diag.write("y_mm,delta_r_mm,roll_rad,left_wheel_y_mm,left_rail_y_mm,left_angle_deg,"
          "right_wheel_y_mm,right_rail_y_mm,right_angle_deg,right_radius_mm,left_radius_mm\n");
  std::vector<double> ys, dr;
  for (std::size_t i = 0; i < table.lateral().size(); ++i) {
    const double y = table.lateral()[i];
    const fc::ContactTableEntry e = table.lookup(y);
    ys.push_back(y);
    dr.push_back(e.delta_r);
    diag.print(
        "{:.4f},{:.6f},{:.9g},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f}\n", y * 1e3,
        e.delta_r * 1e3, e.roll, e.wheel_y[0] * 1e3, e.rail_y[0] * 1e3,
        e.contact_angle[0] * 180.0 / std::numbers::pi, e.wheel_y[1] * 1e3, e.rail_y[1] * 1e3,
        e.contact_angle[1] * 180.0 / std::numbers::pi, e.rolling_radius[1] * 1e3,
        e.rolling_radius[0] * 1e3);
  }
  io::TextWriter con((dir / "conicity.csv").string());
  con.write("amplitude_mm,equivalent_conicity\n");
  for (int k = 1; k <= 20; ++k) {
    const double a = 0.5e-3 * k;
    con.print("{:.2f},{:.6f}\n", a * 1e3, fc::equivalent_conicity(ys, dr, a));
  }
  // Profiles in track coordinates for the diagram (right side).
  io::TextWriter prof((dir / "profiles.csv").string());
  prof.write("kind,y_mm,z_mm\n");
  for (std::size_t i = 0; i < pair.wheel_profile().size(); ++i) {
    prof.print("wheel,{:.5f},{:.5f}\n", pair.wheel_profile().y[i] * 1e3,
                        pair.wheel_profile().z[i] * 1e3);
  }
  for (std::size_t i = 0; i < pair.rail_profile().size(); ++i) {
    prof.print("rail,{:.5f},{:.5f}\n", pair.rail_profile().y[i] * 1e3,
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
  CLI::App* geo = app.add_subcommand(
      "geometry", "Wheel-rail contact geometry: 'geometry pair' (tables, diagram, conicity, "
                  "plots) or 'geometry search' (contact points of one position)");
  geo->require_subcommand(0, 1);
  const char* pair_help =
      "PAIR.yaml (track: gauge, gauge_height, rail_profile, [rail_inclination]; wheelset: "
      "wheel_profile, flange_back_distance, flange_back_position, nominal_radius; mm; the "
      "Manchester benchmark file works as is)";
  auto pair_yaml = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>("geometry_out");
  auto no_plot = std::make_shared<bool>(false);
  CLI::App* pair_cmd = geo->add_subcommand(
      "pair", "Contact table (HDF5), contact-point diagram data, conicity and plots of a pair");
  pair_cmd->add_option("pair", *pair_yaml, pair_help)->required();
  add_output_option(pair_cmd, *out_dir, "output folder", {"--out-dir"})->capture_default_str();
  add_no_plots_flag(pair_cmd, *no_plot, {"--no-plot"});
  pair_cmd->callback([&handler, pair_yaml, out_dir, no_plot] {
    handler = [pair_yaml, out_dir, no_plot] {
      return run_pair_report(*pair_yaml, *out_dir, !*no_plot);
    };
  });
  // The former spelling 'geometry PAIR.yaml --out-dir D --no-plot', hidden, for one release.
  geo->add_option("pair", *pair_yaml, pair_help)->group("");
  add_hidden_alias(geo, "--out-dir", *out_dir);
  geo->add_flag("--no-plot", *no_plot)->group("");

  CLI::App* search = geo->add_subcommand(
      "search", "Every wheel-rail contact point of one wheelset position, as JSON");
  auto po = std::make_shared<PairOptions>();
  auto pin = std::make_shared<PoseInput>();
  auto batch = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>("-");
  auto shear = std::make_shared<double>(82.0e9);
  auto shear_mpa = std::make_shared<double>(std::numeric_limits<double>::quiet_NaN());
  auto poisson = std::make_shared<double>(0.28);
  search->add_option("--wheel", po->wheel, "wheel profile (.prw or two-column mm)")->required();
  search->add_option("--rail", po->rail, "rail profile (.prr or two-column mm)")->required();
  // SI options; the former spelling of each (millimetres, or the unit in the name) stays as a
  // hidden alias, converted after parsing. Given both ways: bad input.
  struct Alias {
    CLI::Option* si;
    double* target;
    double scale;
    std::string old_name;
    double value = std::numeric_limits<double>::quiet_NaN();
  };
  auto aliases = std::make_shared<std::deque<Alias>>();
  const auto add_si = [&](const std::string& name, double& target, const std::string& help,
                          const std::string& old_name, double scale) {
    CLI::Option* o = search->add_option(name, target, help)->check(kFiniteNumber);
    Alias& alias = aliases->emplace_back(Alias{o, &target, scale, old_name});
    search->add_option(old_name, alias.value)->check(kFiniteNumber)->group("");
    return o;
  };
  add_si("--gauge", po->gauge, "track gauge [m]", "--gauge-mm", 1e-3)->capture_default_str();
  add_si("--gauge-depth", po->gauge_depth, "gauge measured below top of rail [m]",
         "--gauge-depth-mm", 1e-3)
      ->capture_default_str();
  search
      ->add_option("--inclination", po->inclination,
                   "rail inclination applied to the rail file: 1:40, 1:20, 0 or an angle in rad")
      ->capture_default_str();
  add_si("--flange-back", po->flange_back, "flange-back distance [m]", "--flange-back-mm", 1e-3)
      ->capture_default_str();
  add_si("--flange-back-y", po->flange_back_y,
         "flange-back position in wheel-profile coordinates (default: first point) [m]",
         "--flange-back-y-mm", 1e-3);
  add_si("--radius", po->radius, "nominal wheel radius at the taping line [m]", "--radius-mm",
         1e-3)
      ->capture_default_str();
  add_si("--section-step", po->section_step, "wheel section spacing [m]", "--section-step-mm",
         1e-3)
      ->capture_default_str();
  add_si("--y", pin->y, "lateral shift, + to the right [m]", "--y-mm", 1e-3)
      ->capture_default_str();
  add_si("--roll", pin->roll,
         "roll [rad], + lowers the right wheel (0 with neither --height nor --load: solved for "
         "rigid contact)",
         "--roll-rad", 1.0);
  add_si("--yaw", pin->yaw, "yaw [rad], + turns the front to the right", "--yaw-rad", 1.0);
  auto* h = add_si("--height", pin->height, "axle-centre drop below nominal (+ down) [m]",
                   "--height-mm", 1e-3);
  add_si("--load", pin->load, "total vertical load [N]: solve the height (Hertz)", "--load-n", 1.0)
      ->excludes(h);
  search->add_option("--shear-modulus", *shear, "for --load [Pa]")
      ->check(kFiniteNumber)
      ->capture_default_str();
  add_hidden_alias(search, "--shear-modulus-mpa", *shear_mpa);
  search->add_option("--poisson", *poisson, "for --load")
      ->check(kFiniteNumber)
      ->capture_default_str();
  search->add_option("--batch", *batch,
                     "CSV in (header with y [m] and optional roll, yaw [rad], height [m], load "
                     "[N]): one CSV row per contact point out");
  add_output_option(search, *out, "batch output CSV ('-' = stdout)", {"--out"})
      ->capture_default_str();

  auto overwrite = std::make_shared<bool>(false);
  add_overwrite_flag(search, *overwrite);
  search->callback([&handler, po, pin, batch, out, shear, shear_mpa, poisson, aliases, overwrite] {
    for (const Alias& a : *aliases) {
      if (std::isnan(a.value)) continue;
      if (a.si->count() > 0) {
        throw CLI::ValidationError(a.si->get_name(), "given twice (also as " + a.old_name + ")");
      }
      *a.target = a.value * a.scale;
    }
    if (!std::isnan(pin->height) && !std::isnan(pin->load)) {
      throw CLI::ValidationError("--height", "give --height or --load, not both");
    }
    handler = [po, pin, batch, out, shear, shear_mpa, poisson, overwrite] {
      const double g = std::isnan(*shear_mpa) ? *shear : *shear_mpa * 1e6;
      const double e = 2.0 * g * (1.0 + *poisson);
      const double estar = e / (2.0 * (1.0 - (*poisson) * (*poisson)));
      const fc::WheelRailPair pair = make_pair(*po);
      if (!batch->empty()) return run_batch(pair, *batch, *out, *pin, estar, *overwrite);
      fmt::print("{}", result_json(pair, solve_pose(pair, *pin, estar)));
      return kExitOk;
    };
  });
  geo->callback([&handler, search, pair_cmd, pair_yaml, out_dir, no_plot] {
    if (search->parsed() || pair_cmd->parsed()) return;
    if (pair_yaml->empty()) {
      throw CLI::ValidationError("geometry", "give the 'pair' or the 'search' subcommand");
    }
    handler = [pair_yaml, out_dir, no_plot] {
      return run_pair_report(*pair_yaml, *out_dir, !*no_plot);
    };
  });
}

}  // namespace ferro::cli
