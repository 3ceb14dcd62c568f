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
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ferro/scenarios/pair_file.hpp"
#include "ferro/scenarios/pair_report.hpp"
#include "ferro/scenarios/pose_output.hpp"
#include "ferro/scenarios/pose_search.hpp"
#include "plotting.hpp"

namespace ferro::cli {
namespace {


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
  if (!a.no_plot) draw("geometry_plot.py", {a.out_dir}, "the CSV files are written");
  return kExitOk;
}

// --- search: one position, or a CSV batch of them -----------------------------------------

struct SearchArgs {
  scenarios::SearchPairOptions pair;
  scenarios::PoseInput pose;
  std::string batch, out = "-";
  bool overwrite = false;
};

int do_search(const SearchArgs& a) {
  scenarios::search_poses(a.pair, a.pose, a.batch, a.out, a.overwrite, std::cout,
                          scenarios::Spelling::option);
  return kExitOk;
}

CLI::App* add_search_command(CLI::App* geo, VerbHandler& handler) {
  auto [search, a] = add_verb<SearchArgs>(
      geo, handler, do_search, "search",
      "Every wheel-rail contact point of one wheelset position, as JSON");
  auto params = scenarios::parameters(a->pair);
  for (auto& p : scenarios::parameters(a->pose)) params.push_back(p);
  add_parameters(search, params);
  search->get_option("--wheel")->required();
  search->get_option("--rail")->required();
  search->get_option("--load")->excludes(search->get_option("--height"));
  search->add_option("--batch", a->batch,
                     "CSV in (header with y [m] and optional roll, yaw [rad], height [m], load "
                     "[N]): one CSV row per contact point out");
  add_output_option(search, a->out, "batch output CSV ('-' = stdout)", {"--out"})
      ->capture_default_str();
  add_overwrite_flag(search, a->overwrite);
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
  auto [pair_cmd, pa] = add_verb<PairArgs>(
      geo, handler, run_pair_report, "pair",
      "Contact table (HDF5), contact-point diagram data, conicity and plots of a pair");
  pair_cmd->add_option("pair", pa->yaml, pair_help)->required();
  add_output_option(pair_cmd, pa->out_dir, "output folder", {"--out-dir"})->capture_default_str();
  add_no_plots_flag(pair_cmd, pa->no_plot, {"--no-plot"});
  // The former spelling 'geometry PAIR.yaml --out-dir D --no-plot', hidden, for one release.
  geo->add_option("pair", pa->yaml, pair_help)->group("");
  add_hidden_alias(geo, "--out-dir", pa->out_dir);
  geo->add_flag("--no-plot", pa->no_plot)->group("");
  CLI::App* search = add_search_command(geo, handler);
  geo->callback([&handler, search, cmd = pair_cmd, pa = pa] {
    if (search->parsed() || cmd->parsed()) return;
    if (pa->yaml.empty()) {
      throw CLI::ValidationError("geometry", "give the 'pair' or the 'search' subcommand");
    }
    handler = [pa] { return run_pair_report(*pa); };
  });
}

}  // namespace ferro::cli
