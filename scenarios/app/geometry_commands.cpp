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
#include <deque>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/scenarios/number_text.hpp"
#include "ferro/scenarios/pair_file.hpp"
#include "ferro/scenarios/pair_report.hpp"
#include "ferro/scenarios/pose_output.hpp"
#include "ferro/scenarios/pose_search.hpp"
#include "plotting.hpp"

namespace ferro::cli {
namespace {

namespace fc = ferro::contact;
using scenarios::PoseInput;

// --- PAIR.yaml: tables, diagram data, conicity, plots -------------------------------------

struct PairArgs {
  std::string yaml, out_dir = "geometry_out";
  bool no_plot = false;
};

int run_pair_report(const PairArgs& a) {
  (void)scenarios::write_pair_report(
      scenarios::make_wheel_rail_pair(scenarios::load_pair_file(a.yaml)), a.out_dir);
  fmt::print("wrote {}/contact_table.h5, contact_points.csv, conicity.csv, profiles.csv\n",
             a.out_dir);
  std::fflush(stdout);
  if (!a.no_plot && run_python_tool("geometry_plot.py", {a.out_dir}) != 0) {
    throw std::runtime_error(
        fmt::format("plotting failed ({} tools/geometry_plot.py {}); the CSV files are written",
                    python_program(), a.out_dir));
  }
  return kExitOk;
}

// --- search: one position, or a CSV batch of them -----------------------------------------

struct SearchArgs {
  scenarios::SearchPairOptions pair;
  PoseInput pose;
  std::string batch, out = "-";
  double shear_mpa = std::numeric_limits<double>::quiet_NaN();  // former spelling [MPa]
  bool overwrite = false;
};

int do_search(const SearchArgs& a) {
  const double g = std::isnan(a.shear_mpa) ? a.pair.shear_modulus : a.shear_mpa * 1e6;
  const double estar = scenarios::pose_search_modulus(g, a.pair.poisson);
  const fc::WheelRailPair pair = scenarios::make_search_pair(a.pair, "--inclination");
  if (!a.batch.empty()) {
    scenarios::write_pose_batch(pair, a.batch, a.out, a.pose, estar, a.overwrite, std::cout);
    return kExitOk;
  }
  fmt::print("{}", scenarios::pose_result_json(pair, scenarios::solve_pose(pair, a.pose, estar)));
  return kExitOk;
}

// Numeric options must be finite: "nan" or "inf" is bad input, not a position.
const CLI::Validator kFiniteNumber(
    [](std::string& text) {
      return std::isnan(scenarios::strict_number(text))
                 ? fmt::format("expected a finite number, got '{}'", text)
                 : std::string();
    },
    "FINITE");

// The former spelling of a length or angle (millimetres, or the unit in the name): a hidden
// option converted after parsing; given both ways is bad input.
struct Alias {
  CLI::Option* si;
  double* target;
  std::string old_name;
  double scale;
  double value = std::numeric_limits<double>::quiet_NaN();
};

// Every number option of `search` checked finite, with the former spellings as hidden options.
std::shared_ptr<std::deque<Alias>> add_former_spellings(CLI::App* search,
                                                        const scenarios::Parameters& params) {
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
  return aliases;
}

// Converts the former spellings given into their options' values.
void apply_former_spellings(const std::deque<Alias>& aliases) {
  for (const Alias& a : aliases) {
    if (std::isnan(a.value)) continue;
    if (a.si->count() > 0) {
      throw CLI::ValidationError(a.si->get_name(), "given twice (also as " + a.old_name + ")");
    }
    *a.target = a.value * a.scale;
  }
}

CLI::App* add_search_command(CLI::App* geo, VerbHandler& handler) {
  CLI::App* search = geo->add_subcommand(
      "search", "Every wheel-rail contact point of one wheelset position, as JSON");
  auto a = std::make_shared<SearchArgs>();
  auto params = scenarios::parameters(a->pair);
  for (auto& p : scenarios::parameters(a->pose)) params.push_back(p);
  add_parameters(search, params);
  search->get_option("--wheel")->required();
  search->get_option("--rail")->required();
  auto aliases = add_former_spellings(search, params);
  search->get_option("--load")->excludes(search->get_option("--height"));
  add_hidden_alias(search, "--shear-modulus-mpa", a->shear_mpa);
  search->add_option("--batch", a->batch,
                     "CSV in (header with y [m] and optional roll, yaw [rad], height [m], load "
                     "[N]): one CSV row per contact point out");
  add_output_option(search, a->out, "batch output CSV ('-' = stdout)", {"--out"})
      ->capture_default_str();
  add_overwrite_flag(search, a->overwrite);
  search->callback([&handler, a, aliases] {
    apply_former_spellings(*aliases);
    if (!std::isnan(a->pose.height) && !std::isnan(a->pose.load)) {
      throw CLI::ValidationError("--height", "give --height or --load, not both");
    }
    handler = [a] { return do_search(*a); };
  });
  return search;
}

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
  auto pa = std::make_shared<PairArgs>();
  CLI::App* pair_cmd = geo->add_subcommand(
      "pair", "Contact table (HDF5), contact-point diagram data, conicity and plots of a pair");
  pair_cmd->add_option("pair", pa->yaml, pair_help)->required();
  add_output_option(pair_cmd, pa->out_dir, "output folder", {"--out-dir"})->capture_default_str();
  add_no_plots_flag(pair_cmd, pa->no_plot, {"--no-plot"});
  on_parsed(pair_cmd, handler, pa, run_pair_report);
  // The former spelling 'geometry PAIR.yaml --out-dir D --no-plot', hidden, for one release.
  geo->add_option("pair", pa->yaml, pair_help)->group("");
  add_hidden_alias(geo, "--out-dir", pa->out_dir);
  geo->add_flag("--no-plot", pa->no_plot)->group("");
  CLI::App* search = add_search_command(geo, handler);
  geo->callback([&handler, search, pair_cmd, pa] {
    if (search->parsed() || pair_cmd->parsed()) return;
    if (pa->yaml.empty()) {
      throw CLI::ValidationError("geometry", "give the 'pair' or the 'search' subcommand");
    }
    handler = [pa] { return run_pair_report(*pa); };
  });
}

}  // namespace ferro::cli
