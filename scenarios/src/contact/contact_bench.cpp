// `ferrodyn bench contact`: speed versus error of every tangential model, fine MIM as reference.
#include "ferro/scenarios/contact_bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include <unistd.h>

#include "ferro/contact/mim_table.hpp"
#include "ferro/contact/tangential_model.hpp"

namespace ferro::scenarios {

namespace fc = ferro::contact;

namespace {

constexpr double kPatchScale = 5.0e-3;  // c = sqrt(ab) [m]
constexpr double kNormalForce = 80.0e3;
constexpr double kFriction = 0.3;

struct Prepared {
  fc::ContactPatch patch;
  fc::Creepage creepage;
};

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

std::vector<ContactBenchCase> contact_bench_cases() {
  std::vector<ContactBenchCase> cases;
  const double ratios[] = {0.2, 0.5, 1.0, 2.0, 5.0};
  const double magnitudes[] = {0.3, 1.0, 3.0};  // micro-slip, transition, full slip
  for (double g : ratios) {
    for (double m : magnitudes) {
      cases.push_back({g, m, 0.0, 0.0, "x"});
      cases.push_back({g, 0.0, m, 0.0, "y"});
      cases.push_back({g, 0.0, 0.0, 2.0 * m, "spin"});
      cases.push_back({g, 0.7 * m, -0.7 * m, 0.0, "x+y"});
      cases.push_back({g, 0.0, 0.7 * m, 1.4 * m, "y+spin"});
      cases.push_back({g, -0.6 * m, 0.5 * m, -1.2 * m, "x+y+spin"});
    }
  }
  return cases;
}

ContactBenchResult run_contact_bench(const ContactBenchOptions& opt) {
  std::vector<ContactBenchCase> cases = contact_bench_cases();
  if (opt.quick) {
    std::vector<ContactBenchCase> sub;
    for (std::size_t k = 0; k < cases.size(); k += 6) sub.push_back(cases[k + (k / 6) % 6]);
    cases = sub;
  }
  const fc::Material steel = fc::Material::from_young(210.0e9, 0.28);

  // mim_table: given or built (default spec) into a temporary file.
  std::string table_path = opt.table;
  if (table_path.empty()) {
    fc::MimTableSpec spec = fc::MimTableSpec::default_spec();
    if (opt.quick) {
      spec.ratio = {0.2, 1.0, 5.0};
      spec.xi_x = {0.0, 0.5, 1.2, 2.5, 5.0};
      spec.xi_y = spec.xi_x;
      spec.spin = {-9.0, -3.0, -1.0, 0.0, 1.0, 3.0, 9.0};
      spec.elements = 8;
    }
    spec.threads = 2;
    table_path = (std::filesystem::temp_directory_path() /
                  fmt::format("ferrodyn_bench_mim_table_{}.h5", static_cast<long>(::getpid())))
                     .string();
    fc::MimTable::build(spec).write_hdf5(table_path);
  }

  // Problems (creepages from the normalised ones with the table's scaling, Kalker C_ij).
  const fc::MimTable scaling = fc::MimTable::read_hdf5(table_path);
  std::vector<Prepared> prepared(cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const double a = kPatchScale * std::sqrt(cases[k].ratio), b = kPatchScale / std::sqrt(cases[k].ratio);
    prepared[k].patch = fc::elliptic_patch(a, b, kNormalForce);
  }
  const auto problem = [&](std::size_t k) {
    fc::TangentialProblem p;
    p.patch = &prepared[k].patch;
    p.friction = kFriction;
    p.body1 = p.body2 = steel;
    p.creepage = {1.0, 1.0, 1.0};
    const fc::MimTablePoint unit = scaling.normalise(p);
    p.creepage = {cases[k].xi_x / unit.xi_x, cases[k].xi_y / unit.xi_y, cases[k].spin / unit.spin};
    return p;
  };

  struct Entry {
    std::string label, name;
    fc::ModelOptions options;
  };
  std::vector<Entry> models = {
      {"kalker_linear", "kalker_linear", {}},
      {"linear_saturated", "linear_saturated", {}},
      {"vermeulen_johnson", "vermeulen_johnson", {}},
      {"shen_hedrick_elkins", "shen_hedrick_elkins", {}},
      {"chopaya", "chopaya", {}},
      {"polach", "polach", {}},
      {"fastsim 10x10", "fastsim", {{"mx", "10"}, {"my", "10"}}},
      {"fastsim 20x20", "fastsim", {{"mx", "20"}, {"my", "20"}}},
      {"fastsim 50x50", "fastsim", {{"mx", "50"}, {"my", "50"}}},
      {"fastsim 100x100", "fastsim", {{"mx", "100"}, {"my", "100"}}},
      {"mim_table", "mim_table", {{"table", table_path}}},
      {"mim 8", "mim", {{"elements", "8"}}},
      {"mim 12", "mim", {{"elements", "12"}}},
      {"mim 16", "mim", {{"elements", "16"}}},
      {"mim 24", "mim", {{"elements", "24"}}},
  };
  const int ref_elements = opt.quick ? 16 : opt.reference_elements;
  models.push_back({fmt::format("mim {} (reference)", ref_elements), "mim",
                    {{"elements", std::to_string(ref_elements)}}});

  // Forces of every model (first pass, also warms caches), then timing passes.
  std::vector<std::vector<fc::TangentialSolution>> forces(models.size());
  std::vector<double> us(models.size());
  for (std::size_t m = 0; m < models.size(); ++m) {
    const auto model = fc::make_tangential_model(models[m].name, models[m].options);
    const bool reference = m + 1 == models.size();
    double t0 = cpu_seconds();
    for (std::size_t k = 0; k < cases.size(); ++k) forces[m].push_back(model->solve(problem(k)));
    double elapsed = cpu_seconds() - t0;
    long evaluations = static_cast<long>(cases.size());
    if (!reference) {  // timed passes with warm caches
      evaluations = 0;
      t0 = cpu_seconds();
      do {
        for (std::size_t k = 0; k < cases.size(); ++k) (void)model->solve(problem(k));
        evaluations += static_cast<long>(cases.size());
        elapsed = cpu_seconds() - t0;
      } while (elapsed < opt.min_time_s);
    }
    us[m] = 1e6 * elapsed / static_cast<double>(evaluations);
  }
  if (opt.table.empty()) std::filesystem::remove(table_path);

  ContactBenchResult result;
  result.cases = static_cast<int>(cases.size());
  const auto& ref = forces.back();
  for (std::size_t m = 0; m < models.size(); ++m) {
    std::vector<double> err;
    for (std::size_t k = 0; k < cases.size(); ++k) {
      err.push_back(std::hypot(forces[m][k].force_x - ref[k].force_x,
                               forces[m][k].force_y - ref[k].force_y) /
                    (kFriction * kNormalForce));
    }
    std::sort(err.begin(), err.end());
    ContactBenchRow row;
    row.label = models[m].label;
    row.us_per_eval = us[m];
    double sum = 0.0;
    for (double e : err) sum += e;
    row.mean_error = sum / static_cast<double>(err.size());
    row.p95_error = err[static_cast<std::size_t>(std::ceil(0.95 * err.size())) - 1];
    row.max_error = err.back();
    result.rows.push_back(row);
  }
  return result;
}

void write_contact_bench_csv(const ContactBenchResult& result, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write", path));
  out << "model,us_per_eval,mean_error_mu_fn,p95_error_mu_fn,max_error_mu_fn\n";
  for (const auto& r : result.rows) {
    out << fmt::format("{},{:.6g},{:.6g},{:.6g},{:.6g}\n", r.label, r.us_per_eval, r.mean_error,
                       r.p95_error, r.max_error);
  }
}

}  // namespace ferro::scenarios
