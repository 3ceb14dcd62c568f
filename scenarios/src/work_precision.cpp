// Work-precision study: see work_precision.hpp.
#include "ferro/scenarios/work_precision.hpp"
#include "ferro/scenarios/number_text.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iterator>
#include <limits>
#include <stdexcept>

#include "ferro/io/text_writer.hpp"
#include "ferro/scenarios/model_factory.hpp"

namespace ferro::scenarios {
namespace {

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// An entry is `method`, `method:max_order` (an order cap) or `method@h` (a fixed step h [s],
// arkode_erk / arkode_dirk / odeint_bs3; run once, the tolerances then only scale the Newton
// test).
vehicle::IntegratorSettings parse_entry(const Scene& scene, const std::string& full_entry,
                                        double rtol, double atol_per_rtol) {
  vehicle::IntegratorSettings s = scene.solver;
  s.fixed_step = 0.0;
  std::string entry = full_entry;
  if (const auto at = entry.find('@'); at != std::string::npos) {
    const std::string step = entry.substr(at + 1);
    const double h = strict_number(step);
    if (!(h > 0.0)) {
      throw std::invalid_argument(fmt::format(
          "--integrators: '{}': expected method@step with a step > 0 s (e.g. arkode_erk@5e-4)",
          full_entry));
    }
    s.fixed_step = h;
    entry = entry.substr(0, at);
  }
  const auto colon = entry.find(':');
  s.method = entry.substr(0, colon);
  s.max_order = 0;
  if (colon != std::string::npos) {
    const std::string order = entry.substr(colon + 1);
    char* end = nullptr;
    const long v = std::strtol(order.c_str(), &end, 10);
    if (order.empty() || end == nullptr || *end != '\0') {
      throw std::invalid_argument(fmt::format(
          "--integrators: '{}': expected method or method:max_order (e.g. cvode_bdf:2)", entry));
    }
    s.max_order = static_cast<int>(v);
  }
  s.rtol = rtol;
  s.atol = rtol * atol_per_rtol;
  s.validate(fmt::format("--integrators '{}'", full_entry));
  return s;
}

struct Trajectory {
  vehicle::IntegrationResult result;
  double cpu_seconds = 0.0;
  std::vector<std::vector<double>> compared;  ///< per output time, the compared states
};

Trajectory integrate(const vehicle::OdeSystem& system, const std::vector<double>& x0,
                     const std::vector<double>& times, const vehicle::IntegratorSettings& s,
                     const std::vector<std::size_t>& index) {
  Trajectory out;
  out.compared.reserve(times.size());
  auto integrator = vehicle::make_integrator(s);
  const double start = cpu_now();
  out.result = integrator->integrate(system, x0, times, [&](double, std::span<const double> x) {
    std::vector<double> row(index.size());
    for (std::size_t k = 0; k < index.size(); ++k) row[k] = x[index[k]];
    out.compared.push_back(std::move(row));
    return true;
  });
  out.cpu_seconds = cpu_now() - start;
  return out;
}

// Parabola through (i-1, i, i+1) on a uniform or non-uniform grid: value at its vertex.
double refined_extremum(const std::vector<double>& t, const std::vector<double>& x,
                        std::size_t i) {
  if (i == 0 || i + 1 >= x.size()) return x[i];
  const double h0 = t[i] - t[i - 1], h1 = t[i + 1] - t[i];
  const double d0 = (x[i] - x[i - 1]) / h0, d1 = (x[i + 1] - x[i]) / h1;
  const double a = (d1 - d0) / (h0 + h1);  // x = x_i + b (s - t_i) + a (s - t_i)^2
  if (a == 0.0) return x[i];
  const double b = d0 + a * h0;
  return x[i] - b * b / (4.0 * a);
}

}  // namespace

CycleStatistics cycle_statistics(const std::vector<double>& t, const std::vector<double>& x) {
  if (t.size() != x.size()) throw std::invalid_argument("cycle_statistics: sizes differ");
  CycleStatistics c;
  c.frequency = std::numeric_limits<double>::quiet_NaN();
  if (x.size() < 3) return c;
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  c.amplitude = 0.5 * (refined_extremum(t, x, static_cast<std::size_t>(hi - x.begin())) -
                       refined_extremum(t, x, static_cast<std::size_t>(lo - x.begin())));
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double first = 0.0, last = 0.0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double a = x[i] - mean, b = x[i + 1] - mean;
    if (a < 0.0 && b >= 0.0) {
      const double tc = t[i] - a * (t[i + 1] - t[i]) / (b - a);
      if (c.crossings == 0) first = tc;
      last = tc;
      ++c.crossings;
    }
  }
  if (c.crossings >= 2) c.frequency = (c.crossings - 1) / (last - first);
  return c;
}

namespace {

// Every option checked before any run.
void check_options(const WorkPrecisionOptions& options) {
  if (options.rtols.empty()) throw std::invalid_argument("--rtols: give at least one tolerance");
  for (double r : options.rtols) {
    if (!(r > 0.0 && r < 1.0)) {
      throw std::invalid_argument(fmt::format("--rtols: each must lie in (0, 1), got {}", r));
    }
  }
  if (!(options.atol_per_rtol > 0.0) || !std::isfinite(options.atol_per_rtol)) {
    throw std::invalid_argument(
        fmt::format("--atol-per-rtol: must be finite and > 0, got {}", options.atol_per_rtol));
  }
  if (!(options.reference_rtol > 0.0 && options.reference_rtol < 1.0)) {
    throw std::invalid_argument(
        fmt::format("--reference-rtol: must lie in (0, 1), got {}", options.reference_rtol));
  }
  if (!(options.settle >= 0.0) || !std::isfinite(options.settle)) {
    throw std::invalid_argument(
        fmt::format("--settle: must be finite and >= 0 s, got {}", options.settle));
  }
  if (options.metric != "pointwise" && options.metric != "cycle") {
    throw std::invalid_argument(
        fmt::format("--metric: allowed values: pointwise, cycle; got '{}'", options.metric));
  }
  if (!(options.target_error > 0.0)) {
    throw std::invalid_argument(
        fmt::format("--target-error: must be > 0, got {}", options.target_error));
  }
}

// The compared states: options.states by name, else every wheelset's lateral and yaw state.
std::vector<std::size_t> compared_state_indices(const std::vector<vehicle::SignalInfo>& info,
                                                const WorkPrecisionOptions& options) {
  std::vector<std::size_t> index;
  if (options.states.empty()) {
    for (std::size_t i = 0; i < info.size(); ++i) {
      const std::string& n = info[i].name;
      const bool wheelset = n.rfind("wheelset", 0) == 0;
      const bool lateral = n.size() > 2 && n.compare(n.size() - 2, 2, ".y") == 0;
      const bool yaw = n.size() > 4 && n.compare(n.size() - 4, 4, ".yaw") == 0;
      if (wheelset && (lateral || yaw)) index.push_back(i);
    }
    if (index.empty()) {
      throw std::invalid_argument(
          "--states: the model has no wheelset lateral or yaw state; name the states to compare");
    }
  } else {
    for (const std::string& name : options.states) {
      const auto it = std::find_if(info.begin(), info.end(),
                                   [&](const vehicle::SignalInfo& s) { return s.name == name; });
      if (it == info.end()) {
        std::vector<std::string> names;
        for (const auto& s : info) names.push_back(s.name);
        throw std::invalid_argument(
            fmt::format("--states: unknown state '{}'; states: {}", name, fmt::join(names, ", ")));
      }
      index.push_back(static_cast<std::size_t>(it - info.begin()));
    }
  }
  return index;
}

// The state at `settle` of the reference integration from x0 (x0 itself when settle is 0).
std::vector<double> settled_state(const vehicle::OdeSystem& system, std::vector<double> x0,
                                  const vehicle::IntegratorSettings& ref_settings,
                                  const Scene& scene, const WorkPrecisionOptions& options,
                                  WorkPrecisionReport& report) {
  const double t0 = options.settle;
  if (t0 > 0.0) {
    std::vector<double> settled;
    auto integrator = vehicle::make_integrator(ref_settings);
    const double start = cpu_now();
    const auto res =
        integrator->integrate(system, x0, vehicle::output_grid(0.0, t0, scene.output.interval),
                              [&](double, std::span<const double> x) {
                                settled.assign(x.begin(), x.end());
                                return true;
                              });
    report.settle_cpu_seconds = cpu_now() - start;
    if (res.status != vehicle::IntegrationResult::Status::kCompleted) {
      throw std::runtime_error(fmt::format(
          "work-precision: the reference's settling run (cvode_bdf, rtol {}) stopped at t = {} "
          "s of {} s: {}",
          options.reference_rtol, res.t_reached, t0, res.message));
    }
    x0 = settled;
  }
  return x0;
}

// Error and cycle error of a completed run against the reference (see the header).
void measure_errors(WorkPrecisionPoint& p, const Trajectory& run, const Trajectory& ref,
                    const std::vector<double>& peak, const std::vector<CycleStatistics>& ref_cycles,
                    const std::vector<CycleStatistics>& run_cycles) {
  const std::size_t n = peak.size();
  double err = 0.0;
  for (std::size_t t = 0; t < run.compared.size(); ++t) {
    for (std::size_t k = 0; k < n; ++k) {
      if (peak[k] > 0.0) {
        err = std::max(err, std::abs(run.compared[t][k] - ref.compared[t][k]) / peak[k]);
      }
    }
  }
  p.error = err;
  double cyc = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const auto& r = ref_cycles[k];
    if (r.amplitude > 0.0) {
      cyc = std::max(cyc, std::abs(run_cycles[k].amplitude - r.amplitude) / r.amplitude);
    }
    // A frequency needs at least two whole periods in the reference.
    if (r.crossings >= 3) {
      const double f = run_cycles[k].frequency;
      cyc = std::max(cyc, std::isfinite(f) ? std::abs(f - r.frequency) / r.frequency
                                           : std::numeric_limits<double>::infinity());
    }
  }
  p.cycle_error = cyc;
}

}  // namespace

void check_work_precision(const Scene& scene, const WorkPrecisionOptions& options) {
  check_options(options);
  if (options.settle > 0.0) {
    const std::string problem =
        track_extent_problem(scene, options.settle + scene.simulation.t_end);
    if (!problem.empty()) throw std::invalid_argument(fmt::format("--settle: {}", problem));
  }
}

WorkPrecisionReport run_work_precision(const Scene& scene, const WorkPrecisionOptions& options) {
  check_work_precision(scene, options);
  // Every entry is checked before any run.
  std::vector<vehicle::IntegratorSettings> settings;
  std::vector<std::string> labels;
  for (const std::string& entry : options.integrators) {
    const bool fixed = entry.find('@') != std::string::npos;
    for (double r : options.rtols) {
      settings.push_back(parse_entry(scene, entry, r, options.atol_per_rtol));
      labels.push_back(entry);
      if (fixed) break;  // a fixed step does not depend on the tolerance: one run
    }
  }
  if (settings.empty()) throw std::invalid_argument("--integrators: give at least one");

  WorkPrecisionReport report;
  report.t_end = scene.simulation.t_end;
  const double setup_start = cpu_now();
  const auto system = build_system(scene, scene.simulation.speed, build_resources(scene));
  std::vector<double> x0 = initial_state(scene, *system);
  report.setup_cpu_seconds = cpu_now() - setup_start;
  report.settle = options.settle;
  report.metric = options.metric;

  const auto info = system->state_info();
  const std::vector<std::size_t> index = compared_state_indices(info, options);
  for (std::size_t i : index) report.compared_states.push_back(info[i].name);

  vehicle::IntegratorSettings ref_settings = scene.solver;
  ref_settings.method = "cvode_bdf";
  ref_settings.max_order = 0;
  ref_settings.fixed_step = 0.0;
  ref_settings.rtol = options.reference_rtol;
  ref_settings.atol = options.reference_rtol * options.atol_per_rtol;

  const double t0 = options.settle;
  x0 = settled_state(*system, x0, ref_settings, scene, options, report);
  const std::vector<double> times =
      vehicle::output_grid(t0, t0 + scene.simulation.t_end, scene.output.interval);
  const Trajectory ref = integrate(*system, x0, times, ref_settings, index);
  const auto fill = [](WorkPrecisionPoint& p, const Trajectory& t) {
    p.status = vehicle::to_string(t.result.status);
    p.t_reached = t.result.t_reached;
    p.steps = t.result.steps;
    p.rhs_evaluations = t.result.rhs_evaluations;
    p.cpu_seconds = t.cpu_seconds;
  };
  report.reference.integrator = "cvode_bdf";
  report.reference.settings = ref_settings;
  fill(report.reference, ref);
  report.reference.error = 0.0;
  if (ref.result.status != vehicle::IntegrationResult::Status::kCompleted) {
    throw std::runtime_error(fmt::format(
        "work-precision: the reference run (cvode_bdf, rtol {}) stopped at t = {} s: {}",
        options.reference_rtol, ref.result.t_reached, ref.result.message));
  }
  std::vector<double> peak(index.size(), 0.0);
  for (const auto& row : ref.compared) {
    for (std::size_t k = 0; k < row.size(); ++k) peak[k] = std::max(peak[k], std::abs(row[k]));
  }
  const auto cycles = [&](const Trajectory& tr) {
    std::vector<CycleStatistics> out;
    std::vector<double> x(tr.compared.size());
    for (std::size_t k = 0; k < index.size(); ++k) {
      for (std::size_t i = 0; i < x.size(); ++i) x[i] = tr.compared[i][k];
      out.push_back(cycle_statistics(times, x));
    }
    return out;
  };
  report.reference_cycles = cycles(ref);

  for (std::size_t i = 0; i < settings.size(); ++i) {
    WorkPrecisionPoint p;
    p.integrator = labels[i];
    p.settings = settings[i];
    const Trajectory run = integrate(*system, x0, times, settings[i], index);
    fill(p, run);
    if (run.result.status == vehicle::IntegrationResult::Status::kCompleted &&
        run.compared.size() == ref.compared.size()) {
      measure_errors(p, run, ref, peak, report.reference_cycles, cycles(run));
    } else {
      p.error = std::numeric_limits<double>::quiet_NaN();
      p.cycle_error = p.error;
    }
    report.points.push_back(p);
  }
  for (std::size_t i = 0; i < report.points.size(); ++i) {
    const auto& p = report.points[i];
    const double e = options.metric == "cycle" ? p.cycle_error : p.error;
    if (!(e <= options.target_error)) continue;
    if (!report.best || p.cpu_seconds < report.points[*report.best].cpu_seconds) report.best = i;
  }
  return report;
}

void write_work_precision_csv(const WorkPrecisionReport& report, const std::string& path) {
  io::TextWriter out(path);
  out.write(
      "integrator,max_order,rtol,atol,status,t_reached_s,steps,rhs_evaluations,cpu_s,"
      "cpu_s_per_simulated_s,error,cycle_error\n");
  const auto row = [&](const WorkPrecisionPoint& p) {
    out.print("{},{},{:.3g},{:.3g},{},{:.9g},{},{},{:.6g},{:.6g},{:.6g},{:.6g}\n",
              p.integrator.substr(0, p.integrator.find(':')), p.settings.max_order, p.settings.rtol,
              p.settings.atol, p.status, p.t_reached, p.steps, p.rhs_evaluations, p.cpu_seconds,
              report.t_end > 0.0 ? p.cpu_seconds / report.t_end : 0.0, p.error, p.cycle_error);
  };
  row(report.reference);
  for (const auto& p : report.points) row(p);
  out.close();
}

Parameters parameters(WorkPrecisionOptions& o) {
  return {
      {"integrators", "",
       "method, method:max_order or method@fixed_step, e.g. cvode_bdf cvode_bdf:2 "
       "odeint_rosenbrock4 arkode_erk@5e-4 odeint_bs3@1e-3",
       &o.integrators},
      {"rtols", "-", "relative tolerances", &o.rtols},
      {"atol_per_rtol", "SI state units", "atol = rtol x this", &o.atol_per_rtol},
      {"reference_rtol", "-", "tolerance of the reference run (cvode_bdf)", &o.reference_rtol},
      {"states", "", "states compared (default: every wheelset's y and yaw)", &o.states, false},
      {"target_error", "-", "error the recommended setting must meet", &o.target_error},
      {"settle", "s",
       "settling time: the reference runs this long first and every run starts from its end "
       "state (for limit cycles)",
       &o.settle},
      {"metric", "",
       "error that picks the best setting: pointwise (largest deviation) or cycle (amplitude "
       "and frequency of each compared state)",
       &o.metric},
  };
}

std::string work_precision_report(const Scene& scene, const WorkPrecisionReport& r,
                                  const WorkPrecisionOptions& options) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "work-precision: {} ({} s simulated at {} m/s); model setup {:.3f} CPU-s\n",
                 scene.name, r.t_end, scene.simulation.speed, r.setup_cpu_seconds);
  fmt::format_to(out, "compared: {}\n", fmt::join(r.compared_states, ", "));
  if (r.settle > 0.0) {
    fmt::format_to(
        out, "settled: the reference ran {} s first ({:.3f} CPU-s); compared over [{}, {}] s\n",
        r.settle, r.settle_cpu_seconds, r.settle, r.settle + r.t_end);
  }
  for (std::size_t k = 0; k < r.compared_states.size(); ++k) {
    const auto& c = r.reference_cycles[k];
    fmt::format_to(out, "reference {}: amplitude {:.6g}, frequency {:.6g} Hz\n",
                   r.compared_states[k], c.amplitude, c.frequency);
  }
  fmt::format_to(
      out,
      "| integrator | max order | rtol | atol | status | steps | rhs | CPU s | CPU s per "
      "simulated s | error | cycle error |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  const auto line = [&](const WorkPrecisionPoint& p, const char* note) {
    fmt::format_to(
        out, "| {}{} | {} | {:.0e} | {:.0e} | {} | {} | {} | {:.3f} | {:.4f} | {:.2e} | {:.2e} |\n",
        p.integrator.substr(0, p.integrator.find(':')), note,
        p.settings.max_order == 0 ? std::string("default") : std::to_string(p.settings.max_order),
        p.settings.rtol, p.settings.atol,
        p.status == "completed" ? p.status : fmt::format("{} at {:.4g} s", p.status, p.t_reached),
        p.steps, p.rhs_evaluations, p.cpu_seconds, p.cpu_seconds / r.t_end, p.error, p.cycle_error);
  };
  line(r.reference, " (reference)");
  for (const auto& p : r.points) line(p, "");
  if (r.best) {
    const auto& b = r.points[*r.best];
    fmt::format_to(out,
                   "cheapest within {} error {:.1e}: {} (max order {}) at rtol {:.0e}: {:.4f} "
                   "CPU-s per simulated s, error {:.2e}, cycle error {:.2e}\n",
                   r.metric, options.target_error, b.integrator, b.settings.max_order,
                   b.settings.rtol, b.cpu_seconds / r.t_end, b.error, b.cycle_error);
  } else {
    fmt::format_to(out, "no setting met {} error {:.1e}\n", r.metric, options.target_error);
  }
  return text;
}

}  // namespace ferro::scenarios
