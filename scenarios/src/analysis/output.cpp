#include "ferro/scenarios/analysis/output.hpp"

#include "ferro/scenarios/h5_output.hpp"
#include "ferro/scenarios/run.hpp"

namespace ferro::scenarios::analysis {
namespace {

H5File create_with_scene(const Scene& scene, const std::string& kind, const std::string& path) {
  H5File file = H5File::create(path);
  file.set_attribute("/", "program", std::string("ferrodyn"));
  file.set_attribute("/", "created_utc", utc_timestamp());
  file.set_attribute("/", "kind", kind);
  file.set_attribute("/", "scene_file", scene.path);
  file.set_attribute("/", "scene_name", scene.name);
  file.set_attribute("/", "integrator", scene.solver.method);
  file.write_text("/scene/text", scene.text);
  return file;
}

}  // namespace

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ",") + n;
  return s;
}

// Samples x states, row-major, from one vector per state.
std::vector<double> by_rows(const std::vector<std::vector<double>>& columns, std::size_t rows) {
  std::vector<double> out;
  out.reserve(rows * columns.size());
  for (std::size_t i = 0; i < rows; ++i)
    for (const auto& c : columns) out.push_back(i < c.size() ? c[i] : NAN);
  return out;
}

}  // namespace

void write_ramp(const Scene& scene, const RampResult& r, const RampOptions& o,
                const std::vector<std::string>& names, const std::string& path) {
  H5File f = create_with_scene(scene, "ramp", path);
  const std::size_t n = r.time.size();
  f.write_vector("/ramp/time", r.time, "s", "time");
  f.write_vector("/ramp/speed", r.speed, "m/s", "forward speed");
  f.write_matrix("/ramp/signal", by_rows(r.signals, n), n, r.signals.size(), "m",
                 "lateral displacement, samples x wheelsets (attribute wheelsets)");
  f.write_matrix("/ramp/wheelset_envelope", by_rows(r.envelopes, n), n, r.envelopes.size(), "m",
                 "half peak-to-peak over the trailing envelope window, samples x wheelsets");
  f.write_vector("/ramp/envelope", r.envelope, "m",
                 "the vehicle's envelope: the largest of the wheelsets' at each sample");
  f.set_attribute("/ramp", "wheelsets", joined(names));
  f.set_attribute("/ramp", "holder", names.empty() ? std::string() : names[r.holder]);
  f.set_attribute("/ramp", "decay_speed", r.decay_speed.value_or(NAN));
  f.set_attribute("/ramp", "envelope_peak_speed", r.peak_speed);
  f.set_attribute("/ramp", "envelope_peak_note",
                  std::string("speed at the envelope's maximum: the Hopf speed for a linear "
                              "model and a slow ramp only; on a cycle limited by the flange, "
                              "where its plateau is highest"));
  f.set_attribute("/ramp", "envelope_growth", r.envelope_growth);
  f.set_attribute("/ramp", "threshold", o.threshold);
  f.set_attribute("/ramp", "deceleration", o.deceleration);
  f.set_attribute("/ramp", "speed_initial", o.speed_initial);
  f.set_attribute("/ramp", "k11", scene.contact.creep.reduction.k11);
  f.set_attribute("/ramp", "k22", scene.contact.creep.reduction.k22);
  f.set_attribute("/", "status", std::string(r.completed ? "completed" : "solver_failure"));
  f.set_attribute("/", "status_message", r.message);
}

void write_branch(const Scene& scene, const BranchResult& b,
                  const std::vector<std::string>& wheelset_names, std::optional<double> hopf_speed,
                  const std::string& path) {
  H5File f = create_with_scene(scene, "bifurcation", path);
  std::vector<double> v, outcome, holder, bis, period, amp, sigma, sigma_error, beta;
  const std::size_t m = wheelset_names.size();
  for (const auto& p : b.points) {
    sigma.push_back(p.run.fit.sigma);
    sigma_error.push_back(p.run.fit.sigma_error);
    beta.push_back(p.run.fit.beta);
    v.push_back(p.speed);
    outcome.push_back(static_cast<double>(p.run.outcome));
    holder.push_back(static_cast<double>(p.run.holder));
    bis.push_back(p.bisection ? 1.0 : 0.0);
    period.push_back(p.run.period);
    for (std::size_t j = 0; j < m; ++j)
      amp.push_back(j < p.run.amplitude.size() ? p.run.amplitude[j] : NAN);
  }
  f.write_vector("/branch/speed", v, "m/s", "speeds in the order computed");
  f.write_vector(
      "/branch/outcome", outcome, "-",
      "0 decayed, 1 steady, 2 diverged, 3 growing, 4 decaying, 5 approaching (cycle from the "
      "amplitude equation)");
  f.write_vector("/branch/holder", holder, "-",
                 "index (0-based, attribute wheelsets) of the wheelset holding the outcome");
  f.write_vector("/branch/bisection", bis, "-", "1 for points of the fold bisection");
  f.write_vector("/branch/period", period, "s", "limit-cycle period");
  f.write_matrix("/branch/amplitude", amp, b.points.size(), m, "m",
                 "steady lateral amplitude, points x wheelsets");
  f.write_vector("/branch/sigma", sigma, "1/s",
                 "growth rate of the amplitude equation d ln A/dt = sigma - beta A^2 fitted to "
                 "the envelope of the holding wheelset of a run ended by the time limit (NaN otherwise)");
  f.write_vector("/branch/sigma_error", sigma_error, "1/s", "standard error of sigma");
  f.write_vector("/branch/beta", beta, "1/(s m^2)", "Landau coefficient of the same fit");
  f.set_attribute("/branch", "wheelsets", joined(wheelset_names));
  f.set_attribute("/branch", "lowest_sustained", b.lowest_sustained.value_or(NAN));
  f.set_attribute("/branch", "holder",
                  b.lowest_sustained && b.holder < wheelset_names.size()
                      ? wheelset_names[b.holder]
                      : std::string());
  f.set_attribute("/branch", "bracket_low", b.bracket_low);
  f.set_attribute("/branch", "bracket_high", b.bracket_high);
  f.set_attribute("/branch", "fold_found", static_cast<long>(b.fold_found));
  f.set_attribute("/branch", "amplitude_squared_zero", b.amplitude_squared_zero);
  f.set_attribute("/branch", "supercritical", static_cast<long>(b.supercritical));
  f.set_attribute("/branch", "hopf_speed", hopf_speed.value_or(NAN));
  f.set_attribute("/branch", "k11", scene.contact.creep.reduction.k11);
  f.set_attribute("/branch", "k22", scene.contact.creep.reduction.k22);
  f.set_attribute("/", "status", std::string("completed"));
}

void write_kij_study(const Scene& scene, const std::vector<KijRow>& rows, const std::string& path) {
  H5File f = create_with_scene(scene, "kij_study", path);
  std::vector<double> k11, k22, vc, lo, hi, hopf;
  for (const auto& r : rows) {
    k11.push_back(r.k.k11);
    k22.push_back(r.k.k22);
    vc.push_back(r.branch.lowest_sustained.value_or(NAN));
    lo.push_back(r.branch.bracket_low);
    hi.push_back(r.branch.bracket_high);
    hopf.push_back(r.hopf_speed.value_or(NAN));
  }
  f.write_vector("/kij/k11", k11, "-", "reduction factor on C11");
  f.write_vector("/kij/k22", k22, "-", "reduction factor on C22");
  f.write_vector("/kij/critical_speed", vc, "m/s", "lowest speed with a sustained oscillation");
  f.write_vector("/kij/bracket_low", lo, "m/s", "fold bracket, lower end");
  f.write_vector("/kij/bracket_high", hi, "m/s", "fold bracket, upper end");
  f.write_vector("/kij/hopf_speed", hopf, "m/s", "linear (eigenvalue) critical speed");
  std::vector<double> tk, tv;
  for (const auto& t : thesis_table_4_1()) {
    tk.push_back(t.k);
    tv.push_back(t.critical_speed_kmh / 3.6);
  }
  f.write_vector("/kij/thesis_k", tk, "-", "Toumi 2016 Table 4.1");
  f.write_vector("/kij/thesis_critical_speed", tv, "m/s", "Toumi 2016 Table 4.1");
  f.set_attribute("/", "status", std::string("completed"));
}

const std::vector<ThesisTableRow>& thesis_table_4_1() {
  static const std::vector<ThesisTableRow> rows = {
      {1.0, 280.0}, {0.9, 266.0}, {0.8, 248.0}, {0.7, 230.0}, {0.6, 205.0}, {0.5, 173.0}};
  return rows;
}

}  // namespace ferro::scenarios::analysis
