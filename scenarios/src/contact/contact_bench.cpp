// `ferrodyn bench contact`: speed versus error of every tangential model against converged MIM
// (grids N x N and 2N x 2N over the patch, Richardson-extrapolated at second order).
#include "ferro/scenarios/contact_bench.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iterator>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <thread>

#include "ferro/contact/mim/mim.hpp"
#include "ferro/contact/tangential/kalker_coefficients.hpp"
#include "ferro/contact/tangential/mim_table.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/io/csv.hpp"
#include "ferro/io/text_writer.hpp"

namespace ferro::scenarios {

namespace fc = ferro::contact;

namespace {

constexpr double kPatchScale = 5.0e-3;  // c = sqrt(ab) [m]
constexpr double kNormalForce = 80.0e3;
constexpr double kFriction = 0.3;
constexpr double kPoisson = 0.28;
// Two reference values agree when their inputs match to this relative precision (CSV digits).
constexpr double kInputMatch = 1e-9;

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

constexpr double kYoung = 210.0e9;

fc::Material steel() { return fc::Material::from_young(kYoung, kPoisson); }

double semi_axis_x(double ratio) { return kPatchScale * std::sqrt(ratio); }
double semi_axis_y(double ratio) { return kPatchScale / std::sqrt(ratio); }

// Creepages [-, -, 1/m] of a case from its normalised ones (mim_table.hpp units, Kalker C_ij).
fc::Creepage creepage_of(const ContactBenchCase& c) {
  const double a = semi_axis_x(c.ratio), b = semi_axis_y(c.ratio);
  const double g = fc::combine(steel(), steel()).shear_modulus;
  const fc::KalkerCoefficients cij = fc::kalker_coefficients_table(a, b, kPoisson);
  const double s = kFriction * kNormalForce;
  return {c.xi_x * s / (g * a * b * cij.c11), c.xi_y * s / (g * a * b * cij.c22),
          c.spin * s / (g * a * b * std::sqrt(a * b) * cij.c23)};
}

}  // namespace

ContactBenchInput contact_bench_input(const ContactBenchCase& c) {
  const fc::Creepage cr = creepage_of(c);
  ContactBenchInput in;
  in.semi_axis_x = semi_axis_x(c.ratio);
  in.semi_axis_y = semi_axis_y(c.ratio);
  in.normal_force = kNormalForce;
  in.friction = kFriction;
  in.creepage_x = cr.longitudinal;
  in.creepage_y = cr.lateral;
  in.spin = cr.spin;
  in.young = kYoung;
  in.poisson = kPoisson;
  return in;
}

fc::ContactPatch contact_bench_patch(const ContactBenchCase& c) {
  const ContactBenchInput in = contact_bench_input(c);
  return fc::elliptic_patch(in.semi_axis_x, in.semi_axis_y, in.normal_force);
}

fc::TangentialProblem contact_bench_problem(const ContactBenchCase& c,
                                            const fc::ContactPatch& patch) {
  const ContactBenchInput in = contact_bench_input(c);
  fc::TangentialProblem p;
  p.patch = &patch;
  p.friction = in.friction;
  p.body1 = p.body2 = steel();
  p.creepage = fc::Creepage{in.creepage_x, in.creepage_y, in.spin};
  return p;
}

std::vector<ContactBenchCase> contact_bench_cases() {
  std::vector<ContactBenchCase> cases;
  const double ratios[] = {0.2, 0.5, 1.0, 2.0, 5.0};
  const double spins[] = {0.0, 0.5, 1.0, 2.0};
  const double magnitudes[] = {0.2, 0.5, 0.8, 1.2, 2.0, 4.0};  // micro-slip ... full slip
  for (double r : ratios) {
    for (double s : spins) {
      const std::string suffix = s > 0.0 ? "+spin" : "";
      if (s > 0.0) cases.push_back({r, 0.0, 0.0, s, "spin"});
      for (int d = 0; d <= 6; ++d) {
        const double angle = d * std::numbers::pi / 6.0;
        const double cx = d == 3 ? 0.0 : std::cos(angle), sy = d == 6 ? 0.0 : std::sin(angle);
        const std::string kind = (d == 0 || d == 6 ? "x" : d == 3 ? "y" : "x+y") + suffix;
        for (double m : magnitudes) cases.push_back({r, m * cx, m * sy, s, kind});
      }
    }
  }
  return cases;
}

std::vector<ContactBenchReference> contact_bench_reference(
    const std::vector<ContactBenchCase>& cases, int elements, int threads) {
  if (elements < 8 || threads < 1) {
    throw std::invalid_argument(fmt::format(
        "bench contact reference: elements >= 8 and threads >= 1 required, got {} and {}",
        elements, threads));
  }
  std::vector<ContactBenchReference> out(cases.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto worker = [&] {
    fc::mim::HertzMimSolver solver;
    try {
      for (std::size_t k = next++; k < cases.size(); k = next++) {
        const ContactBenchCase& c = cases[k];
        const fc::Creepage cr = creepage_of(c);
        fc::mim::HertzRollingInput in;
        in.semi_axis_x = semi_axis_x(c.ratio);
        in.semi_axis_y = semi_axis_y(c.ratio);
        in.normal_force = kNormalForce;
        in.rolling = {cr.longitudinal, cr.lateral, cr.spin, kFriction};
        in.body1 = in.body2 = steel();
        in.grid_over_patch = true;
        const double s = kFriction * kNormalForce;
        const double sc = s * kPatchScale;
        double f[2][3];
        for (int level = 0; level < 2; ++level) {
          in.elements_minor = elements << level;
          const fc::mim::MimResult r = solver.solve(in);
          if (!r.converged) {
            throw std::runtime_error(fmt::format(
                "bench contact reference: MIM {} x {} did not converge at a/b = {}, xi* = ({}, "
                "{}, {})",
                in.elements_minor, in.elements_minor, c.ratio, c.xi_x, c.xi_y, c.spin));
          }
          f[level][0] = r.force_x / s;
          f[level][1] = r.force_y / s;
          f[level][2] = r.moment_z / sc;
        }
        ContactBenchReference& ref = out[k];
        ref.fx_n = f[0][0];
        ref.fy_n = f[0][1];
        ref.fx_2n = f[1][0];
        ref.fy_2n = f[1][1];
        ref.fx = f[1][0] + (f[1][0] - f[0][0]) / 3.0;
        ref.fy = f[1][1] + (f[1][1] - f[0][1]) / 3.0;
        ref.mz = f[1][2] + (f[1][2] - f[0][2]) / 3.0;
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = cases.size();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  if (failure) std::rethrow_exception(failure);
  return out;
}

bool read_contact_bench_reference(const std::string& path,
                                  const std::vector<ContactBenchCase>& cases,
                                  std::vector<ContactBenchReference>& out, int& elements) {
  std::ifstream in(path);
  if (!in) return false;
  io::CsvReader csv(in, path);
  if (csv.header().size() != 11) {
    throw std::invalid_argument(
        csv.located(fmt::format("expected 11 columns, got {}", csv.header().size())));
  }
  // The grid of the reference solves is named in the first comment ("... elements=40").
  elements = 0;
  for (const std::string& comment : csv.comments()) {
    const auto pos = comment.find("elements=");
    if (pos != std::string::npos) elements = std::atoi(comment.c_str() + pos + 9);
  }
  std::vector<ContactBenchReference> ref;
  std::size_t k = 0;
  const auto same = [](double a, double b) {
    return std::abs(a - b) <= kInputMatch * std::max(1.0, std::abs(b));
  };
  std::vector<std::string> cells;
  while (csv.next(cells)) {
    double v[11];
    for (std::size_t i = 0; i < 11; ++i) v[i] = csv.number(cells, i);
    if (k >= cases.size() || !same(v[0], cases[k].ratio) || !same(v[1], cases[k].xi_x) ||
        !same(v[2], cases[k].xi_y) || !same(v[3], cases[k].spin)) {
      return false;  // another case set
    }
    ref.push_back({v[4], v[5], v[6], v[7], v[8], v[9], v[10]});
    ++k;
  }
  if (k != cases.size() || elements < 8) return false;
  out = std::move(ref);
  return true;
}

void write_contact_bench_reference(const std::string& path,
                                   const std::vector<ContactBenchCase>& cases,
                                   const std::vector<ContactBenchReference>& ref, int elements) {
  io::TextWriter out(path);
  out.print(
      "# ferrodyn bench contact reference: MIM grids N x N and 2N x 2N over the patch, "
      "elements={}\n# forces F = F_2N + (F_2N - F_N)/3 in mu F_n, moment in mu F_n sqrt(ab); "
      "inputs: a/b, normalised xi_x*, xi_y*, phi* (contact/mim_table.hpp units)\n",
      elements);
  out.write("ratio,xi_x,xi_y,spin,fx,fy,mz,fx_n,fy_n,fx_2n,fy_2n\n");
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const ContactBenchCase& c = cases[k];
    const ContactBenchReference& r = ref[k];
    out.print("{:.17g},{:.17g},{:.17g},{:.17g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n",
              c.ratio, c.xi_x, c.xi_y, c.spin, r.fx, r.fy, r.mz, r.fx_n, r.fy_n, r.fx_2n, r.fy_2n);
  }
  out.close();
}

namespace {

// The mim_table file: given, or built (default spec) into a temporary file.
std::string bench_table_path(const ContactBenchOptions& opt) {
  std::string table_path = opt.table;
  if (table_path.empty()) {
    fc::MimTableSpec spec = fc::MimTableSpec::default_spec();
    if (opt.quick) {
      spec.ratio = {0.2, 1.0, 5.0};
      spec.xi_x = {0.0, 0.5, 1.2, 2.5, 5.0};
      spec.xi_y = spec.xi_x;
      spec.spin = {-9.0, -3.0, -1.0, 0.0, 1.0, 3.0, 9.0};
      spec.elements = 8;
      spec.grid = "minor";
    }
    spec.threads = std::max(1, opt.threads);
    table_path = (std::filesystem::temp_directory_path() /
                  fmt::format("ferrodyn_bench_mim_table_{}.h5", static_cast<long>(::getpid())))
                     .string();
    fc::MimTable::build(spec).write_hdf5(table_path);
  }

  return table_path;
}

struct BenchModel {
  std::string label, name;
  fc::ModelOptions options;
};

// Every model and setting the bench times, with the mim_table file.
std::vector<BenchModel> bench_models(const std::string& table_path) {
  return {
      {"kalker_linear", "kalker_linear", {}},
      {"linear_saturated", "linear_saturated", {}},
      {"vermeulen_johnson", "vermeulen_johnson", {}},
      {"shen_hedrick_elkins", "shen_hedrick_elkins", {}},
      {"chopaya", "chopaya", {}},
      {"polach", "polach", {}},
      {"fastsim 20x20", "fastsim", {{"mx", "20"}, {"my", "20"}}},
      {"fastsim 50x50", "fastsim", {{"mx", "50"}, {"my", "50"}}},
      {"fastsim 20x20 elliptic", "fastsim", {{"mx", "20"}, {"my", "20"}, {"bound", "elliptic"}}},
      {"fastsim 10x10 adaptive",
       "fastsim",
       {{"mx", "10"}, {"my", "10"}, {"flexibility", "adaptive"}}},
      {"fastsim 20x20 adaptive",
       "fastsim",
       {{"mx", "20"}, {"my", "20"}, {"flexibility", "adaptive"}}},
      {"fastsim 50x50 adaptive",
       "fastsim",
       {{"mx", "50"}, {"my", "50"}, {"flexibility", "adaptive"}}},
      {"fastrip 8x8", "fastrip", {{"mx", "8"}, {"my", "8"}}},
      {"fastrip 12x12", "fastrip", {{"mx", "12"}, {"my", "12"}}},
      {"fastrip 20x20", "fastrip", {{"mx", "20"}, {"my", "20"}}},
      {"fastrip 12x12 weighted", "fastrip", {{"slip_flexibility", "weighted"}}},
      {"fastrip 12x12 three", "fastrip", {{"slip_flexibility", "three"}}},
      {"mim_table", "mim_table", {{"table", table_path}}},
      {"mim 16 patch", "mim", {{"elements", "16"}, {"grid", "patch"}}},
      {"mim 25 patch", "mim", {{"elements", "25"}, {"grid", "patch"}}},
      {"mim 20 patch_richardson", "mim", {{"elements", "20"}, {"grid", "patch_richardson"}}},
      {"mim 25 patch_richardson", "mim", {{"elements", "25"}, {"grid", "patch_richardson"}}},
  };
}

// Times one model over the cases and measures its errors against the reference.
ContactBenchRow bench_row(const BenchModel& e, const std::vector<ContactBenchCase>& cases,
                          const std::vector<fc::TangentialProblem>& problems,
                          const std::vector<ContactBenchReference>& reference, double min_time_s) {
  const auto problem = [&](std::size_t k) -> const fc::TangentialProblem& { return problems[k]; };
  const double s = kFriction * kNormalForce;
  const auto model = fc::make_tangential_model(e.name, e.options);
  std::vector<fc::TangentialSolution> forces;
  double t0 = cpu_seconds();
  for (std::size_t k = 0; k < cases.size(); ++k) forces.push_back(model->solve(problem(k)));
  double elapsed = cpu_seconds() - t0;
  long evaluations = static_cast<long>(cases.size());
  if (elapsed < min_time_s) {  // timed passes with warm caches
    evaluations = 0;
    t0 = cpu_seconds();
    do {
      for (std::size_t k = 0; k < cases.size(); ++k) (void)model->solve(problem(k));
      evaluations += static_cast<long>(cases.size());
      elapsed = cpu_seconds() - t0;
    } while (elapsed < min_time_s);
  }
  ContactBenchRow row;
  row.label = e.label;
  row.us_per_eval = 1e6 * elapsed / static_cast<double>(evaluations);
  std::vector<double> err;
  double sum_spin = 0.0, sum_plain = 0.0, sum_mz = 0.0;
  int n_spin = 0, n_plain = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const double fx = forces[k].force_x / s, fy = forces[k].force_y / s;
    const double ex = std::hypot(fx - reference[k].fx, fy - reference[k].fy);
    err.push_back(ex);
    (cases[k].spin != 0.0 ? sum_spin : sum_plain) += ex;
    (cases[k].spin != 0.0 ? n_spin : n_plain) += 1;
    sum_mz += std::abs(forces[k].moment_z / (s * kPatchScale) - reference[k].mz);
    row.max_force = std::max(row.max_force, std::hypot(fx, fy));
  }
  double sum = 0.0;
  for (double v : err) sum += v;
  std::sort(err.begin(), err.end());
  row.mean_error = sum / static_cast<double>(err.size());
  row.p95_error =
      err[static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(err.size()))) - 1];
  row.max_error = err.back();
  row.mean_no_spin = n_plain > 0 ? sum_plain / n_plain : 0.0;
  row.mean_spin = n_spin > 0 ? sum_spin / n_spin : 0.0;
  row.mz_mean_error = sum_mz / static_cast<double>(cases.size());
  return row;
}

}  // namespace

ContactBenchResult run_contact_bench(const ContactBenchOptions& opt) {
  if (opt.reference_elements < 8) {
    throw std::invalid_argument(fmt::format("--reference-elements: must be >= 8, got {}",
                                            opt.reference_elements));
  }
  if (opt.threads < 1)
    throw std::invalid_argument(fmt::format("--threads: must be >= 1, got {}", opt.threads));
  ContactBenchResult result;
  std::vector<ContactBenchCase> cases = contact_bench_cases();
  if (opt.quick) {  // 15 cases spread over the ratios, spins, directions and magnitudes
    std::vector<ContactBenchCase> sub;
    for (std::size_t k = 0; k < 15; ++k) sub.push_back(cases[(k * 571 + 13) % cases.size()]);
    cases = sub;
  }
  result.cases = cases;

  // Reference: from the file when it holds this case set, else computed (and cached).
  const int ref_elements = opt.quick ? 12 : opt.reference_elements;
  int file_elements = 0;
  if (!opt.reference.empty() && !opt.quick &&
      read_contact_bench_reference(opt.reference, cases, result.reference, file_elements)) {
    result.reference_from_file = true;
    result.reference_elements = file_elements;
  } else {
    result.reference = contact_bench_reference(cases, ref_elements, opt.threads);
    result.reference_elements = ref_elements;
    if (!opt.reference.empty() && !opt.quick) {
      write_contact_bench_reference(opt.reference, cases, result.reference, ref_elements);
    }
  }

  const std::string table_path = bench_table_path(opt);

  std::vector<fc::ContactPatch> patches(cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) patches[k] = contact_bench_patch(cases[k]);
  // Problems prepared once: the timed loops contain the model evaluations only.
  std::vector<fc::TangentialProblem> problems(cases.size());
  for (std::size_t k = 0; k < cases.size(); ++k) {
    problems[k] = contact_bench_problem(cases[k], patches[k]);
  }
  for (const BenchModel& e : bench_models(table_path))
    result.rows.push_back(bench_row(e, cases, problems, result.reference, opt.min_time_s));
  if (opt.table.empty()) std::filesystem::remove(table_path);
  return result;
}

std::string write_contact_bench_csv_in(const ContactBenchResult& result, const std::string& dir) {
  std::filesystem::create_directories(dir);
  const std::string csv = (std::filesystem::path(dir) / "bench_contact.csv").string();
  write_contact_bench_csv(result, csv);
  return csv;
}

void write_contact_bench_csv(const ContactBenchResult& result, const std::string& path) {
  io::TextWriter out(path);
  out.write(
      "model,us_per_eval,mean_error_mu_fn,p95_error_mu_fn,max_error_mu_fn,mean_no_spin,"
      "mean_spin,mz_mean_error,max_force_mu_fn\n");
  for (const auto& r : result.rows) {
    out.print("{},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", r.label,
              r.us_per_eval, r.mean_error, r.p95_error, r.max_error, r.mean_no_spin, r.mean_spin,
              r.mz_mean_error, r.max_force);
  }
  out.close();
}

Parameters parameters(ContactBenchOptions& o) {
  return {
      {"reference_elements", "", "reference MIM: N (grids N x N and 2N x 2N over the patch)",
       &o.reference_elements},
      {"reference", "",
       "reference CSV: read when it holds this case set, else computed and written (shipped: "
       "tests/data/contact_bench_reference.csv)",
       &o.reference, false},
      {"threads", "", "threads of the reference computation", &o.threads},
      {"table", "", "mim_table HDF5 file (default: build the default table)", &o.table, false},
      {"min_time", "s", "timing: minimum CPU time per model", &o.min_time_s},
      {"quick", "", "15 cases, coarse reference and table (smoke test)", &o.quick},
  };
}

std::vector<ContactBenchGridRow> contact_bench_grid_study(const ContactBenchResult& r,
                                                          int threads) {
  const int n = r.reference_elements;
  std::vector<ContactBenchCase> study;
  std::vector<std::size_t> index;
  for (std::size_t k = 0; k < r.cases.size(); ++k) {
    const auto& c = r.cases[k];
    const bool spin = c.kind == "spin" && c.spin == 1.0;
    const bool creep = c.spin == 0.0 && c.kind == "x+y" && c.xi_y > 0.0 &&
                       std::abs(std::hypot(c.xi_x, c.xi_y) - 0.8) < 1e-9 && c.xi_x > c.xi_y;
    if (spin || creep) {
      study.push_back(c);
      index.push_back(k);
    }
  }
  std::vector<ContactBenchGridRow> rows;
  if (study.empty() || n < 16) return rows;
  const auto half = contact_bench_reference(study, n / 2, threads);
  for (std::size_t j = 0; j < study.size(); ++j) {
    const auto& ref = r.reference[index[j]];
    const double d1 = std::hypot(half[j].fx_n - ref.fx_n, half[j].fy_n - ref.fy_n);
    const double d2 = std::hypot(ref.fx_n - ref.fx_2n, ref.fy_n - ref.fy_2n);
    rows.push_back(
        {study[j], half[j].fy_n, ref.fy_n, ref.fy_2n, ref.fy, d2 > 0.0 ? std::log2(d1 / d2) : 0.0});
  }
  return rows;
}

double contact_bench_mean_correction(const ContactBenchResult& r) {
  double corr = 0.0;
  for (const auto& ref : r.reference) corr += std::hypot(ref.fx - ref.fx_2n, ref.fy - ref.fy_2n);
  return corr / static_cast<double>(r.reference.size());
}

std::string contact_bench_report(const ContactBenchResult& r, int threads) {
  std::string text;
  auto out = std::back_inserter(text);
  const int n = r.reference_elements;
  const auto study = contact_bench_grid_study(r, threads);
  if (!study.empty()) {
    fmt::format_to(out, "Reference grid study (MIM over the patch; F in mu F_n):\n");
    fmt::format_to(out,
                   "| a/b | case | F_y ({0}) | F_y ({1}) | F_y ({2}) | extrapolated | order |\n"
                   "|---|---|---|---|---|---|---|\n",
                   n / 2, n, 2 * n);
    for (const auto& g : study) {
      fmt::format_to(out, "| {} | {} | {:.5f} | {:.5f} | {:.5f} | {:.5f} | {:.2f} |\n", g.c.ratio,
                     g.c.kind == "spin" ? "spin 1" : "creep 0.8 @ 30 deg", g.fy_half, g.fy_n,
                     g.fy_2n, g.fy_extrapolated, g.order);
    }
  }
  fmt::format_to(out,
                 "{} Hertzian cases; reference MIM {} / {} over the patch{}, mean Richardson "
                 "correction {:.5f} mu F_n; error = |F_t - F_t,ref| / (mu F_n); CPU time per "
                 "evaluation\n",
                 r.cases.size(), n, 2 * n, r.reference_from_file ? " (from file)" : "",
                 contact_bench_mean_correction(r));
  fmt::format_to(
      out,
      "| model | us / eval | mean | 95th pct | max | mean no spin | mean spin | M_z mean "
      "| max abs F |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& row : r.rows) {
    fmt::format_to(out,
                   "| {} | {:.3g} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} "
                   "|\n",
                   row.label, row.us_per_eval, row.mean_error, row.p95_error, row.max_error,
                   row.mean_no_spin, row.mean_spin, row.mz_mean_error, row.max_force);
  }
  return text;
}

}  // namespace ferro::scenarios
