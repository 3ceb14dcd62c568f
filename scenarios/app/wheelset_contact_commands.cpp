// `ferrodyn contact wheelset CASES.yaml -o out.h5`: full wheel-rail contact (patches at their
// penetration-weighted centres, MIM normal and rolling contact, height solved for the wheel
// load with friction in the vertical balance) of every wheelset position of a pair file with
// cases (the Manchester contact benchmark format); prints the table, writes HDF5 + CSV
// and the picture of contact positions and patch extents against the lateral shift.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ferro/scenarios/wheelset_contact_run.hpp"
#include "plotting.hpp"

namespace ferro::cli {
namespace {

struct WheelsetArgs {
  std::string yaml, out = "wheelset_contact.h5";
  std::vector<int> only;
  bool no_plots = false, overwrite = false;
};

int run_wheelset_contact(const WheelsetArgs& a) {
  const auto files = scenarios::write_wheelset_contact_files(a.yaml, a.out, a.only, a.overwrite);
  fmt::print("{}", files.report);
  fmt::print("wrote {}, {}\n", files.h5, files.csv);
  if (!a.no_plots) draw("wheelset_contact_plot.py", {files.h5}, "the table is written");
  return kExitOk;
}

}  // namespace

void add_wheelset_contact_commands(CLI::App& app, VerbHandler& handler) {
  auto [cmd, a] = add_verb<WheelsetArgs>(
      app.get_subcommand("contact"), handler, run_wheelset_contact, "wheelset",
      "Full contact of prescribed wheelset positions (pair file with cases, Manchester A-2.2 "
      "format): patches at their penetration-weighted centres, MIM normal and rolling contact, "
      "height solved for the wheel load with friction in the vertical balance");
  cmd->add_option("cases_file", a->yaml, "pair file with load, material, friction and cases (mm)")
      ->required()
      ->check(CLI::ExistingFile);
  add_output_option(cmd, a->out,
                    "HDF5 table to write (the CSV goes next to it, the picture to "
                    "<stem>_plots/)")
      ->capture_default_str();
  cmd->add_option("--cases", a->only, "only these case ids (default: every case)")->delimiter(',');
  add_no_plots_flag(cmd, a->no_plots);
  add_overwrite_flag(cmd, a->overwrite);
}

}  // namespace ferro::cli
