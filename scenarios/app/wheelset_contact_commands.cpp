// `ferrodyn contact wheelset CASES.yaml -o out.h5`: full wheel-rail contact (patches at their
// penetration-weighted centres, MIM normal and rolling contact, height solved for the wheel
// load with friction in the vertical balance) of every wheelset position of a pair file with
// cases (the Manchester contact benchmark format); prints the table, writes HDF5 + CSV
// and the picture of contact positions and patch extents against the lateral shift.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/pair_file.hpp"
#include "ferro/scenarios/report.hpp"
#include "ferro/scenarios/wheelset_contact_file.hpp"
#include "plotting.hpp"

namespace ferro::cli {
namespace {

namespace fc = ferro::contact;

int run_wheelset_contact(const std::string& yaml, const std::string& out,
                         const std::vector<int>& only, bool plot, bool overwrite) {
  scenarios::WheelsetContactInput in = scenarios::load_wheelset_contact_file(yaml);
  std::filesystem::path h5(out);
  std::filesystem::path csv = h5;
  csv.replace_extension(".csv");
  scenarios::OutputSet outputs({overwrite, {yaml}});
  scenarios::OutputFile& h5_file = outputs.claim(h5.string(), "-o");
  scenarios::OutputFile& csv_file = outputs.claim(csv.string(), "-o (its CSV)");
  if (!only.empty()) {
    std::set<int> known;
    for (const auto& c : in.cases) known.insert(c.id);
    std::vector<fc::WheelsetCase> kept;
    for (int id : only) {
      if (!known.count(id)) {
        throw std::invalid_argument(fmt::format("--cases: case {} is not in {} (ids {}..{})", id,
                                                yaml, *known.begin(), *known.rbegin()));
      }
      for (const auto& c : in.cases) {
        if (c.id == id) kept.push_back(c);
      }
    }
    in.cases = kept;
  }
  const fc::WheelRailPair pair = scenarios::make_wheel_rail_pair(in.pair);
  const auto results = fc::solve_wheelset_contacts(pair, in.spec, in.cases);
  fmt::print("{}", scenarios::wheelset_contact_report(results));
  fc::write_wheelset_contacts(results, in.spec, in.pair.path, h5_file.write_path(),
                              csv_file.write_path());
  outputs.commit_all();
  fmt::print("wrote {}, {}\n", h5.string(), csv.string());
  if (plot) {
    if (run_python_tool("wheelset_contact_plot.py", {h5.string()}) != 0) {
      fmt::print(stderr,
                 "plotting failed ({} tools/wheelset_contact_plot.py {}); the table is "
                 "written\n",
                 python_program(), h5.string());
      return kExitRunFailure;
    }
  }
  return kExitOk;
}

}  // namespace

void add_wheelset_contact_commands(CLI::App& app, VerbHandler& handler) {
  CLI::App* contact = app.get_subcommand("contact");
  auto yaml = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>("wheelset_contact.h5");
  auto only = std::make_shared<std::vector<int>>();
  auto no_plots = std::make_shared<bool>(false);
  auto overwrite = std::make_shared<bool>(false);
  CLI::App* cmd = contact->add_subcommand(
      "wheelset",
      "Full contact of prescribed wheelset positions (pair file with cases, Manchester A-2.2 "
      "format): patches at their penetration-weighted centres, MIM normal and rolling contact, "
      "height solved for the wheel load with friction in the vertical balance");
  cmd->add_option("cases_file", *yaml, "pair file with load, material, friction and cases (mm)")
      ->required()
      ->check(CLI::ExistingFile);
  add_output_option(cmd, *out,
                    "HDF5 table to write (the CSV goes next to it, the picture to "
                    "<stem>_plots/)")
      ->capture_default_str();
  cmd->add_option("--cases", *only, "only these case ids (default: every case)")->delimiter(',');
  add_no_plots_flag(cmd, *no_plots);
  add_overwrite_flag(cmd, *overwrite);
  cmd->callback([&handler, yaml, out, only, no_plots, overwrite] {
    handler = [yaml, out, only, no_plots, overwrite] {
      return run_wheelset_contact(*yaml, *out, *only, !*no_plots, *overwrite);
    };
  });
}

}  // namespace ferro::cli
