// Time simulation of a scene from Python: every sample kept in memory as NumPy arrays, an HDF5
// file when asked for, the GIL released while integrating, Ctrl-C keeping what was computed.
#include <fmt/format.h>

#include "common.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/report.hpp"
#include "ferro/scenarios/run.hpp"

namespace ferro::python {
namespace {

// The samples of a run, one row of every channel per output time, in one growing buffer (the
// arrays handed to Python are views of it).
struct Samples {
  std::size_t channels = 0, count = 0;
  std::vector<double> time, values;  // values[i * channels + c]
  void add(double t, std::span<const double> row) {
    time.push_back(t);
    values.insert(values.end(), row.begin(), row.end());
    ++count;
  }
};

py::dict metadata(const scenarios::Scene& scene) {
  py::dict m;
  m["program"] = "ferrodyn";
  m["version"] = FERRO_VERSION;
  m["scene_file"] = scene.path;
  m["scene_name"] = scene.name;
  m["model_type"] = scene.model.type;
  m["integrator"] = scene.solver.method;
  m["rtol"] = scene.solver.rtol;
  m["atol"] = scene.solver.atol;
  m["fixed_step"] = scene.solver.fixed_step;
  m["speed"] = scene.simulation.speed;
  m["t_end"] = scene.simulation.t_end;
  m["output_interval"] = scene.output.interval;
  if (scene.model.type == "vehicle") {
    const auto& w = scene.model.vehicle.wheel_rail;
    m["vehicle"] = scene.model.vehicle.name;
    m["model_scope"] = scene.model.selection.scope;
    m["contact_geometry"] = w.geometry;
    m["tangential_model"] = w.tangential_model;
    m["normal_model"] = w.normal_model;
    m["acceleration"] = scene.simulation.acceleration;
  }
  m["scene_text"] = scene.text;
  return m;
}

// The result as the Python layer's RunResult takes it (ferrodyn/__init__.py).
py::dict result_dict(const scenarios::Scene& scene, const scenarios::RunSummary& s,
                     Samples&& samples) {
  py::dict r;
  const auto n = static_cast<py::ssize_t>(samples.count);
  const auto channels = static_cast<py::ssize_t>(s.channels.size());
  r["time"] = to_numpy(std::move(samples.time));
  // Samples x channels in memory; handed over as channels x samples (a transposed view).
  r["data"] = to_numpy(std::move(samples.values), {n, channels}).attr("T");
  py::list names, units, descriptions;
  for (const auto& c : s.channels) {
    names.append(c.name);
    units.append(c.unit);
    descriptions.append(c.description);
  }
  r["names"] = names;
  r["units"] = units;
  r["descriptions"] = descriptions;
  r["state_count"] = s.state_count;
  r["status"] = s.status_text;
  r["message"] = s.message;
  r["t_reached"] = s.t_reached;
  r["samples"] = s.samples;
  r["steps"] = s.steps;
  r["rhs_evaluations"] = s.rhs_evaluations;
  r["jacobians"] = s.jacobians;
  r["newton_iterations"] = s.newton_iterations;
  r["step_splits"] = s.step_splits;
  r["wall_seconds"] = s.wall_seconds;
  r["output_file"] = s.output_file.empty() ? py::object(py::none()) : py::object(py::str(s.output_file));
  r["metadata"] = metadata(scene);
  r["summary"] = scenarios::run_report(scene, s);
  return r;
}

// The overrides a run takes (the eigenvalue range is not among them).
scenarios::Parameters run_parameters(scenarios::RunOverrides& o) {
  return scenarios::select_parameters(
      scenarios::parameters(o),
      {"t_end", "speed", "integrator", "fixed_step", "rtol", "atol", "tangential", "normal"});
}

py::object run(const SceneSource& source, const py::object& output, const py::object& progress,
               bool overwrite, const py::kwargs& kwargs) {
  scenarios::Scene scene = source.scene;
  scenarios::RunOverrides overrides;
  set_parameters(run_parameters(overrides), kwargs);
  try {
    scenarios::apply_overrides(scene, overrides, scenarios::Spelling::key);
  } catch (const std::invalid_argument& e) {
    raise_scene_error(e, scene.path);
  }
  Samples samples;
  scenarios::RunOptions opt;
  opt.write_output = !output.is_none();
  if (opt.write_output) opt.output_file = py::str(output).cast<std::string>();
  opt.overwrite = overwrite;
  if (!opt.write_output) opt.csv = std::vector<std::string>{};  // CSV only beside a file
  const std::uint64_t times =
      scenarios::output_sample_count(scene.simulation.t_end, scene.output.interval);
  SignalWatch watch;
  opt.should_stop = [&watch] { return watch.stop(); };
  opt.stop_reason = "interrupted (KeyboardInterrupt)";
  opt.on_sample = [&samples, times](double t, std::span<const double> row) {
    if (samples.count == 0) {  // first sample: the channel count is known now
      const std::size_t rows = std::min<std::uint64_t>(times, 1u << 14);
      samples.channels = row.size();
      samples.time.reserve(rows);
      samples.values.reserve(rows * samples.channels);
    }
    samples.add(t, row);
  };
  if (!progress.is_none()) {
    opt.progress = [&progress](double t) {
      py::gil_scoped_acquire gil;
      progress(t);
    };
  }
  scenarios::RunSummary summary;
  try {
    py::gil_scoped_release release;
    summary = scenarios::run_scene(scene, opt);
  } catch (const std::invalid_argument& e) {
    raise_scene_error(e, scene.path);
  }
  py::dict result = result_dict(scene, summary, std::move(samples));
  watch.raise_if_stopped(result);
  return result;
}

}  // namespace

void bind_run(py::module_& m) {
  scenarios::RunOverrides keys;
  const std::string doc =
      "run(scene, output=None, progress=None, overwrite=False, **overrides) -> dict\n\n"
      "Integrates the scene as `ferrodyn run` does and returns every sample in memory\n"
      "(ferrodyn.run wraps it in a RunResult). output: HDF5 file to write as well (None: no\n"
      "file; written under a temporary name and renamed when the run ends). overwrite: replace\n"
      "an existing output file (else it is refused, as `ferrodyn run` without --overwrite).\n"
      "progress: called with the simulated time [s] at each output time. The GIL is\n"
      "released while integrating. Ctrl-C stops the run and raises KeyboardInterrupt whose\n"
      "`result` attribute holds every sample computed (status 'interrupted'); the file, when\n"
      "asked for, keeps them too. A solver failure is not an exception: status\n"
      "'solver_failure' and the message say why.\n\nOverrides (as `ferrodyn run`'s options):\n" +
      parameter_doc(run_parameters(keys));
  m.def("_run", &run, py::arg("scene"), py::arg("output") = py::none(),
        py::arg("progress") = py::none(), py::arg("overwrite") = false, doc.c_str());
}

}  // namespace ferro::python
