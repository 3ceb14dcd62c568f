#include "ferro/scenarios/run.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <exception>
#include <filesystem>
#include <optional>
#include <thread>

#include "ferro/io/text_writer.hpp"
#include "ferro/scenarios/analysis/run_context.hpp"
#include "ferro/scenarios/analysis/scene_analysis.hpp"
#include "ferro/scenarios/h5_output.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/yaml_reader.hpp"
#include "model_errors.hpp"

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
    analysis::write_run_context(file, analysis::run_context(scene));
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
                                     const std::vector<vehicle::SignalInfo>& channels,
                                     const std::string& where) {
  std::vector<std::string> out;
  for (const auto& name : asked) {
    if (name == "all") {
      for (const auto& c : channels) out.push_back(c.name);
      continue;
    }
    const bool found = std::any_of(channels.begin(), channels.end(),
                                   [&](const auto& c) { return c.name == name; });
    if (!found) throw std::invalid_argument(fmt::format("{}: unknown signal '{}'", where, name));
    out.push_back(name);
  }
  return out;
}

}  // namespace

void check_output_on_steps(double interval, const vehicle::IntegratorSettings& solver,
                           const std::string& where) {
  if (!(solver.fixed_step > 0.0) || !vehicle::takes_fixed_step(solver.method)) return;
  const double ratio = interval / solver.fixed_step;
  if (ratio >= 1.0 - 1e-9 && std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio) return;
  throw std::invalid_argument(fmt::format(
      "{}: {} s is not a whole multiple of solver.fixed_step {} s ({} at a fixed step samples "
      "at its steps only: forces between steps would come from interpolated states); choose "
      "an interval of k x {} s, or a step that divides {} s",
      where, interval, solver.fixed_step, solver.method, solver.fixed_step, interval));
}

std::uint64_t output_sample_count(double t_end, double interval, const std::string& where) {
  if (!(interval > 0.0) || !std::isfinite(interval)) {
    throw std::invalid_argument(
        fmt::format("{}: must be a positive finite number of seconds, got {}", where, interval));
  }
  if (!(t_end >= 0.0) || !std::isfinite(t_end)) {
    throw std::invalid_argument(fmt::format("{}: t_end must be finite and >= 0 s, got {}", where,
                                            t_end));
  }
  const double n = std::floor(t_end / interval + 1e-9) + 1.0;
  if (!(n <= kMaxOutputSamples)) {
    throw std::invalid_argument(fmt::format(
        "{}: {} s over t_end = {} s gives {:.3g} samples; at most {:.0e} are allowed (use an "
        "interval of at least {:.3g} s)",
        where, interval, t_end, n, kMaxOutputSamples, t_end / kMaxOutputSamples));
  }
  return static_cast<std::uint64_t>(n) + (t_end - (n - 1.0) * interval > 1e-9 * interval ? 1 : 0);
}

namespace {

// Output times i * interval for i in [first, last], plus t_end after the last regular time when
// it is not on the grid (the same times as vehicle::output_grid, produced block by block).
std::vector<double> output_block(std::uint64_t first, std::uint64_t last, std::uint64_t regular,
                                 double t_end, double interval) {
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(last - first + 1));
  for (std::uint64_t i = first; i <= last; ++i) {
    times.push_back(i < regular ? static_cast<double>(i) * interval : t_end);
  }
  return times;
}

// Waits until wall time `until`, returning early (false) when `should_stop` fires.
bool pace_until(std::chrono::steady_clock::time_point until,
                const std::function<bool()>& should_stop) {
  constexpr auto kPoll = std::chrono::milliseconds(20);  // reaction time to a stop request
  while (std::chrono::steady_clock::now() < until) {
    if (should_stop && should_stop()) return false;
    std::this_thread::sleep_until(std::min(until, std::chrono::steady_clock::now() + kPoll));
  }
  return true;
}

// The CSV file beside the HDF5 output; a device output (e.g. /dev/null) takes the CSV too.
std::string csv_path_for(const std::string& output) {
  std::error_code ec;
  const auto status = std::filesystem::status(output, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    return output;
  return std::filesystem::path(output).replace_extension(".csv").string();
}

}  // namespace

namespace {

// What run_scene decides before its first step; every check of this is also what check_scene()
// makes.
struct RunPlan {
  std::unique_ptr<vehicle::OdeSystem> system;
  std::vector<vehicle::SignalInfo> channels;  // states then derived signals
  std::size_t state_count = 0;
  std::vector<std::size_t> csv_index;
  std::unique_ptr<vehicle::Integrator> integrator;
  std::string output_file, csv_file;
};

// The plan; errors as the model and the tables raise them (plan_run locates them).
RunPlan plan_run_unlocated(const Scene& scene, const RunOptions& options) {
  RunPlan plan;
  plan.system = build_run_system(scene, scene.simulation.speed, build_resources(scene));
  check_initial_state(scene, *plan.system);
  const auto states = plan.system->state_info();
  const auto derived = plan.system->signal_info();
  plan.channels = states;
  plan.channels.insert(plan.channels.end(), derived.begin(), derived.end());
  plan.state_count = states.size();
  // An initial perturbation beyond a state's bound would start the run diverged.
  for (const auto& bound : plan.system->state_bounds()) {
    const std::string& name = states[bound.index].name;
    const auto it = scene.simulation.initial.find(name);
    if (it == scene.simulation.initial.end() || std::abs(it->second) <= bound.limit) continue;
    const auto at = scene.simulation.initial_position.find(name);
    const auto [line, col] =
        at == scene.simulation.initial_position.end() ? std::pair{0, 0} : at->second;
    throw YamlInputError(scene.path, line, col, "simulation.initial." + name,
                         fmt::format("{} {} lies beyond the bound +-{:.6g} {} of this state ({})",
                                     it->second, states[bound.index].unit, bound.limit,
                                     states[bound.index].unit, bound.reason));
  }
  for (const auto& name : scene.output.plots) {
    const bool found = std::any_of(plan.channels.begin(), plan.channels.end(),
                                   [&](const auto& c) { return c.name == name; });
    if (!found) {
      std::vector<std::string> names;
      for (const auto& c : plan.channels) names.push_back(c.name);
      throw std::invalid_argument(fmt::format("output.plots: unknown signal '{}'; signals: {}",
                                              name, fmt::join(names, ", ")));
    }
  }
  (void)output_sample_count(scene.simulation.t_end, scene.output.interval);
  if (!(options.pace >= 0.0))
    throw std::invalid_argument(fmt::format("pace: must be >= 0, got {}", options.pace));
  plan.integrator = vehicle::make_integrator(scene.solver);
  const auto csv_names = resolve_csv(options.csv.value_or(scene.output.csv), plan.channels,
                                     options.csv ? "--csv" : "output.csv");
  for (const auto& name : csv_names) {
    for (std::size_t i = 0; i < plan.channels.size(); ++i)
      if (plan.channels[i].name == name) plan.csv_index.push_back(i);
  }
  plan.output_file = options.output_file.empty() ? scene.output.file : options.output_file;
  if (!plan.csv_index.empty()) plan.csv_file = csv_path_for(plan.output_file);
  return plan;
}

RunPlan plan_run(const Scene& scene, const RunOptions& options) {
  try {
    return plan_run_unlocated(scene, options);
  } catch (const std::invalid_argument&) {
    detail::rethrow_located(scene, std::current_exception());
  }
}

// The outputs of a run: the scene's inputs are never written, an existing file only with
// options.overwrite.
OutputSet run_outputs(const Scene& scene, const RunOptions& options) {
  OutputRules rules;
  rules.overwrite = options.overwrite;
  rules.inputs = scene_inputs(scene);
  return OutputSet(std::move(rules));
}

const char* output_option(const RunOptions& options) {
  return options.output_file.empty() ? "output.file" : "-o";
}

}  // namespace

void check_scene(const Scene& scene, const RunOptions& options) {
  const RunPlan plan = plan_run(scene, options);
  OutputRules rules;
  rules.inputs = scene_inputs(scene);
  rules.overwrite = true;  // whether the file exists is the run's business, not the scene's
  OutputSet outputs(std::move(rules));
  if (options.write_output) outputs.check(plan.output_file, output_option(options));
}

namespace {

/// Writes the opening of a run's HDF5 file: the scene's metadata and warnings, status
/// "running", no samples.
void write_run_header(H5File& file, const Scene& scene) {
  write_metadata(file, scene, "time_simulation");
  const auto warnings = scene_warnings(scene);
  file.set_attribute("/", "warning_count", static_cast<long>(warnings.size()));
  file.set_attribute("/", "warnings", fmt::format("{}", fmt::join(warnings, "\n")));
  set_status(file, "running", "", 0.0);
  file.set_attribute("/", "samples", 0L);
}

/// Opens the CSV of the asked signals and writes its header line.
void open_csv(std::optional<io::TextWriter>& csv, const OutputFile& csv_out, const RunPlan& plan,
              const std::vector<vehicle::SignalInfo>& channels) {
  // The CSV leaves the HDF5 writer's reserve free, so the HDF5 file can always be closed.
  csv.emplace(csv_out.write_path(), TimeSeriesWriter::kCloseReserve);
  csv->write("time");
  for (auto i : plan.csv_index) csv->print(",{}", channels[i].name);
  csv->write("\n");
}

/// What a run does with each output sample: the derived signals beside the state, the HDF5
/// writer, the CSV, the caller's callback, the summary's peaks and final values, pacing to
/// wall-clock time and stop requests.
struct SampleSink {
  const vehicle::OdeSystem& system;
  const RunPlan& plan;
  const RunOptions& options;
  RunSummary& summary;
  TimeSeriesWriter* writer;  // null without an output file
  io::TextWriter* csv;       // null without a CSV
  std::chrono::steady_clock::time_point wall_start;
  double& last_sample_time;  // without a file, what the caller has received
  std::vector<double> row = std::vector<double>(summary.channels.size());
  bool skip_first = false;  // each block after the first starts at the previous block's end
  bool stopped_by_request = false;

  [[nodiscard]] bool stop_requested() const { return options.should_stop && options.should_stop(); }

  /// The observer: false stops the integration (a stop request).
  bool operator()(double t, std::span<const double> x) {
    if (skip_first) {
      skip_first = false;
      return true;
    }
    const std::size_t n_channels = row.size();
    std::copy(x.begin(), x.end(), row.begin());
    system.signals(t, x, std::span<double>(row).subspan(plan.state_count));
    if (writer) writer->append(t, row);
    ++summary.samples;
    last_sample_time = t;
    if (options.on_sample) options.on_sample(t, row);
    for (std::size_t i = 0; i < n_channels; ++i)
      summary.peak_abs[i] = std::max(summary.peak_abs[i], std::abs(row[i]));
    summary.final_values = row;
    if (csv) {
      csv->print("{:.10g}", t);
      for (auto i : plan.csv_index) csv->print(",{:.10g}", row[i]);
      csv->write("\n");
    }
    if (options.progress) options.progress(t);
    if (options.pace > 0.0) {
      pace_until(wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                  std::chrono::duration<double>(t / options.pace)),
                 options.should_stop);
    }
    if (stop_requested()) {
      stopped_by_request = true;
      return false;
    }
    return true;
  }
};

/// Between two outputs the integrator polls this before every right-hand side and after every
/// step: a stop request ends the run at once, and samples waiting in the buffer reach the file
/// at least every flush_seconds however long the solver takes to the next output. A write
/// failure here cannot cross the integrator: it stops the run and is kept in `write_failure`.
void watch_stops_and_flushes(vehicle::Integrator& integrator, SampleSink& sink,
                             std::exception_ptr& write_failure) {
  integrator.set_stop_request([&sink, &write_failure] {
    try {
      if (sink.writer) sink.writer->flush_if_due();
    } catch (...) {
      write_failure = std::current_exception();
      return true;
    }
    if (sink.stop_requested()) {
      sink.stopped_by_request = true;
      return true;
    }
    return false;
  });
}

/// Integrates from x0 through the run's n_times output times. The output times go to the
/// integrator block by block, so memory does not grow with the number of samples; the
/// integrator continues each block from the state the previous one reached. Ends at the first
/// block that does not complete; rethrows a write failure caught between two outputs.
vehicle::IntegrationResult integrate_in_blocks(vehicle::Integrator& integrator,
                                               const vehicle::OdeSystem& system,
                                               const std::vector<double>& x0, const Scene& scene,
                                               std::uint64_t n_times, std::uint64_t n_regular,
                                               SampleSink& sink,
                                               const std::exception_ptr& write_failure) {
  const double t_end = scene.simulation.t_end, interval = scene.output.interval;
  const auto observer = [&sink](double t, std::span<const double> x) { return sink(t, x); };
  constexpr std::uint64_t kBlock = 1u << 16;  // output times per block
  vehicle::IntegrationResult result;
  std::vector<double> x = x0;
  for (std::uint64_t first = 0; first < n_times;) {
    const std::uint64_t last = std::min(n_times - 1, first + kBlock);
    const auto times = output_block(first, last, n_regular, t_end, interval);
    sink.skip_first = first > 0;
    auto part = integrator.integrate(system, x, times, observer);
    result.steps += part.steps;
    result.rhs_evaluations += part.rhs_evaluations;
    result.jacobians += part.jacobians;
    result.newton_iterations += part.newton_iterations;
    result.step_splits += part.step_splits;
    result.status = part.status;
    result.t_reached = part.t_reached;
    result.message = part.message;
    result.state = std::move(part.state);
    if (write_failure) std::rethrow_exception(write_failure);
    if (result.status != vehicle::IntegrationResult::Status::kCompleted || last + 1 >= n_times)
      break;
    x = result.state;
    first = last;
  }
  return result;
}

/// The summary of an integration that ended (completed, stopped or failed); after a solver
/// failure, the state where the solver stopped is kept in the file beside the samples.
void record_result(RunSummary& summary, const vehicle::IntegrationResult& result,
                   const SampleSink& sink, const RunOptions& options, H5File* file) {
  summary.status = result.status;
  summary.status_text = vehicle::to_string(result.status);
  // The file's t_reached is its last sample; the solver's own time (a stop or a failure
  // between two outputs) goes into the message.
  summary.t_reached = sink.writer ? sink.writer->last_written_time() : sink.last_sample_time;
  summary.steps = result.steps;
  summary.rhs_evaluations = result.rhs_evaluations;
  summary.jacobians = result.jacobians;
  summary.newton_iterations = result.newton_iterations;
  summary.step_splits = result.step_splits;
  summary.message = result.message;
  if (sink.stopped_by_request ||
      result.status == vehicle::IntegrationResult::Status::kInterrupted) {
    summary.message = fmt::format("{} at t = {:.9g} s", options.stop_reason, result.t_reached);
  }
  if (file && result.status == vehicle::IntegrationResult::Status::kSolverFailure) {
    file->write_vector("/failure/state", result.state, "SI (see /signals units)",
                       "state where the solver stopped, at time t, in state order");
    file->set_attribute("/failure/state", "t", result.t_reached);
  }
}

/// Records a failure in the file (status "error" and its message), closes it and gives it its
/// name; throws nothing (on e.g. a full disk the last flush stands).
void record_error(H5File* file, OutputFile* h5, const char* what, double t_reached) {
  try {
    if (file) set_status(*file, "error", what, t_reached);
  } catch (const std::exception&) {
  }
  try {
    if (file) {
      file->close();
      h5->commit();
    }
  } catch (const std::exception&) {
  }
}

/// Writes the closing attributes of a finished run, closes the file and gives every output its
/// name.
void close_run_file(H5File& file, const RunSummary& summary, OutputSet& outputs) {
  file.set_attribute("/", "wall_time_s", summary.wall_seconds);
  file.set_attribute("/", "steps", summary.steps);
  file.set_attribute("/", "rhs_evaluations", summary.rhs_evaluations);
  file.set_attribute("/", "jacobians", summary.jacobians);
  file.set_attribute("/", "newton_iterations", summary.newton_iterations);
  file.set_attribute("/", "step_splits", summary.step_splits);
  set_status(file, summary.status_text, summary.message, summary.t_reached);
  file.close();
  outputs.commit_all();
}

}  // namespace

Parameters parameters(RunOptions& o) {
  return {Parameter{"pace", "",
                    "Simulated seconds per wall-clock second (0: as fast as possible; 1: real "
                    "time)",
                    &o.pace}
              .within({0.0, kNoBound, false, true, ""})};
}

RunSummary run_scene(const Scene& scene, const RunOptions& options) {
  // Everything that can be refused is refused before any file is touched.
  const RunPlan plan = plan_run(scene, options);
  const vehicle::OdeSystem& system = *plan.system;
  RunSummary summary;
  summary.channels = plan.channels;
  summary.state_count = plan.state_count;
  summary.plots = scene.output.plots;  // default: every state
  if (summary.plots.empty()) {
    for (std::size_t i = 0; i < plan.state_count; ++i)
      summary.plots.push_back(plan.channels[i].name);
  }
  const std::size_t n_channels = summary.channels.size();
  summary.peak_abs.assign(n_channels, 0.0);
  summary.final_values.assign(n_channels, 0.0);
  const double t_end = scene.simulation.t_end, interval = scene.output.interval;
  const std::uint64_t n_times = output_sample_count(t_end, interval);
  check_output_on_steps(interval, scene.solver);
  const std::uint64_t n_regular = static_cast<std::uint64_t>(std::floor(t_end / interval + 1e-9)) + 1;

  if (!options.write_output && !plan.csv_index.empty())
    throw std::invalid_argument("csv: signals are written to CSV only beside an output file");
  // Without an output file (options.write_output false) the samples reach the caller through
  // options.on_sample only; with one, it is written as <file>.part and renamed when complete.
  OutputSet outputs = run_outputs(scene, options);
  std::optional<H5File> file;
  OutputFile* h5 = nullptr;
  OutputFile* csv_out = nullptr;
  if (options.write_output) {
    h5 = &outputs.claim(plan.output_file, output_option(options));
    if (!plan.csv_file.empty()) csv_out = &outputs.claim(plan.csv_file, "--csv");
    summary.output_file = h5->path();
    summary.csv_file = plan.csv_file;
    file.emplace(H5File::create(h5->write_path()));
    write_run_header(*file, scene);
  }

  // From here every failure is recorded in the file, which is then renamed to its name.
  const auto wall_start = std::chrono::steady_clock::now();
  std::optional<TimeSeriesWriter> writer;
  double last_sample_time = 0.0;  // without a file, what the caller has received
  try {
    std::optional<io::TextWriter> csv;
    if (csv_out != nullptr) open_csv(csv, *csv_out, plan, summary.channels);
    if (file) writer.emplace(*file, summary.channels, scene.output.flush_seconds);
    const std::vector<double> x0 = initial_state(scene, system);
    TimeSeriesWriter* const sample_writer = writer ? &*writer : nullptr;
    io::TextWriter* const sample_csv = csv ? &*csv : nullptr;
    SampleSink sink{system, plan, options, summary, sample_writer, sample_csv, wall_start,
                    last_sample_time};
    std::exception_ptr write_failure;
    watch_stops_and_flushes(*plan.integrator, sink, write_failure);
    const vehicle::IntegrationResult result = integrate_in_blocks(
        *plan.integrator, system, x0, scene, n_times, n_regular, sink, write_failure);
    if (writer) writer->flush();
    if (csv) csv->close();
    record_result(summary, result, sink, options, file ? &*file : nullptr);
  } catch (const std::exception& e) {
    // Record the failure in the file, close it and give it its name; the original error is what
    // the caller sees.
    summary.t_reached = writer ? writer->last_written_time() : last_sample_time;
    record_error(file ? &*file : nullptr, h5, e.what(), summary.t_reached);
    throw;
  }
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  if (file) close_run_file(*file, summary, outputs);
  return summary;
}

std::optional<double> hopf_speed(const vehicle::LinearisationAtSpeed& family, double v_min,
                                 double v_max, int scan_points) {
  return vehicle::critical_speed(family, v_min, v_max, scan_points, kHopfRelTol);
}

std::optional<double> hopf_speed(const Scene& scene, double v_min, double v_max, int scan_points) {
  return hopf_speed(analysis::with_mode_shapes(scene, linearisation_family(scene)), v_min, v_max,
                    scan_points);
}

EigenReport run_eigen(const Scene& scene) {
  EigenReport report;
  // Each speed about its own equilibrium (for a vehicle the static equilibrium depends on the
  // speed through the creep forces' dependence on it, see linearisation_family()).
  const auto family = analysis::with_mode_shapes(scene, linearisation_family(scene));
  std::vector<double> speeds(static_cast<std::size_t>(scene.eigen.points));
  for (int i = 0; i < scene.eigen.points; ++i) {
    speeds[static_cast<std::size_t>(i)] =
        scene.eigen.speed_min +
        (scene.eigen.speed_max - scene.eigen.speed_min) * i / (scene.eigen.points - 1);
  }
  report.sweep = vehicle::damping_sweep(family, speeds);
  report.critical_speed =
      hopf_speed(family, scene.eigen.speed_min, scene.eigen.speed_max, scene.eigen.points);
  const auto at_scene_speed = family(scene.simulation.speed);
  report.modes_at_scene_speed = vehicle::linear_modes(*at_scene_speed.system, 0.0,
                                                      at_scene_speed.x_eq, at_scene_speed.shapes);
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
  file.write_vector("/eigen/damping_ratio", zeta, "-",
                    "damping ratio of the least damped mode of any class");
  file.write_vector("/eigen/frequency", freq, "Hz", "frequency of the least damped mode");
  file.write_vector("/eigen/eigenvalue_real", re, "1/s",
                    "real part of the least damped eigenvalue");
  file.write_vector("/eigen/eigenvalue_imag", im, "1/s",
                    "imaginary part of the least damped eigenvalue");
  // The hunting mode followed over the speeds, and the least damped mode of each class (NaN
  // where the class has none), with their participation.
  if (!report.sweep.empty() && report.sweep.front().least_damped.kind !=
                                   vehicle::ModeClass::unclassified) {
    std::vector<double> hz, hf, hc, hs;
    for (const auto& p : report.sweep) {
      hz.push_back(p.hunting.damping_ratio);
      hf.push_back(p.hunting.frequency_hz);
      hc.push_back(p.hunting_correlation);
      for (double s : p.hunting.participation) hs.push_back(s);
    }
    file.write_vector("/eigen/hunting_mode/damping_ratio", hz, "-",
                      "damping ratio of the hunting mode (followed down from the highest speed)");
    file.write_vector("/eigen/hunting_mode/frequency", hf, "Hz", "frequency of the hunting mode");
    file.write_vector("/eigen/hunting_mode/correlation", hc, "-",
                      "shape correlation with the hunting mode of the speed above (below 0.5: "
                      "branch lost, the least damped hunting-class mode taken)");
    file.write_matrix("/eigen/hunting_mode/participation", hs, report.sweep.size(),
                      static_cast<std::size_t>(vehicle::kDofGroups), "-",
                      "kinetic-energy share of each group, speeds x groups");
  }
  for (const auto c : {vehicle::ModeClass::hunting, vehicle::ModeClass::contact,
                       vehicle::ModeClass::longitudinal, vehicle::ModeClass::body,
                       vehicle::ModeClass::track}) {
    const std::string name = vehicle::to_string(c);
    std::vector<double> cz, cf, share;
    for (const auto& p : report.sweep) {
      cz.push_back(p.of(c).damping_ratio);
      cf.push_back(p.of(c).frequency_hz);
      for (double s : p.of(c).participation) share.push_back(s);
    }
    file.write_vector("/eigen/" + name + "/damping_ratio", cz, "-",
                      "damping ratio of the least damped " + name + " mode");
    file.write_vector("/eigen/" + name + "/frequency", cf, "Hz",
                      "frequency of the least damped " + name + " mode");
    file.write_matrix("/eigen/" + name + "/participation", share, report.sweep.size(),
                      static_cast<std::size_t>(vehicle::kDofGroups), "-",
                      "kinetic-energy share of each group (attribute groups), speeds x groups");
    std::string groups;
    for (int g = 0; g < vehicle::kDofGroups; ++g) {
      if (g > 0) groups += ',';
      groups += vehicle::to_string(static_cast<vehicle::DofGroup>(g));
    }
    file.set_attribute("/eigen/" + name, "groups", groups);
  }
  file.set_attribute("/eigen", "critical_speed", report.critical_speed.value_or(std::nan("")));
  file.set_attribute("/eigen", "closed_form_critical_speed",
                     report.closed_form_critical_speed.value_or(std::nan("")));
  file.set_attribute("/eigen", "closed_form_note", report.closed_form_note);
  file.set_attribute("/", "status", std::string("completed"));
}

}  // namespace ferro::scenarios
