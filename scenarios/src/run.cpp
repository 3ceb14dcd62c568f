#include "ferro/scenarios/run.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <thread>

#include "ferro/scenarios/h5_output.hpp"
#include "ferro/scenarios/model_factory.hpp"

namespace ferro::scenarios {

std::string utc_timestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

namespace {

void write_metadata(H5File& file, const Scene& scene, const std::string& kind) {
  file.set_attribute("/", "program", std::string("ferrodyn"));
  file.set_attribute("/", "version", std::string(FERRO_VERSION));
  file.set_attribute("/", "created_utc", utc_timestamp());
  file.set_attribute("/", "kind", kind);
  file.set_attribute("/", "scene_file", scene.path);
  file.set_attribute("/", "scene_name", scene.name);
  file.set_attribute("/", "model_type", scene.model.type);
  file.set_attribute("/", "integrator", scene.solver.method);
  file.set_attribute("/", "rtol", scene.solver.rtol);
  file.set_attribute("/", "atol", scene.solver.atol);
  file.set_attribute("/", "speed", scene.simulation.speed);
  if (scene.model.type == "vehicle") {
    const auto& w = scene.model.vehicle.wheel_rail;
    file.set_attribute("/", "vehicle", scene.model.vehicle.name);
    file.set_attribute("/", "model_scope", scene.model.selection.scope);
    file.set_attribute("/", "contact_geometry", w.geometry);
    file.set_attribute("/", "tangential_model", w.tangential_model);
    file.set_attribute("/", "acceleration", scene.simulation.acceleration);
  }
  file.set_attribute("/", "units",
                     std::string("SI: m, s, kg, N, rad; each dataset has a 'unit' attribute"));
  file.write_text("/scene/text", scene.text);
}

void set_status(H5File& file, const std::string& status, const std::string& message,
                double t_reached) {
  file.set_attribute("/", "status", status);
  file.set_attribute("/", "status_message", message);
  file.set_attribute("/", "t_reached", t_reached);
  file.flush();
}

std::vector<std::string> resolve_csv(const std::vector<std::string>& asked,
                                     const std::vector<vehicle::SignalInfo>& channels) {
  std::vector<std::string> out;
  for (const auto& name : asked) {
    if (name == "all") {
      for (const auto& c : channels) out.push_back(c.name);
      continue;
    }
    const bool found = std::any_of(channels.begin(), channels.end(),
                                   [&](const auto& c) { return c.name == name; });
    if (!found) throw std::invalid_argument(fmt::format("--csv: unknown signal '{}'", name));
    out.push_back(name);
  }
  return out;
}

}  // namespace

RunSummary run_scene(const Scene& scene, const RunOptions& options) {
  const auto system = build_system(scene, scene.simulation.speed, build_resources(scene));
  const auto x0 = initial_state(scene, *system);
  const auto states = system->state_info();
  const auto derived = system->signal_info();
  RunSummary summary;
  summary.channels = states;
  summary.channels.insert(summary.channels.end(), derived.begin(), derived.end());
  summary.state_count = states.size();
  for (const auto& name : scene.output.plots) {
    const bool found = std::any_of(summary.channels.begin(), summary.channels.end(),
                                   [&](const auto& c) { return c.name == name; });
    if (!found) {
      std::vector<std::string> names;
      for (const auto& c : summary.channels) names.push_back(c.name);
      throw std::invalid_argument(fmt::format("output.plots: unknown signal '{}'; signals: {}",
                                              name, fmt::join(names, ", ")));
    }
  }
  const std::size_t n_states = states.size();
  const std::size_t n_channels = summary.channels.size();
  summary.peak_abs.assign(n_channels, 0.0);
  summary.final_values.assign(n_channels, 0.0);

  const auto times = vehicle::output_grid(0.0, scene.simulation.t_end, scene.output.interval);
  auto integrator = vehicle::make_integrator(scene.solver);
  const auto csv_names = resolve_csv(options.csv.value_or(scene.output.csv), summary.channels);
  std::vector<std::size_t> csv_index;
  for (const auto& name : csv_names) {
    for (std::size_t i = 0; i < n_channels; ++i)
      if (summary.channels[i].name == name) csv_index.push_back(i);
  }

  summary.output_file = options.output_file.empty() ? scene.output.file : options.output_file;
  H5File file = H5File::create(summary.output_file);
  write_metadata(file, scene, "time_simulation");
  set_status(file, "running", "", 0.0);
  std::ofstream csv;
  if (!csv_index.empty()) {
    summary.csv_file =
        std::filesystem::path(summary.output_file).replace_extension(".csv").string();
    csv.open(summary.csv_file);
    if (!csv)
      throw std::runtime_error(fmt::format("cannot create CSV file '{}'", summary.csv_file));
    csv << "time";
    for (auto i : csv_index) csv << ',' << summary.channels[i].name;
    csv << '\n';
  }

  const auto wall_start = std::chrono::steady_clock::now();
  bool stopped_by_request = false;
  try {
    TimeSeriesWriter writer(file, summary.channels, scene.output.flush_seconds);
    std::vector<double> row(n_channels);
    const auto observer = [&](double t, std::span<const double> x) {
      std::copy(x.begin(), x.end(), row.begin());
      system->signals(t, x, std::span<double>(row).subspan(n_states));
      writer.append(t, row);
      for (std::size_t i = 0; i < n_channels; ++i)
        summary.peak_abs[i] = std::max(summary.peak_abs[i], std::abs(row[i]));
      summary.final_values = row;
      if (csv.is_open()) {
        csv << fmt::format("{:.10g}", t);
        for (auto i : csv_index) csv << fmt::format(",{:.10g}", row[i]);
        csv << '\n';
      }
      if (options.progress) options.progress(t);
      if (options.pace > 0.0) {
        std::this_thread::sleep_until(
            wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(t / options.pace)));
      }
      if (options.should_stop && options.should_stop()) {
        stopped_by_request = true;
        return false;
      }
      return true;
    };
    const auto result = integrator->integrate(*system, x0, times, observer);
    writer.flush();
    if (csv.is_open()) csv.flush();
    summary.status = result.status;
    summary.status_text = vehicle::to_string(result.status);
    summary.t_reached = result.t_reached;
    summary.steps = result.steps;
    summary.rhs_evaluations = result.rhs_evaluations;
    summary.samples = writer.samples();
    summary.message = result.message;
    if (stopped_by_request)
      summary.message = fmt::format("{} at t = {:.9g} s", options.stop_reason, result.t_reached);
    if (result.status == vehicle::IntegrationResult::Status::kSolverFailure) {
      // Keep the state where the solver stopped beside the samples.
      file.write_vector("/failure/state", result.state, "SI (see /signals units)",
                        "state at the failure time t_reached, in state order");
    }
  } catch (const std::exception& e) {
    set_status(file, "error", e.what(), summary.t_reached);
    throw;
  }
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  file.set_attribute("/", "wall_time_s", summary.wall_seconds);
  file.set_attribute("/", "steps", summary.steps);
  file.set_attribute("/", "rhs_evaluations", summary.rhs_evaluations);
  set_status(file, summary.status_text, summary.message, summary.t_reached);
  return summary;
}

EigenReport run_eigen(const Scene& scene) {
  EigenReport report;
  const ModelResources resources = build_resources(scene);
  const auto factory = [&scene, &resources](double v) {
    return build_system(scene, v, resources);
  };
  const auto probe = build_system(scene, scene.simulation.speed, resources);
  // About the static equilibrium at the scene's speed (on straight track it does not depend on
  // the speed).
  const std::vector<double> x_eq = equilibrium_state(scene, *probe);
  std::vector<double> speeds(static_cast<std::size_t>(scene.eigen.points));
  for (int i = 0; i < scene.eigen.points; ++i) {
    speeds[static_cast<std::size_t>(i)] =
        scene.eigen.speed_min +
        (scene.eigen.speed_max - scene.eigen.speed_min) * i / (scene.eigen.points - 1);
  }
  report.sweep = vehicle::damping_sweep(factory, speeds, x_eq);
  report.critical_speed = vehicle::critical_speed(factory, scene.eigen.speed_min,
                                                  scene.eigen.speed_max, x_eq, scene.eigen.points);
  report.modes_at_scene_speed = vehicle::linear_modes(*probe, 0.0, x_eq);
  if (scene.model.type == "suspended_wheelset") {
    try {
      report.closed_form_critical_speed = vehicle::analytic_critical_speed(
          scene.model.wheelset, vehicle::creep_coefficients(scene.contact.creep));
      report.closed_form_note = "eq. (151) applies (C11 = C22, I_zz = m e^2, no primary damping)";
    } catch (const std::invalid_argument& e) {
      report.closed_form_note = fmt::format("eq. (151) does not apply: {}", e.what());
    }
  }
  return report;
}

void write_eigen_report(const Scene& scene, const EigenReport& report, const std::string& path) {
  H5File file = H5File::create(path);
  write_metadata(file, scene, "eigen_analysis");
  std::vector<double> v, zeta, freq, re, im;
  for (const auto& p : report.sweep) {
    v.push_back(p.speed);
    zeta.push_back(p.least_damped.damping_ratio);
    freq.push_back(p.least_damped.frequency_hz);
    re.push_back(p.least_damped.eigenvalue.real());
    im.push_back(p.least_damped.eigenvalue.imag());
  }
  file.write_vector("/eigen/speed", v, "m/s", "forward speed of the sweep");
  file.write_vector("/eigen/damping_ratio", zeta, "-", "damping ratio of the least damped mode");
  file.write_vector("/eigen/frequency", freq, "Hz", "frequency of the least damped mode");
  file.write_vector("/eigen/eigenvalue_real", re, "1/s",
                    "real part of the least damped eigenvalue");
  file.write_vector("/eigen/eigenvalue_imag", im, "1/s",
                    "imaginary part of the least damped eigenvalue");
  file.set_attribute("/eigen", "critical_speed", report.critical_speed.value_or(std::nan("")));
  file.set_attribute("/eigen", "closed_form_critical_speed",
                     report.closed_form_critical_speed.value_or(std::nan("")));
  file.set_attribute("/eigen", "closed_form_note", report.closed_form_note);
  file.set_attribute("/", "status", std::string("completed"));
}

}  // namespace ferro::scenarios
