// `ferrodyn contact eval | curve | patch`: the contact layer from the command line.
//
// Units: SI everywhere (m, N, Pa, 1/m for spin). Sign convention: creepages are the rigid slip
// of the wheel relative to the rail over the rolling speed; forces and moment are those of the
// rail on the wheel (F_x = -G a b C11 xi_x in the linear range).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/contact/normal/hertz.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/scenarios/contact_analysis.hpp"
#include "ferro/scenarios/contact_case.hpp"
#include "ferro/scenarios/contact_eval.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "plotting.hpp"

namespace ferro::cli {
namespace {

namespace fc = ferro::contact;

using scenarios::EvalInput;
using scenarios::EvalOutput;

fc::ModelOptions parse_options(const std::vector<std::string>& items) {
  fc::ModelOptions o;
  for (const std::string& it : items) {
    const auto eq = it.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw std::invalid_argument(fmt::format("--option '{}': expected key=value", it));
    }
    o[it.substr(0, eq)] = it.substr(eq + 1);
  }
  return o;
}

void print_json(const EvalInput& in, const EvalOutput& out) {
  nlohmann::ordered_json j;
  j["model"] = in.model;
  j["semi_axis_x"] = out.patch.semi_axis_x;
  j["semi_axis_y"] = out.patch.semi_axis_y;
  j["normal_force"] = out.patch.normal_force;
  j["peak_pressure"] = out.patch.peak_pressure;
  j["force_x"] = out.forces.force_x;
  j["force_y"] = out.forces.force_y;
  j["moment_z"] = out.forces.moment_z;
  j["adhesion_fraction"] = out.forces.adhesion_fraction;
  j["c11"] = out.c.c11;
  j["c22"] = out.c.c22;
  j["c23"] = out.c.c23;
  j["c33"] = out.c.c33;
  j["units"] = "SI (m, N, Pa, N m)";
  j["convention"] = "forces and moment on the wheel from the rail";
  fmt::print("{}\n", j.dump(2));
}

std::string output_path(const std::string& dir, const std::string& name,
                        const std::string& suffix) {
  std::filesystem::create_directories(dir);
  return (std::filesystem::path(dir) / (name + suffix)).string();
}

}  // namespace

void add_contact_commands(CLI::App& app, VerbHandler& handler) {
  CLI::App* contact =
      app.add_subcommand("contact", "Contact models: evaluate, creep curves, patch pictures");
  contact->require_subcommand(1);

  // contact eval
  auto in = std::make_shared<EvalInput>();
  auto opts = std::make_shared<std::vector<std::string>>();
  auto batch = std::make_shared<bool>(false);
  auto kij_table = std::make_shared<std::string>();
  auto kij_at = std::make_shared<std::vector<std::string>>();
  CLI::App* eval = contact->add_subcommand(
      "eval",
      "Solve a Hertzian case; prints forces on the wheel (from the rail) as JSON, SI units");
  add_parameters(eval, scenarios::parameters(*in));
  add_hidden_alias(eval, "--phi", in->phi);
  eval->add_option("--option", *opts,
                   "model option key=value (repeatable), e.g. mx=40, "
                   "flexibility=weighted, coefficients=voco_fit, k_a=0.7");
  eval->add_option("--kij-table", *kij_table,
                   "HDF5 K_ij table (docs/KIJ_TABLE.md); overrides --kXX");
  eval->add_option("--kij-at", *kij_at,
                   "table coordinate axis=value (repeatable); normal_force and peak_pressure "
                   "default to the patch's");
  eval->add_flag("--batch", *batch,
                 "read cases as CSV (header = option names with '_') on stdin, "
                 "write one CSV row per case");
  eval->callback([&handler, in, opts, batch, kij_table, kij_at] {
    handler = [in, opts, batch, kij_table, kij_at] {
      const fc::ModelOptions options = parse_options(*opts);
      EvalInput input = *in;
      if (!kij_table->empty()) {
        input.table = std::make_shared<const fc::KijTable>(fc::KijTable::read_hdf5(*kij_table));
        for (const auto& kv : parse_options(*kij_at)) {
          try {
            input.table_point[kv.first] = std::stod(kv.second);
          } catch (const std::exception&) {
            throw std::invalid_argument(fmt::format("--kij-at {}: not a number", kv.first));
          }
        }
      }
      const fc::CoefficientSource source = fc::coefficient_source_from_name(
          fc::option_string(options, "coefficients", "kalker_table"));
      if (*batch) {
        scenarios::evaluate_contact_batch(std::cin, "--batch: stdin", input, options, source,
                                          std::cout);
        return kExitOk;
      }
      const auto model =
          fc::make_tangential_model(input.model,
                                    scenarios::with_environment_options(input.model, options));
      print_json(input, scenarios::evaluate_contact(input, *model, source));
      return kExitOk;
    };
  });

  // contact curve
  auto curve_case = std::make_shared<std::string>();
  auto curve_out = std::make_shared<std::string>(".");
  auto no_png = std::make_shared<bool>(false);
  CLI::App* curve = contact->add_subcommand(
      "curve", "Creep curves of every model of a case: CSV, HDF5 and one PNG overlay");
  curve->add_option("case", *curve_case, "contact case YAML (scenarios/cases/contact/)")
      ->required();
  add_output_option(curve, *curve_out, "output folder", {"--out"})->capture_default_str();
  add_no_plots_flag(curve, *no_png, {"--no-png"});
  curve->callback([&handler, curve_case, curve_out, no_png] {
    handler = [curve_case, curve_out, no_png] {
      scenarios::ContactCase c = scenarios::load_contact_case(*curve_case);
      const fc::NormalSolution normal = scenarios::solve_case_normal(c);
      const auto points = scenarios::compute_creep_curves(c, normal);
      if (points.empty()) {
        throw std::invalid_argument(
            fmt::format("{}: key 'curves': no curve requested", *curve_case));
      }
      const std::string csv = output_path(*curve_out, c.name, "_curves.csv");
      const std::string h5 = output_path(*curve_out, c.name, "_curves.h5");
      scenarios::write_curves_csv(csv, points);
      scenarios::write_curves_hdf5(h5, points);
      fmt::print("{}\n{}\n", csv, h5);
      if (!*no_png) {
        const std::string png = output_path(*curve_out, c.name, "_curves.png");
        const fc::ContactPatch& p = normal.patches.at(0);
        run_plot_script(
            "curves", csv, png,
            fmt::format("{}: a = {:.3g} mm, b = {:.3g} mm, Fn = {:.4g} kN, mu = {}", c.name,
                        p.semi_axis_x * 1e3, p.semi_axis_y * 1e3, c.normal.normal_force * 1e-3,
                        c.friction));
        fmt::print("{}\n", png);
      }
      return kExitOk;
    };
  });

  // contact patch
  auto patch_case = std::make_shared<std::string>();
  auto patch_out = std::make_shared<std::string>(".");
  auto patch_no_png = std::make_shared<bool>(false);
  CLI::App* patch = contact->add_subcommand(
      "patch", "Patch picture of a case: pressure, traction vectors, adhesion/slip (CSV + PNG)");
  patch->add_option("case", *patch_case, "contact case YAML")->required();
  add_output_option(patch, *patch_out, "output folder", {"--out"})->capture_default_str();
  add_no_plots_flag(patch, *patch_no_png, {"--no-png"});
  patch->callback([&handler, patch_case, patch_out, patch_no_png] {
    handler = [patch_case, patch_out, patch_no_png] {
      scenarios::ContactCase c = scenarios::load_contact_case(*patch_case);
      const fc::NormalSolution normal = scenarios::solve_case_normal(c);
      const scenarios::PatchPicture pic = scenarios::compute_patch_picture(c, normal);
      const std::string csv = output_path(*patch_out, c.name, "_patch.csv");
      scenarios::write_patch_csv(csv, pic);
      nlohmann::ordered_json summary = nlohmann::ordered_json::array();
      for (std::size_t k = 0; k < normal.patches.size(); ++k) {
        const fc::ContactPatch& p = normal.patches[k];
        nlohmann::ordered_json j;
        j["patch"] = k;
        j["y_center"] = p.y_center;
        j["semi_axis_x"] = p.semi_axis_x;
        j["semi_axis_y"] = p.semi_axis_y;
        j["normal_force"] = p.normal_force;
        j["peak_pressure"] = p.peak_pressure;
        j["force_x"] = pic.forces[k].force_x;
        j["force_y"] = pic.forces[k].force_y;
        j["moment_z"] = pic.forces[k].moment_z;
        j["adhesion_fraction"] = pic.forces[k].adhesion_fraction;
        summary.push_back(std::move(j));
      }
      fmt::print("{}\n{}\n", summary.dump(2), csv);
      if (!*patch_no_png) {
        const std::string png = output_path(*patch_out, c.name, "_patch.png");
        run_plot_script(
            "patch", csv, png,
            fmt::format("{}: {} + {}, xi_x = {:.3g}, xi_y = {:.3g}, phi = {:.3g} 1/m", c.name,
                        c.normal_model, c.patch_model.label(), c.patch_creepage.longitudinal,
                        c.patch_creepage.lateral, c.patch_creepage.spin));
        fmt::print("{}\n", png);
      }
      return kExitOk;
    };
  });
}

}  // namespace ferro::cli
