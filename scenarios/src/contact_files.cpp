#include "ferro/scenarios/contact_files.hpp"
#include "ferro/scenarios/number_text.hpp"

#include <fmt/format.h>

#include <cmath>

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/scenarios/contact_analysis.hpp"
#include "ferro/scenarios/contact_case.hpp"
#include "ferro/scenarios/overrides.hpp"

namespace ferro::scenarios {
namespace {

namespace fc = ferro::contact;

// <dir>/<name><suffix>, the folder made when missing.
std::string output_path(const std::string& dir, const std::string& name,
                        const std::string& suffix) {
  std::filesystem::create_directories(dir);
  return (std::filesystem::path(dir) / (name + suffix)).string();
}

}  // namespace

fc::ModelOptions parse_model_options(const std::vector<std::string>& items) {
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

void use_kij_table(EvalInput& input, const std::string& path, const std::vector<std::string>& at) {
  input.table = std::make_shared<const fc::KijTable>(fc::KijTable::read_hdf5(path));
  for (const auto& kv : parse_model_options(at)) {
    const double v = strict_number(kv.second);
    if (std::isnan(v))
      throw std::invalid_argument(fmt::format("--kij-at {}: not a number", kv.first));
    input.table_point[kv.first] = v;
  }
}

std::string eval_json(const EvalInput& in, const EvalOutput& out) {
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
  return j.dump(2);
}

void run_contact_eval(const EvalRequest& request, bool batch, std::istream& in,
                      const std::string& in_name, std::ostream& out) {
  const fc::ModelOptions options = parse_model_options(request.options);
  EvalInput input = request.input;
  if (!request.kij_table.empty()) use_kij_table(input, request.kij_table, request.kij_at);
  const fc::CoefficientSource source = fc::coefficient_source_from_name(
      fc::option_string(options, "coefficients", "kalker_table"));
  if (batch) {
    evaluate_contact_batch(in, in_name, input, options, source, out);
    return;
  }
  const auto model =
      fc::make_tangential_model(input.model, with_environment_options(input.model, options));
  out << eval_json(input, evaluate_contact(input, *model, source)) << "\n";
}

CurveFiles write_creep_curve_files(const std::string& case_path, const std::string& out_dir) {
  ContactCase c = load_contact_case(case_path);
  const fc::NormalSolution normal = solve_case_normal(c);
  const auto points = compute_creep_curves(c, normal);
  if (points.empty()) {
    throw std::invalid_argument(fmt::format("{}: key 'curves': no curve requested", case_path));
  }
  CurveFiles files;
  files.csv = output_path(out_dir, c.name, "_curves.csv");
  files.h5 = output_path(out_dir, c.name, "_curves.h5");
  write_curves_csv(files.csv, points);
  write_curves_hdf5(files.h5, points);
  files.png = output_path(out_dir, c.name, "_curves.png");
  const fc::ContactPatch& p = normal.patches.at(0);
  files.title = fmt::format("{}: a = {:.3g} mm, b = {:.3g} mm, Fn = {:.4g} kN, mu = {}", c.name,
                            p.semi_axis_x * 1e3, p.semi_axis_y * 1e3,
                            c.normal.normal_force * 1e-3, c.friction);
  return files;
}

PatchFiles write_patch_files(const std::string& case_path, const std::string& out_dir) {
  ContactCase c = load_contact_case(case_path);
  const fc::NormalSolution normal = solve_case_normal(c);
  const PatchPicture pic = compute_patch_picture(c, normal);
  PatchFiles files;
  files.csv = output_path(out_dir, c.name, "_patch.csv");
  write_patch_csv(files.csv, pic);
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
  files.summary_json = summary.dump(2);
  files.png = output_path(out_dir, c.name, "_patch.png");
  files.title = fmt::format("{}: {} + {}, xi_x = {:.3g}, xi_y = {:.3g}, phi = {:.3g} 1/m", c.name,
                            c.normal_model, c.patch_model.label(), c.patch_creepage.longitudinal,
                            c.patch_creepage.lateral, c.patch_creepage.spin);
  return files;
}

}  // namespace ferro::scenarios
