// One Hertzian evaluation and CSV batches of them (`ferrodyn contact eval [--batch]`).
#include "ferro/scenarios/contact_eval.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

#include "ferro/contact/mim/hertz_gap.hpp"
#include "ferro/contact/normal/hertz.hpp"
#include "ferro/io/csv.hpp"
#include "ferro/scenarios/contact_analysis.hpp"

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
      Parameter{"spin", "1/m", "spin creepage", &in.phi, false}.formerly("phi"),
      {"model", "",
       "kalker_linear, linear_saturated, vermeulen_johnson, shen_hedrick_elkins, chopaya, "
       "polach, fastsim, fastrip, mim, mim_table",
       &in.model},
      {"k11", "-", "reduction factor K11", &in.reduction.k11},
      {"k22", "-", "reduction factor K22", &in.reduction.k22},
      {"k23", "-", "reduction factor K23 (default: K22, as in the thesis 4.2.4)", &in.reduction.k23, false},
      {"k33", "-", "reduction factor K33", &in.reduction.k33},
  };
}

namespace {

// The numeric fields of a case by name ("phi" and "spin" both name the spin creepage; k11..k33
// the reduction factors).
using Field = double& (*)(EvalInput&);
const std::map<std::string, Field>& numeric_fields() {
  static const std::map<std::string, Field> fields = {
      {"a", [](EvalInput& e) -> double& { return e.a; }},
      {"b", [](EvalInput& e) -> double& { return e.b; }},
      {"curvature_x", [](EvalInput& e) -> double& { return e.curvature_x; }},
      {"curvature_y", [](EvalInput& e) -> double& { return e.curvature_y; }},
      {"fn", [](EvalInput& e) -> double& { return e.fn; }},
      {"g1", [](EvalInput& e) -> double& { return e.g1; }},
      {"nu1", [](EvalInput& e) -> double& { return e.nu1; }},
      {"g2", [](EvalInput& e) -> double& { return e.g2; }},
      {"nu2", [](EvalInput& e) -> double& { return e.nu2; }},
      {"mu", [](EvalInput& e) -> double& { return e.mu; }},
      {"xi_x", [](EvalInput& e) -> double& { return e.xi_x; }},
      {"xi_y", [](EvalInput& e) -> double& { return e.xi_y; }},
      {"phi", [](EvalInput& e) -> double& { return e.phi; }},
      {"spin", [](EvalInput& e) -> double& { return e.phi; }},
      {"k11", [](EvalInput& e) -> double& { return e.reduction.k11; }},
      {"k22", [](EvalInput& e) -> double& { return e.reduction.k22; }},
      {"k23", [](EvalInput& e) -> double& { return e.reduction.k23; }},
      {"k33", [](EvalInput& e) -> double& { return e.reduction.k33; }}};
  return fields;
}

void put(std::span<double> column, std::size_t i, double value) {
  if (!column.empty()) column[i] = value;
}

}  // namespace

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
  p.reduction = in.reduction;
  if (std::isnan(p.reduction.k23)) p.reduction.k23 = p.reduction.k22;
  if (in.table) p.reduction = in.table->at_patch(out.patch, in.table_point);
  if (!(in.mu >= 0.0))
    throw std::invalid_argument(fmt::format("--mu: must be >= 0, got {}", in.mu));
  out.forces = model.solve(p);
  require_finite_forces(out.forces, fmt::format("model '{}'", in.model));
  out.c = fc::linear_creep_stiffness(p, source).c;
  return out;
}

void evaluate_contact_columns(const EvalInput& defaults,
                              const std::map<std::string, std::span<const double>>& inputs,
                              std::size_t n, const fc::TangentialModel& model,
                              fc::CoefficientSource source, const EvalOutputColumns& out) {
  struct Column {
    Field field;
    std::span<const double> values;
  };
  std::vector<Column> columns;
  for (const auto& [key, values] : inputs) {
    const auto it = numeric_fields().find(key);
    if (it == numeric_fields().end()) {
      std::vector<std::string> names;
      for (const auto& kv : numeric_fields()) names.push_back(kv.first);
      throw std::invalid_argument(
          fmt::format("{}: unknown input; allowed: {}", key, fmt::join(names, ", ")));
    }
    if (values.size() != n && values.size() != 1) {
      throw std::invalid_argument(
          fmt::format("{}: {} values for {} cases (give one, or one per case)", key,
                      values.size(), n));
    }
    columns.push_back({it->second, values});
  }
  for (const std::span<double> c :
       {out.semi_axis_x, out.semi_axis_y, out.peak_pressure, out.force_x, out.force_y,
        out.moment_z, out.adhesion_fraction, out.c11, out.c22, out.c23, out.c33}) {
    if (!c.empty() && c.size() != n)
      throw std::invalid_argument(fmt::format("output column of {} values for {} cases", c.size(), n));
  }
  EvalInput in = defaults;
  for (std::size_t i = 0; i < n; ++i) {
    for (const Column& c : columns) c.field(in) = c.values[c.values.size() == 1 ? 0 : i];
    EvalOutput r;
    try {
      r = evaluate_contact(in, model, source);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("case {}: {}", i, e.what()));
    }
    put(out.semi_axis_x, i, r.patch.semi_axis_x);
    put(out.semi_axis_y, i, r.patch.semi_axis_y);
    put(out.peak_pressure, i, r.patch.peak_pressure);
    put(out.force_x, i, r.forces.force_x);
    put(out.force_y, i, r.forces.force_y);
    put(out.moment_z, i, r.forces.moment_z);
    put(out.adhesion_fraction, i, r.forces.adhesion_fraction);
    put(out.c11, i, r.c.c11);
    put(out.c22, i, r.c.c22);
    put(out.c23, i, r.c.c23);
    put(out.c33, i, r.c.c33);
  }
}

NormalCases solve_normal_cases(const fc::NormalContactModel& model, const fc::NormalProblem& base,
                               std::size_t n, std::span<const double> normal_force,
                               std::span<const double> curvature_x,
                               std::span<const double> curvature_y) {
  const auto at = [n](std::span<const double> column, const char* key, std::size_t i,
                      double fallback) {
    if (column.empty()) return fallback;
    if (column.size() != n && column.size() != 1) {
      throw std::invalid_argument(fmt::format(
          "{}: {} values for {} cases (give one, or one per case)", key, column.size(), n));
    }
    return column[column.size() == 1 ? 0 : i];
  };
  NormalCases out;
  fc::NormalProblem p = base;
  for (std::size_t i = 0; i < n; ++i) {
    p.normal_force = at(normal_force, "fn", i, base.normal_force);
    p.curvature_x = at(curvature_x, "curvature_x", i, base.curvature_x);
    p.curvature_y = at(curvature_y, "curvature_y", i, base.curvature_y);
    fc::NormalSolution s;
    try {
      s = model.solve(p);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("case {}: {}", i, e.what()));
    }
    out.approach.push_back(s.approach);
    for (auto& patch : s.patches) {
      out.patch_case.push_back(i);
      out.patches.push_back(std::move(patch));
    }
  }
  return out;
}

void evaluate_contact_batch(std::istream& in, const std::string& input_name,
                            const EvalInput& defaults, const fc::ModelOptions& options,
                            fc::CoefficientSource source, std::ostream& out) {
  io::CsvReader reader(in, input_name);
  const auto& numeric = numeric_fields();
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
      numeric.at(header[i])(row_in) = reader.number(cells, i);
    }
    try {
      auto it = models.find(row_in.model);
      if (it == models.end())
        it = models.emplace(row_in.model, fc::make_tangential_model(row_in.model, options)).first;
      const EvalOutput r = evaluate_contact(row_in, *it->second, source);
      // Shortest text that reads back as the same double: a batch is exact to the last bit.
      out << fmt::format("{},{},{},{},{},{},{},{},{}\n", row,
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
