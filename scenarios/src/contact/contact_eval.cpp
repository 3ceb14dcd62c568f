// One Hertzian evaluation and CSV batches of them (`ferrodyn contact eval [--batch]`).
#include "ferro/scenarios/contact_eval.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

#include "ferro/contact/hertz.hpp"
#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/scenarios/contact_analysis.hpp"
#include "ferro/scenarios/csv_batch.hpp"

namespace ferro::scenarios {
namespace {

namespace fc = ferro::contact;

// Elliptic patch from A, B (Hertz) or from a, b (curvatures recovered from Hertz so that
// VOCO's fits in A/B can be used).
fc::ContactPatch make_patch(const EvalInput& in, const fc::CombinedMaterial& m) {
  const bool have_ab = std::isfinite(in.a) || std::isfinite(in.b);
  const bool have_curv = std::isfinite(in.curvature_x) || std::isfinite(in.curvature_y);
  if (have_ab == have_curv) {
    throw std::invalid_argument(
        "give either --a and --b (semi-axes [m]) or --curvature-x and --curvature-y (A, B [1/m])");
  }
  if (!(in.fn > 0.0))
    throw std::invalid_argument(fmt::format("--fn: must be > 0 [N], got {}", in.fn));
  if (have_curv) {
    return fc::hertz_patch(
        fc::hertz_solve(in.curvature_x, in.curvature_y, in.fn, m.contact_modulus),
        in.curvature_x, in.curvature_y);
  }
  if (!(in.a > 0.0) || !(in.b > 0.0)) {
    throw std::invalid_argument(
        fmt::format("--a, --b: must both be > 0 [m], got {}, {}", in.a, in.b));
  }
  // Hertz inverse: the curvatures A, B that give this ellipse under F_n.
  const fc::mim::HertzGap g = fc::mim::hertz_gap_for_ellipse(in.a, in.b, in.fn, m.contact_modulus);
  return fc::elliptic_patch(in.a, in.b, in.fn, g.curvature_x, g.curvature_y);
}

}  // namespace

Parameters parameters(EvalInput& in) {
  return {
      {"a", "m", "semi-axis along rolling x (with b)", &in.a, false},
      {"b", "m", "lateral semi-axis (with a)", &in.b, false},
      {"curvature_x", "1/m", "A: longitudinal relative curvature", &in.curvature_x, false},
      {"curvature_y", "1/m", "B: lateral relative curvature", &in.curvature_y, false},
      {"fn", "N", "normal load", &in.fn, false},
      {"g1", "Pa", "wheel shear modulus", &in.g1},
      {"nu1", "-", "wheel Poisson ratio", &in.nu1},
      {"g2", "Pa", "rail shear modulus", &in.g2},
      {"nu2", "-", "rail Poisson ratio", &in.nu2},
      {"mu", "-", "friction coefficient", &in.mu, false},
      {"xi_x", "-", "longitudinal creepage", &in.xi_x, false},
      {"xi_y", "-", "lateral creepage", &in.xi_y, false},
      {"spin", "1/m", "spin creepage", &in.phi, false},
      {"model", "",
       "kalker_linear, linear_saturated, vermeulen_johnson, shen_hedrick_elkins, chopaya, "
       "polach, fastsim, fastrip, mim, mim_table",
       &in.model},
      {"k11", "-", "reduction factor K11", &in.k11},
      {"k22", "-", "reduction factor K22", &in.k22},
      {"k23", "-", "reduction factor K23 (default: K22, as in the thesis 4.2.4)", &in.k23, false},
      {"k33", "-", "reduction factor K33", &in.k33},
  };
}

EvalOutput evaluate_contact(const EvalInput& in, const fc::TangentialModel& model,
                            fc::CoefficientSource source) {
  const fc::Material body1{in.g1, in.nu1}, body2{in.g2, in.nu2};
  body1.validate("--g1/--nu1");
  body2.validate("--g2/--nu2");
  EvalOutput out;
  out.patch = make_patch(in, fc::combine(body1, body2));
  out.gap.curvature_x = out.patch.curvature_x;
  out.gap.curvature_y = out.patch.curvature_y;
  out.gap.normal_force = out.patch.normal_force;
  out.gap.body1 = body1;
  out.gap.body2 = body2;
  fc::TangentialProblem p;
  p.gap = &out.gap;
  p.patch = &out.patch;
  p.creepage = {in.xi_x, in.xi_y, in.phi};
  p.friction = in.mu;
  p.body1 = body1;
  p.body2 = body2;
  p.reduction = {in.k11, in.k22, std::isnan(in.k23) ? in.k22 : in.k23, in.k33};
  if (in.table) p.reduction = in.table->at_patch(out.patch, in.table_point);
  if (!(in.mu >= 0.0))
    throw std::invalid_argument(fmt::format("--mu: must be >= 0, got {}", in.mu));
  out.forces = model.solve(p);
  require_finite_forces(out.forces, fmt::format("model '{}'", in.model));
  out.c = fc::linear_creep_stiffness(p, source).c;
  return out;
}

void evaluate_contact_batch(std::istream& in, const std::string& input_name,
                            const EvalInput& defaults, const fc::ModelOptions& options,
                            fc::CoefficientSource source, std::ostream& out) {
  CsvBatchReader reader(in, input_name);
  const std::map<std::string, double EvalInput::*> numeric = {
      {"a", &EvalInput::a},
      {"b", &EvalInput::b},
      {"curvature_x", &EvalInput::curvature_x},
      {"curvature_y", &EvalInput::curvature_y},
      {"fn", &EvalInput::fn},
      {"g1", &EvalInput::g1},
      {"nu1", &EvalInput::nu1},
      {"g2", &EvalInput::g2},
      {"nu2", &EvalInput::nu2},
      {"mu", &EvalInput::mu},
      {"xi_x", &EvalInput::xi_x},
      {"xi_y", &EvalInput::xi_y},
      {"phi", &EvalInput::phi},
      {"spin", &EvalInput::phi},
      {"k11", &EvalInput::k11},
      {"k22", &EvalInput::k22},
      {"k23", &EvalInput::k23},
      {"k33", &EvalInput::k33}};
  std::set<std::string> allowed = {"model"};
  for (const auto& kv : numeric) allowed.insert(kv.first);
  reader.require_known_columns(allowed);
  const std::vector<std::string>& header = reader.header();
  std::map<std::string, std::unique_ptr<fc::TangentialModel>> models;
  out << "row,model,semi_axis_x,semi_axis_y,peak_pressure,force_x,force_y,moment_z,adhesion_"
         "fraction\n";
  int row = 0;
  std::vector<std::string> cells;
  while (reader.next(cells)) {
    EvalInput row_in = defaults;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (cells[i].empty()) continue;
      if (header[i] == "model") {
        row_in.model = cells[i];
        continue;
      }
      row_in.*(numeric.at(header[i])) = reader.number(cells, i);
    }
    try {
      auto it = models.find(row_in.model);
      if (it == models.end())
        it = models.emplace(row_in.model, fc::make_tangential_model(row_in.model, options)).first;
      const EvalOutput r = evaluate_contact(row_in, *it->second, source);
      out << fmt::format("{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", row,
                         row_in.model, r.patch.semi_axis_x, r.patch.semi_axis_y,
                         r.patch.peak_pressure, r.forces.force_x, r.forces.force_y,
                         r.forces.moment_z, r.forces.adhesion_fraction);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(reader.located(e.what()));
    }
    ++row;
  }
}

}  // namespace ferro::scenarios
