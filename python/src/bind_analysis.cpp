// Analyses from Python: eigenvalues against speed, the critical-speed studies, the sweep and
// the assessment of a run, each returning arrays and dicts (units in the keys' docs).
#include <fmt/format.h>

#include <complex>
#include <filesystem>
#include <optional>

#include <pybind11/stl/filesystem.h>

#include "common.hpp"
#include "ferro/scenarios/analysis/report.hpp"
#include "ferro/scenarios/analysis/studies.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/report.hpp"
#include "ferro/scenarios/run.hpp"

namespace ferro::python {
namespace {

namespace an = scenarios::analysis;

py::array_t<double> arr(std::vector<double> v) { return to_numpy(std::move(v)); }

template <class T, class F>
py::array_t<double> column(const std::vector<T>& items, F f) {
  std::vector<double> v;
  v.reserve(items.size());
  for (const auto& i : items) v.push_back(f(i));
  return arr(std::move(v));
}

py::object opt(const std::optional<double>& v) {
  return v ? py::object(py::float_(*v)) : py::object(py::none());
}

// Runs `work` without the GIL; library input errors become SceneError or ValueError.
template <class F>
auto released(const std::string& file, F work) {
  try {
    py::gil_scoped_release release;
    return work();
  } catch (const scenarios::YamlInputError& e) {
    raise_scene_error(e, file);
  }
}

py::dict eigen_dict(const scenarios::Scene& scene, const scenarios::EigenReport& r) {
  py::dict d;
  d["speed"] = column(r.sweep, [](const auto& p) { return p.speed; });
  d["damping_ratio"] = column(r.sweep, [](const auto& p) { return p.least_damped.damping_ratio; });
  d["frequency"] = column(r.sweep, [](const auto& p) { return p.least_damped.frequency_hz; });
  std::vector<std::complex<double>> lambda;
  for (const auto& p : r.sweep) lambda.push_back(p.least_damped.eigenvalue);
  d["eigenvalue"] = py::array(py::cast(lambda));
  d["critical_speed"] = opt(r.critical_speed);
  d["closed_form_critical_speed"] = opt(r.closed_form_critical_speed);
  d["closed_form_note"] = r.closed_form_note;
  py::list modes;
  for (const auto& mode : r.modes_at_scene_speed) {
    py::dict md;
    md["eigenvalue"] = mode.eigenvalue;
    md["damping_ratio"] = mode.damping_ratio;
    md["frequency"] = mode.frequency_hz;
    modes.append(md);
  }
  d["modes_at_scene_speed"] = modes;
  d["summary"] = scenarios::eigen_sweep_report(scene, r);
  return d;
}

py::dict eigenvalues(const SceneSource& source, double k11, double k22, const py::kwargs& kw,
                     scenarios::RunOverrides range) {
  scenarios::Scene scene = source.scene;
  const std::vector<std::string_view> keys = {"speed_min", "speed_max", "points", "tangential"};
  set_parameters(scenarios::select_parameters(scenarios::parameters(range), keys), kw);
  try {
    if (k11 != 1.0 || k22 != 1.0) scene = an::with_reduction(scene, contact::ReductionFactors::following_k22(k11, k22));
    scenarios::apply_overrides(scene, range, scenarios::Spelling::key);
  } catch (const std::invalid_argument& e) {
    raise_scene_error(e, scene.path);
  }
  const auto r = released(scene.path, [&] { return scenarios::run_eigen(scene); });
  return eigen_dict(scene, r);
}

py::dict branch_dict(const an::KijRow& row, const std::vector<std::string>& names) {
  const auto& b = row.branch;
  py::dict d;
  d["speed"] = column(b.points, [](const auto& p) { return p.speed; });
  py::list outcome;
  std::vector<double> amplitude, period, time;
  std::vector<bool> bisection;
  std::vector<double> holder;
  for (const auto& p : b.points) {
    outcome.append(an::to_string(p.run.outcome));
    holder.push_back(static_cast<double>(p.run.holder));
    for (std::size_t j = 0; j < names.size(); ++j)
      amplitude.push_back(j < p.run.amplitude.size() ? p.run.amplitude[j] : NAN);
    period.push_back(p.run.period);
    time.push_back(p.run.time);
    bisection.push_back(p.bisection);
  }
  d["outcome"] = outcome;
  d["amplitude"] = to_numpy(std::move(amplitude), {static_cast<py::ssize_t>(b.points.size()),
                                                    static_cast<py::ssize_t>(names.size())});
  d["period"] = arr(std::move(period));
  d["time"] = arr(std::move(time));
  d["bisection"] = py::array(py::cast(bisection));
  d["holder"] = arr(std::move(holder));
  d["fold_holder"] = b.holder;
  d["wheelsets"] = names;
  d["k11"] = row.k.k11;
  d["k22"] = row.k.k22;
  d["fold_found"] = b.fold_found;
  d["lowest_sustained"] = opt(b.lowest_sustained);
  d["bracket_low"] = b.bracket_low;
  d["bracket_high"] = b.bracket_high;
  d["amplitude_squared_zero"] = b.amplitude_squared_zero;
  d["supercritical"] = b.supercritical;
  d["hopf_speed"] = opt(row.hopf_speed);
  d["summary"] = an::branch_report(row, names);
  return d;
}

py::dict ramp(const SceneSource& source, const py::kwargs& kw) {
  an::RampRequest request;
  set_parameters(an::parameters(request), kw);
  const auto study = released(source.scene.path, [&] {
    return an::run_ramp(source.scene, request, scenarios::Spelling::key);
  });
  const auto& r = study.result;
  py::dict d;
  d["time"] = arr(r.time);
  d["speed"] = arr(r.speed);
  // Samples x observed states, as the program's /ramp/signal and /ramp/wheelset_envelope.
  const auto by_rows = [&r](const std::vector<std::vector<double>>& columns) {
    std::vector<double> v;
    v.reserve(r.time.size() * columns.size());
    for (std::size_t i = 0; i < r.time.size(); ++i)
      for (const auto& c : columns) v.push_back(i < c.size() ? c[i] : NAN);
    return to_numpy(std::move(v), {static_cast<py::ssize_t>(r.time.size()),
                                   static_cast<py::ssize_t>(columns.size())});
  };
  d["signal"] = by_rows(r.signals);
  d["wheelset_envelope"] = by_rows(r.envelopes);
  d["envelope"] = arr(r.envelope);
  d["observed"] = study.observed;
  d["holder"] = r.holder < study.observed.size() ? study.observed[r.holder] : std::string();
  d["decay_speed"] = opt(r.decay_speed);
  d["decay_time"] = r.decay_time;
  d["peak_speed"] = r.peak_speed;
  d["envelope_growth"] = r.envelope_growth;
  d["completed"] = r.completed;
  d["message"] = r.message;
  d["summary"] = an::ramp_report(study, request);
  return d;
}

py::dict bifurcation(const SceneSource& source, const py::kwargs& kw) {
  an::BranchRequest request;
  set_parameters(an::parameters(request), kw);
  std::vector<std::string> names;
  const auto k = request.settle.reduction();
  const auto row = released(source.scene.path, [&] {
    return an::run_bifurcation(source.scene, request, k, &names, {}, scenarios::Spelling::key);
  });
  return branch_dict(row, names);
}

py::dict kij_study(const SceneSource& source, const py::kwargs& kw) {
  an::KijStudyRequest request;
  set_parameters(an::parameters(request), kw);
  SignalWatch watch;
  const auto study = released(source.scene.path, [&] {
    return an::run_kij_study(source.scene, request, [&watch] { return watch.stop(); }, {},
                             scenarios::Spelling::key);
  });
  watch.raise_if_stopped(py::none());
  py::dict d;
  py::list branches;
  for (const auto& row : study.rows) branches.append(branch_dict(row, study.names));
  d["branches"] = branches;
  d["k11"] = column(study.rows, [](const auto& r) { return r.k.k11; });
  d["k22"] = column(study.rows, [](const auto& r) { return r.k.k22; });
  d["critical_speed"] = column(study.rows, [](const auto& r) {
    return r.branch.fold_found ? *r.branch.lowest_sustained : NAN;
  });
  d["lowest_sustained"] = column(study.rows, [](const auto& r) {
    return r.branch.lowest_sustained.value_or(NAN);
  });
  d["hopf_speed"] = column(study.rows, [](const auto& r) { return r.hopf_speed.value_or(NAN); });
  d["summary"] = an::kij_study_report(source.scene, request, study);
  return d;
}

py::dict sweep(const SceneSource& source, const py::object& output, bool overwrite,
               const py::kwargs& kw) {
  an::SweepRequest request;
  set_parameters(an::parameters(request), kw);
  // As `ferrodyn sweep`: the output claimed before any point is computed (never an input of
  // the scene, an existing file only with overwrite), written under a temporary name and given
  // its name once the sweep is complete; finished points are journaled beside the final name.
  std::optional<scenarios::OutputSet> outputs;
  scenarios::OutputFile* file = nullptr;
  if (!output.is_none()) {
    const std::string path = py::str(output);
    outputs.emplace(scenarios::OutputRules{overwrite, scenarios::scene_inputs(source.scene)});
    file = &outputs->claim(path, "output");
    request.output = file->write_path();
    request.journal = path + ".points";
  }
  SignalWatch watch;
  an::SweepCallbacks callbacks;
  callbacks.should_stop = [&watch] { return watch.stop(); };
  auto executor = an::make_sweep_executor(false);
  const auto r = released(source.scene.path, [&] {
    return an::run_sweep(source.scene, request, *executor, callbacks, scenarios::Spelling::key);
  });
  watch.raise_if_stopped(py::none());
  if (file != nullptr && r.complete) {
    file->commit();
    request.output = file->path();
  }
  py::dict d;
  const auto& p = r.results;
  d["speed"] = column(p, [](const auto& x) { return x.point.speed; });
  d["k11"] = column(p, [](const auto& x) { return x.point.k.k11; });
  d["k22"] = column(p, [](const auto& x) { return x.point.k.k22; });
  d["holder"] = column(p, [](const auto& x) { return static_cast<double>(x.holder); });
  py::list outcome;
  std::vector<double> amplitude;
  for (const auto& x : p) {
    outcome.append(an::to_string(x.outcome));
    for (std::size_t j = 0; j < r.wheelset_names.size(); ++j)
      amplitude.push_back(j < x.amplitude.size() ? x.amplitude[j] : NAN);
  }
  d["outcome"] = outcome;
  d["amplitude"] = to_numpy(std::move(amplitude), {static_cast<py::ssize_t>(p.size()),
                                                    static_cast<py::ssize_t>(r.wheelset_names.size())});
  d["period"] = column(p, [](const auto& x) { return x.period; });
  d["time"] = column(p, [](const auto& x) { return x.time; });
  d["cpu_time"] = column(p, [](const auto& x) { return x.cpu_seconds; });
  d["wheelsets"] = r.wheelset_names;
  d["complete"] = r.complete;
  d["wall_seconds"] = r.wall_seconds;
  d["summary"] = r.complete ? an::sweep_report(source.scene, request, r, 1) : std::string();
  return d;
}

py::dict assess(const std::filesystem::path& run_path, const py::kwargs& kw) {
  const std::string run_file = run_path.string();
  an::AssessmentRequest request;
  set_parameters(an::parameters(request), kw);
  const an::AssessmentOptions o = an::assessment_options(request, scenarios::Spelling::key);
  const auto r = released(run_file, [&] { return an::assess_run(run_file, o); });
  py::dict d;
  d["vehicle"] = r.vehicle;
  d["category"] = r.category;
  d["alpha"] = r.alpha;
  d["mu"] = r.mu;
  d["sample_rate"] = r.sample_rate;
  d["f0"] = r.f0;
  d["f0_from_spectrum"] = r.f0_from_spectrum;
  d["twist_test"] = r.twist_test;
  d["accelerations_derived"] = r.accelerations_derived;
  d["forces_filtered_in_run"] = r.forces_filtered_in_run;
  py::dict sections;
  sections["name"] = [&] {
    std::vector<std::string> v;
    for (const auto& x : r.sections) v.push_back(x.name);
    return v;
  }();
  sections["start"] = column(r.sections, [](const auto& x) { return x.start; });
  sections["end"] = column(r.sections, [](const auto& x) { return x.end; });
  sections["radius"] = column(r.sections, [](const auto& x) { return x.radius; });
  d["sections"] = sections;
  // The rows as columns, in the order of the HDF5 file's table.
  py::dict rows;
  const auto text = [&](std::string an::AssessmentRow::*field) {
    std::vector<std::string> v;
    for (const auto& x : r.rows) v.push_back(x.*field);
    return v;
  };
  rows["group"] = text(&an::AssessmentRow::group);
  rows["quantity"] = text(&an::AssessmentRow::quantity);
  rows["item"] = text(&an::AssessmentRow::item);
  rows["section"] = text(&an::AssessmentRow::section);
  rows["unit"] = text(&an::AssessmentRow::unit);
  rows["value"] = column(r.rows, [](const auto& x) { return x.value; });
  rows["limit"] = column(r.rows, [](const auto& x) { return x.limit; });
  rows["verdict"] = [&] {
    std::vector<std::string> v;
    for (const auto& x : r.rows) v.emplace_back(an::to_string(x.verdict));
    return v;
  }();
  rows["max_abs"] = column(r.rows, [](const auto& x) { return x.max_abs; });
  rows["position"] = column(r.rows, [](const auto& x) { return x.position; });
  rows["p_low"] = column(r.rows, [](const auto& x) { return x.stats.p_low; });
  rows["p_median"] = column(r.rows, [](const auto& x) { return x.stats.p_median; });
  rows["p_high"] = column(r.rows, [](const auto& x) { return x.stats.p_high; });
  rows["rms"] = column(r.rows, [](const auto& x) { return x.stats.rms; });
  rows["samples"] = column(r.rows, [](const auto& x) { return static_cast<double>(x.stats.samples); });
  d["rows"] = rows;
  py::list signals;
  for (const auto& x : r.signals) {
    py::dict sd;
    sd["quantity"] = x.quantity;
    sd["item"] = x.item;
    sd["unit"] = x.unit;
    sd["description"] = x.description;
    sd["position"] = arr(x.position);
    sd["value"] = arr(x.value);
    sd["limit"] = x.limit;
    signals.append(sd);
  }
  d["signals"] = signals;
  d["notes"] = r.notes;
  d["pass"] = r.pass;
  d["summary"] = an::assessment_report(run_file, r);
  return d;
}

}  // namespace

void bind_analysis(py::module_& m) {
  scenarios::RunOverrides range;
  const std::string range_doc = parameter_doc(scenarios::select_parameters(
      scenarios::parameters(range), {"speed_min", "speed_max", "points", "tangential"}));
  static const std::string eig_doc =
      "eigenvalues(scene, **range) -> dict\n\nLinear eigenvalue analysis over a speed range "
      "(`ferrodyn eig`): each speed about its own equilibrium. Keys: speed [m/s],\n"
      "damping_ratio [-] and frequency [Hz] of the least damped mode, eigenvalue [1/s]\n"
      "(complex), critical_speed [m/s] (None: no crossing), closed_form_critical_speed [m/s],\n"
      "modes_at_scene_speed, summary. Range (default: the scene's analysis.eigen):\n" +
      range_doc;
  m.def(
      "eigenvalues",
      [](const SceneSource& s, const py::kwargs& kw) {
        return eigenvalues(s, 1.0, 1.0, kw, scenarios::RunOverrides{});
      },
      py::arg("scene"), eig_doc.c_str());
  static const std::string ceig_doc =
      "critical_speed_eigen(scene, k11=1.0, k22=1.0, **range) -> dict\n\nThe Hopf speed as "
      "`ferrodyn critical-speed eigen`: eigenvalues() over 1..150 m/s at 150 speeds unless "
      "given, with Kalker reduction factors k11, k22 [-].\n";
  m.def(
      "critical_speed_eigen",
      [](const SceneSource& s, double k11, double k22, const py::kwargs& kw) {
        scenarios::RunOverrides r;
        r.speed_min = 1.0;
        r.speed_max = 150.0;
        r.points = 150;
        return eigenvalues(s, k11, k22, kw, r);
      },
      py::arg("scene"), py::arg("k11") = 1.0, py::arg("k22") = 1.0, ceig_doc.c_str());

  an::RampRequest ramp_request;
  static const std::string ramp_doc =
      "critical_speed_ramp(scene, **request) -> dict\n\nDecelerating run after a lateral "
      "disturbance (`ferrodyn critical-speed ramp`). Keys: time [s], speed [m/s], signal and\n"
      "wheelset_envelope [m] (samples x observed states), envelope [m] (the vehicle's: the\n"
      "largest), observed (each wheelset's lateral state), holder (the last to die out),\n"
      "decay_speed [m/s] (None: none), peak_speed [m/s], envelope_growth, completed, message,\n"
      "summary. Request:\n" +
      parameter_doc(an::parameters(ramp_request));
  m.def("critical_speed_ramp", &ramp, py::arg("scene"), ramp_doc.c_str());

  an::BranchRequest branch_request;
  static const std::string bif_doc =
      "critical_speed_bifurcation(scene, **request) -> dict\n\nLimit-cycle amplitudes "
      "followed down the periodic branch to its fold (`ferrodyn critical-speed bifurcation`).\n"
      "Keys: speed [m/s], outcome, amplitude [m] (points x wheelsets), period [s], time [s],\n"
      "bisection, holder (index of the wheelset holding each point's outcome), fold_holder,\n"
      "wheelsets, fold_found, lowest_sustained [m/s] (the nonlinear critical speed),\n"
      "bracket_low, bracket_high [m/s], hopf_speed [m/s], summary. Request:\n" +
      parameter_doc(an::parameters(branch_request));
  m.def("critical_speed_bifurcation", &bifurcation, py::arg("scene"), bif_doc.c_str());

  an::KijStudyRequest kij_request;
  static const std::string kij_doc =
      "kij_study(scene, **request) -> dict\n\nThe nonlinear critical speed against Kalker's "
      "reduction factors (`ferrodyn kij-study`), one branch per factor over `jobs` threads.\n"
      "Keys: k11, k22, critical_speed [m/s] (the fold; NaN: none found), lowest_sustained\n"
      "[m/s] (lowest speed with a sustained oscillation), hopf_speed [m/s], branches\n"
      "(one dict each, as critical_speed_bifurcation), summary. Request:\n" +
      parameter_doc(an::parameters(kij_request));
  m.def("kij_study", &kij_study, py::arg("scene"), kij_doc.c_str());

  an::SweepRequest sweep_request;
  static const std::string sweep_doc =
      "sweep(scene, output=None, overwrite=False, **request) -> dict\n\nIndependent "
      "constant-speed runs over speeds x reduction factors on `jobs` threads (`ferrodyn sweep`;\n"
      "the same numbers as the program's serial, threaded and MPI sweeps). output: HDF5 file\n"
      "(written under a temporary name, renamed when the sweep completes; its resumable journal\n"
      "<output>.points/ until then). overwrite: replace an existing output file (else it is\n"
      "refused, as `ferrodyn sweep` without --overwrite). Keys: speed [m/s], k11, k22, holder (index of\n"
      "the wheelset holding the outcome), outcome,\n"
      "amplitude [m] (points x wheelsets), period [s], time [s], cpu_time [s], wheelsets,\n"
      "complete, wall_seconds, summary. Request:\n" +
      parameter_doc(an::parameters(sweep_request));
  m.def("sweep", &sweep, py::arg("scene"), py::arg("output") = py::none(),
        py::arg("overwrite") = false, sweep_doc.c_str());

  an::AssessmentRequest assess_request;
  static const std::string assess_doc =
      "assess(run_file, **request) -> dict\n\nAssessment of a run's HDF5 file as EN 14363 / "
      "UIC 518 / EN 12299 define it (`ferrodyn assess`, the same numbers):\n"
      "running safety, track loading, stability, ride (and the twist test). Keys: vehicle,\n"
      "category, alpha [-], mu [-], sample_rate [Hz], f0 [Hz] (NaN: stability not assessed),\n"
      "f0_from_spectrum, twist_test, accelerations_derived, forces_filtered_in_run, sections\n"
      "(name, start [m], end [m], radius [m]), rows (columns of the result table: group,\n"
      "quantity, item, section, unit, value, limit, verdict, max_abs, position [m], p_low,\n"
      "p_median, p_high, rms, samples; values in the row's SI unit), signals (the processed\n"
      "signals along the track: quantity, item, unit, description, position [m], value, limit),\n"
      "notes, pass, summary. Request:\n" +
      parameter_doc(an::parameters(assess_request));
  m.def("assess", &assess, py::arg("run_file"), assess_doc.c_str());
}

}  // namespace ferro::python
