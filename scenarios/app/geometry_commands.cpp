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
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/io/text_writer.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/pair_file.hpp"
#include "ferro/scenarios/pair_report.hpp"
#include "ferro/scenarios/pose_search.hpp"
#include "plotting.hpp"

namespace ferro::cli {
namespace {

namespace fc = ferro::contact;

using scenarios::PoseInput;

std::string result_json(const fc::WheelRailPair& pair, const scenarios::PoseResult& r) {
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
    q["lead_mm"] = scenarios::contact_lead(pair, r.pose, p) * 1e3;
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
  std::optional<scenarios::OutputSet> outputs;
  scenarios::OutputFile* claimed = nullptr;
  if (out_path != "-") {
    outputs.emplace(scenarios::OutputRules{overwrite, {in_path}});
    claimed = &outputs->claim(out_path, "-o");
  }
  std::optional<io::TextWriter> out_file;  // opened once the input's header is good
  scenarios::search_pose_batch(pair, in, in_path, defaults, estar, [&](const std::string& rows) {
    if (claimed != nullptr && !out_file) out_file.emplace(claimed->write_path());
    if (out_file) {
      out_file->write(rows);
    } else {
      std::cout << rows;
      if (!std::cout) throw std::runtime_error("cannot write the standard output");
    }
  });
  if (out_file) {
    out_file->close();
    claimed->commit();
  }
  std::cout.flush();
  return kExitOk;
}

// --- PAIR.yaml: tables, diagram data, conicity, plots -------------------------------------

int run_pair_report(const std::string& yaml_path, const std::string& out_dir, bool plot) {
  (void)scenarios::write_pair_report(
      scenarios::make_wheel_rail_pair(scenarios::load_pair_file(yaml_path)), out_dir);
  fmt::print("wrote {}/contact_table.h5, contact_points.csv, conicity.csv, profiles.csv\n",
             out_dir);
  std::fflush(stdout);
  if (plot) {
    if (run_python_tool("geometry_plot.py", {out_dir}) != 0) {
      throw std::runtime_error(fmt::format(
          "plotting failed ({} tools/geometry_plot.py {}); the CSV files are written",
          python_program(), out_dir));
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
  auto po = std::make_shared<scenarios::SearchPairOptions>();
  auto pin = std::make_shared<PoseInput>();
  auto batch = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>("-");
  auto shear_mpa = std::make_shared<double>(std::numeric_limits<double>::quiet_NaN());
  auto params = scenarios::parameters(*po);
  for (auto& p : scenarios::parameters(*pin)) params.push_back(p);
  add_parameters(search, params);
  search->get_option("--wheel")->required();
  search->get_option("--rail")->required();
  // Numbers must be finite; the former spelling of each length and angle (millimetres, or the
  // unit in the name) stays as a hidden alias, converted after parsing (given both ways: bad
  // input).
  struct Alias {
    CLI::Option* si;
    double* target;
    std::string old_name;
    double scale;
    double value = std::numeric_limits<double>::quiet_NaN();
  };
  const std::map<std::string, std::pair<std::string, double>> old_names{
      {"gauge", {"--gauge-mm", 1e-3}},   {"gauge_depth", {"--gauge-depth-mm", 1e-3}},
      {"flange_back", {"--flange-back-mm", 1e-3}},
      {"flange_back_y", {"--flange-back-y-mm", 1e-3}},
      {"radius", {"--radius-mm", 1e-3}}, {"section_step", {"--section-step-mm", 1e-3}},
      {"y", {"--y-mm", 1e-3}},           {"roll", {"--roll-rad", 1.0}},
      {"yaw", {"--yaw-rad", 1.0}},       {"height", {"--height-mm", 1e-3}},
      {"load", {"--load-n", 1.0}}};
  auto aliases = std::make_shared<std::deque<Alias>>();
  for (const auto& p : params) {
    double* const* target = std::get_if<double*>(&p.target);
    if (target == nullptr) continue;
    CLI::Option* si = search->get_option(scenarios::spelled(p.key, scenarios::Spelling::option));
    si->check(kFiniteNumber);
    const auto old = old_names.find(p.key);
    if (old == old_names.end()) continue;
    Alias& a = aliases->emplace_back(Alias{si, *target, old->second.first, old->second.second});
    search->add_option(a.old_name, a.value)->check(kFiniteNumber)->group("");
  }
  search->get_option("--load")->excludes(search->get_option("--height"));
  add_hidden_alias(search, "--shear-modulus-mpa", *shear_mpa);
  search->add_option("--batch", *batch,
                     "CSV in (header with y [m] and optional roll, yaw [rad], height [m], load "
                     "[N]): one CSV row per contact point out");
  add_output_option(search, *out, "batch output CSV ('-' = stdout)", {"--out"})
      ->capture_default_str();
  auto overwrite = std::make_shared<bool>(false);
  add_overwrite_flag(search, *overwrite);
  search->callback([&handler, po, pin, batch, out, shear_mpa, aliases, overwrite] {
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
    handler = [po, pin, batch, out, shear_mpa, overwrite] {
      const double g = std::isnan(*shear_mpa) ? po->shear_modulus : *shear_mpa * 1e6;
      const double estar = scenarios::pose_search_modulus(g, po->poisson);
      const fc::WheelRailPair pair = scenarios::make_search_pair(*po, "--inclination");
      if (!batch->empty()) return run_batch(pair, *batch, *out, *pin, estar, *overwrite);
      fmt::print("{}", result_json(pair, scenarios::solve_pose(pair, *pin, estar)));
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
