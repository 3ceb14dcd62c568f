// `ferrodyn contact eval | curve | patch`: the contact layer from the command line.
//
// Units: SI everywhere (m, N, Pa, 1/m for spin). Sign convention: creepages are the rigid slip
// of the wheel relative to the rail over the rolling speed; forces and moment are those of the
// rail on the wheel (F_x = -G a b C11 xi_x in the linear range).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ferro/scenarios/contact_files.hpp"
#include "plotting.hpp"

namespace ferro::cli {
namespace {

struct EvalArgs {
  scenarios::EvalRequest request;
  bool batch = false;
};

int do_eval(const EvalArgs& a) {
  scenarios::run_contact_eval(a.request, a.batch, std::cin, "--batch: stdin", std::cout);
  return kExitOk;
}

// The case file, output folder and picture switch of `contact curve` and `contact patch`.
struct CaseArgs {
  std::string case_file, out = ".";
  bool no_png = false;
};

// Prints the written files and draws the picture of a curve or patch case.
template <class Files>
int report_case_files(const CaseArgs& a, const char* plot_kind, const Files& f,
                      const std::string& first, const std::string& second) {
  fmt::print("{}\n{}\n", first, second);
  if (!a.no_png) {
    draw("plot_contact.py", {plot_kind, f.csv, f.png, f.title}, "the CSV " + f.csv + " is written");
    fmt::print("{}\n", f.png);
  }
  return kExitOk;
}

int do_curve(const CaseArgs& a) {
  const scenarios::CurveFiles f = scenarios::write_creep_curve_files(a.case_file, a.out);
  return report_case_files(a, "curves", f, f.csv, f.h5);
}

int do_patch(const CaseArgs& a) {
  const scenarios::PatchFiles f = scenarios::write_patch_files(a.case_file, a.out);
  return report_case_files(a, "patch", f, f.summary_json, f.csv);
}

void add_eval_command(CLI::App* contact, VerbHandler& handler) {
  auto [eval, a] = add_verb<EvalArgs>(
      contact, handler, do_eval, "eval",
      "Solve a Hertzian case; prints forces on the wheel (from the rail) as JSON, SI units");
  add_parameters(eval, scenarios::parameters(a->request.input));
  eval->add_option("--option", a->request.options,
                   "model option key=value (repeatable), e.g. mx=40, "
                   "flexibility=weighted, coefficients=voco_fit, k_a=0.7");
  eval->add_option("--kij-table", a->request.kij_table,
                   "HDF5 K_ij table (docs/KIJ_TABLE.md); overrides --kXX");
  eval->add_option("--kij-at", a->request.kij_at,
                   "table coordinate axis=value (repeatable); normal_force and peak_pressure "
                   "default to the patch's");
  eval->add_flag("--batch", a->batch,
                 "read cases as CSV (header = option names with '_') on stdin, "
                 "write one CSV row per case");
}

}  // namespace

void add_contact_commands(CLI::App& app, VerbHandler& handler) {
  CLI::App* contact =
      app.add_subcommand("contact", "Contact models: evaluate, creep curves, patch pictures");
  contact->require_subcommand(1);
  add_eval_command(contact, handler);

  auto [curve, c] = add_verb<CaseArgs>(
      contact, handler, do_curve, "curve",
      "Creep curves of every model of a case: CSV, HDF5 and one PNG overlay");
  curve->add_option("case", c->case_file, "contact case YAML (scenarios/cases/contact/)")
      ->required();
  add_output_option(curve, c->out, "output folder", {"--out"})->capture_default_str();
  add_no_plots_flag(curve, c->no_png, {"--no-png"});

  auto [patch, p] = add_verb<CaseArgs>(
      contact, handler, do_patch, "patch",
      "Patch picture of a case: pressure, traction vectors, adhesion/slip (CSV + PNG)");
  patch->add_option("case", p->case_file, "contact case YAML")->required();
  add_output_option(patch, p->out, "output folder", {"--out"})->capture_default_str();
  add_no_plots_flag(patch, p->no_png, {"--no-png"});
}

}  // namespace ferro::cli
