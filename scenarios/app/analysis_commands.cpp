// Verbs of the analyses: assessment of a run (EN 14363 / UIC 518 / EN 12299), critical speed (ramp, bifurcation,
// eigen), reduction-factor studies and parallel sweeps (threads and, when built with it, MPI).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <mutex>

#include "cli.hpp"
#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/assessment.hpp"
#include "ferro/scenarios/analysis/output.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/output_file.hpp"
#include "ferro/scenarios/plotting.hpp"
#include "ferro/scenarios/run.hpp"
#include "terminal.hpp"

#ifdef FERRO_WITH_MPI
#include <mpi.h>
#endif

namespace ferro::cli {
namespace {

namespace fs = std::filesystem;
namespace an = scenarios::analysis;
namespace fc = ferro::contact;
using scenarios::Scene;

std::string sibling(const std::string& file, const std::string& suffix) {
  const fs::path p(file);
  return (p.parent_path() / (p.stem().string() + suffix)).string();
}

// Draws the plots of an analysis' output; returns the verb's exit code (`code` unless a stop
// request ended the plotting).
int plot(const std::string& h5, bool no_plots, int code) {
  if (no_plots) return code;
  std::fflush(stdout);  // the report before the script's list of files
  const std::string dir = sibling(h5, "_plots");
  const int rc = scenarios::run_python_tool("ferroplot.py",
                                            {"auto", h5, "--out", dir, "--format", "png,svg"},
                                            [] { return InterruptGuard::stop_now(); });
  if (rc == scenarios::kProgramStopped) return 128 + InterruptGuard::signal_received();
  if (rc == 0) {
    fmt::print("  plots     {}/\n", dir);
  } else if (rc == kPlotsNeedPython) {
    fmt::print(stderr,
               "ferrodyn: warning: no plots: python3 with matplotlib and h5py needed; the "
               "results in {} are complete\n",
               h5);
  } else {
    fmt::print(stderr,
               "ferrodyn: warning: plotting failed (exit status {}, see above); the results in {} "
               "are complete\n",
               rc, h5);
  }
  return code;
}

void positive(double v, const char* option) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(fmt::format("{}: must be > 0, got {}", option, v));
}

// The output of an analysis, claimed before it computes (refused paths are refused at once):
// `given` from -o, else `fallback`; the scene's (or run file's) inputs are never written.
struct AnalysisOutput {
  scenarios::OutputSet set;
  scenarios::OutputFile* file = nullptr;
  AnalysisOutput(const std::string& given, const std::string& fallback, bool overwrite,
                 std::vector<std::string> inputs, bool no_plots)
      : set({overwrite, std::move(inputs)}) {
    file = &set.claim(given.empty() ? fallback : given, given.empty() ? "output" : "-o");
    if (!no_plots) check_plot_folder(sibling(file->path(), "_plots"), "plots");
  }
  [[nodiscard]] const std::string& path() const { return file->path(); }
  [[nodiscard]] const std::string& write_path() const { return file->write_path(); }
};

// ---------------------------------------------------------------- assess
struct AssessArgs {
  std::string file, output, category;
  double mu = NAN, flange_angle_deg = NAN, section_length = NAN, f0 = NAN;  // NaN: not given
  double floor_offset = 1.0, y_over_q_limit = 0.8;
  bool twist_test = false, no_twist_test = false, all_rows = false, no_plots = false;
  bool overwrite = false;
};

std::string value_text(double v, const std::string& unit) {
  if (std::isnan(v)) return "-";
  if (unit == "N") return fmt::format("{:.2f} kN", v / 1e3);
  if (unit == "m/s^2") return fmt::format("{:.3f}", v);
  return fmt::format("{:.3f}", v);
}

std::string verdict_text(const an::AssessmentRow& r) {
  if (r.verdict != an::Verdict::info || std::isnan(r.limit)) return an::to_string(r.verdict);
  return r.value > r.limit ? "info: above" : "info: below";
}

int do_assess(const AssessArgs& a) {
  if (!fs::exists(a.file))
    throw std::invalid_argument(fmt::format("assess: no such file '{}'", a.file));
  an::AssessmentOptions o;
  if (!std::isnan(a.mu)) {
    if (!(a.mu >= 0.0 && a.mu < 2.0)) throw std::invalid_argument("--mu: allowed [0, 2)");
    o.mu = a.mu;
  }
  if (!std::isnan(a.flange_angle_deg)) {
    if (!(a.flange_angle_deg > 0.0 && a.flange_angle_deg < 90.0))
      throw std::invalid_argument("--flange-angle-deg: allowed (0, 90)");
    o.flange_angle = a.flange_angle_deg * M_PI / 180.0;
  }
  if (!std::isnan(a.section_length)) {
    positive(a.section_length, "--section-length");
    o.section_length = a.section_length;
  }
  if (!std::isnan(a.f0)) positive(a.f0, "--f0");
  o.f0 = a.f0;
  if (!(a.floor_offset >= 0.0)) throw std::invalid_argument("--floor-offset: must be >= 0 m");
  o.floor_offset = a.floor_offset;
  positive(a.y_over_q_limit, "--y-over-q-limit");
  o.y_over_q_limit = a.y_over_q_limit;
  o.category = a.category;
  if (a.twist_test && a.no_twist_test)
    throw std::invalid_argument("--twist-test and --no-twist-test: give one of them");
  if (a.twist_test) o.twist_test = true;
  if (a.no_twist_test) o.twist_test = false;
  AnalysisOutput out(a.output, sibling(a.file, "_assessment.h5"), a.overwrite, {a.file},
                     a.no_plots);
  const auto r = an::assess_run(a.file, o);
  fmt::print("ferrodyn assess: {} ({}, category {}, alpha {:g}; output every {:.3g} ms)\n",
             a.file, r.vehicle, r.category, r.alpha, 1e3 / r.sample_rate);
  fmt::print("  sections: ");
  for (std::size_t i = 0; i < r.sections.size(); ++i)
    fmt::print("{}{} [{:.1f}, {:.1f}) m", i ? "; " : "", r.sections[i].name,
               r.sections[i].start, r.sections[i].end);
  if (std::isnan(r.f0)) {
    fmt::print("\n  stability not assessed (see the notes)");
  } else {
    fmt::print("\n  f0 = {:.2f} Hz ({})", r.f0,
               r.f0_from_spectrum ? "peak of the sum-Y spectrum" : "given");
  }
  fmt::print(", Nadal mu = {:g}{}\n", r.mu, r.twist_test ? ", twist test" : "");
  // One line per quantity and item: its worst section (largest value / limit, else value), or
  // every row with --all.
  std::vector<const an::AssessmentRow*> shown;
  for (const auto& row : r.rows) {
    if (a.all_rows) {
      shown.push_back(&row);
      continue;
    }
    const auto score = [](const an::AssessmentRow& x) {
      return std::isnan(x.limit) || x.limit <= 0.0 ? x.value : x.value / x.limit;
    };
    auto it = std::find_if(shown.begin(), shown.end(), [&](const an::AssessmentRow* s) {
      return s->quantity == row.quantity && s->item == row.item;
    });
    if (it == shown.end()) {
      shown.push_back(&row);
    } else if (score(row) > score(**it)) {
      *it = &row;
    }
  }
  const std::vector<std::string> groups = {"running safety", "track loading", "twist test",
                                           "stability", "ride"};
  const auto rank = [&](const an::AssessmentRow* x) {
    return std::find(groups.begin(), groups.end(), x->group) - groups.begin();
  };
  std::stable_sort(shown.begin(), shown.end(),
                   [&](const auto* lhs, const auto* rhs) { return rank(lhs) < rank(rhs); });
  std::string group;
  for (const auto* row : shown) {
    if (row->group != group) {
      group = row->group;
      fmt::print("  {}\n  {:<44} {:<34} {:>12} {:>12} {:>10}  {:<22} {}\n", group, "quantity",
                 "item", "value", "limit", "at [m]", "section", "verdict");
    }
    fmt::print("  {:<44} {:<34} {:>12} {:>12} {:>10}  {:<22} {}\n", row->quantity, row->item,
               value_text(row->value, row->unit), value_text(row->limit, row->unit),
               std::isnan(row->position) ? std::string("-") : fmt::format("{:.1f}", row->position),
               row->section, verdict_text(*row));
  }
  for (const auto& n : r.notes) fmt::print("  note: {}\n", n);
  if (r.accelerations_derived)
    fmt::print("  note: floor and bogie-frame accelerations derived from the bodies' rigid "
               "motion (the run has no acceleration sensors)\n");
  fmt::print("  verdict   {}\n", r.pass ? "pass" : "FAIL");
  an::write_assessment(r, a.file, out.write_path());
  out.file->commit();
  fmt::print("  output    {}\n", out.path());
  // The verdict is a result, not a failure of the assessment.
  return plot(out.path(), a.no_plots, kExitOk);
}

// ---------------------------------------------------------------- settle options
struct SettleArgs {
  double segment = 10.0, t_max = 60.0, interval = 2e-3, zero = 1e-5, max = 0.05, rel_tol = 2e-3;
  int periods = 5;
  double disturbance = 0.01;
  double k11 = 1.0, k22 = 1.0;
};

void add_settle_options(CLI::App* c, SettleArgs& s) {
  c->add_option("--disturbance", s.disturbance,
                "Lateral offset added to the leading wheelset at the start [m]")->capture_default_str();
  c->add_option("--segment", s.segment, "Simulated time per convergence check [s]")->capture_default_str();
  c->add_option("--t-max", s.t_max, "Simulated time limit per speed [s]")->capture_default_str();
  c->add_option("--output-interval", s.interval, "Sampling of the lateral states [s]")->capture_default_str();
  c->add_option("--zero-amplitude", s.zero, "Below: oscillation decayed [m]")->capture_default_str();
  c->add_option("--max-amplitude", s.max, "Above: diverged [m]")->capture_default_str();
  c->add_option("--periods", s.periods, "Periods the steady amplitude is measured over")->capture_default_str();
  c->add_option("--rel-tol", s.rel_tol, "Relative amplitude change that counts as settled")->capture_default_str();
  c->add_option("--k11", s.k11, "Reduction factor on C11")->capture_default_str();
  c->add_option("--k22", s.k22, "Reduction factor on C22")->capture_default_str();
}

an::SettleOptions settle_options(const Scene& scene, const SettleArgs& s) {
  positive(s.segment, "--segment");
  positive(s.t_max, "--t-max");
  positive(s.interval, "--output-interval");
  positive(s.zero, "--zero-amplitude");
  positive(s.max, "--max-amplitude");
  positive(s.rel_tol, "--rel-tol");
  if (s.periods < 1) throw std::invalid_argument("--periods: must be >= 1");
  if (s.t_max < s.segment) throw std::invalid_argument("--t-max: must be >= --segment");
  if (s.max <= s.zero) throw std::invalid_argument("--max-amplitude: must be > --zero-amplitude");
  an::SettleOptions o;
  o.solver = scene.solver;
  o.segment = s.segment;
  o.max_time = s.t_max;
  o.output_interval = s.interval;
  o.zero_amplitude = s.zero;
  o.max_amplitude = s.max;
  o.amplitude.periods = s.periods;
  o.amplitude.rel_tol = s.rel_tol;
  return o;
}

// ---------------------------------------------------------------- ramp
struct RampArgs {
  std::string scene, output;
  double speed_initial = 110.0, deceleration = 1.0, speed_final = NAN, hold = 0.1,
         threshold = 1e-4, max_amplitude = 0.05, window = 2.0, interval = 2e-3, disturbance = 0.01, k11 = 1.0, k22 = 1.0;
  bool no_plots = false, overwrite = false;
};

int do_ramp(const RampArgs& a) {
  const Scene scene = an::with_reduction(scenarios::load_scene(a.scene),
                                         fc::ReductionFactors::following_k22(a.k11, a.k22));
  an::RampOptions o;
  o.speed_initial = a.speed_initial;
  o.deceleration = a.deceleration;
  o.speed_final = std::isnan(a.speed_final) ? 0.1 * a.speed_initial : a.speed_final;
  positive(a.speed_initial, "--speed-initial");
  positive(a.deceleration, "--deceleration");
  positive(a.hold, "--hold");
  positive(a.threshold, "--threshold");
  positive(a.window, "--envelope-window");
  positive(a.interval, "--output-interval");
  if (!(o.speed_final >= 0.0 && o.speed_final < o.speed_initial))
    throw std::invalid_argument("--speed-final: allowed [0, --speed-initial)");
  o.hold = a.hold;
  o.threshold = a.threshold;
  o.max_amplitude = a.max_amplitude;
  o.envelope_window = a.window;
  o.output_interval = a.interval;
  o.solver = scene.solver;
  AnalysisOutput out(a.output, sibling(scene.output.file, "_ramp.h5"), a.overwrite,
                     scenarios::scene_inputs(scene), a.no_plots);
  const auto family = an::speed_family(scene);
  const auto probe = family(o.speed_initial);
  const auto lateral = an::lateral_states(*probe);
  o.observed = lateral.index;
  const auto x0 = an::disturbed_state(scene, *probe, a.disturbance);
  const auto r = an::ramp_down(family, x0, o);
  fmt::print("ferrodyn critical-speed ramp: {} ({}), K11 = {}, K22 = {}\n", scene.name, scene.path,
             a.k11, a.k22);
  fmt::print("  ramp      {:.3f} -> {:.3f} m/s at -{} m/s^2, pieces of {} s, {} + {} m at start\n",
             o.speed_initial, o.speed_final, o.deceleration, o.hold, lateral.name.front(),
             a.disturbance);
  if (!r.completed) fmt::print("  stopped   {}\n", r.message);
  if (r.decay_speed) {
    fmt::print("  decay     every wheelset's envelope below {} m for good at t = {:.3f} s: V = "
               "{:.3f} m/s = {:.2f} km/h (the last to die out: {})\n",
               o.threshold, r.decay_time, *r.decay_speed, *r.decay_speed * 3.6,
               lateral.name[r.holder]);
  } else {
    fmt::print("  decay     none: the vehicle's envelope {} below {} m over the whole ramp{}\n",
               r.envelope.empty() || r.envelope.back() >= o.threshold ? "never stays" : "stays",
               o.threshold,
               r.completed && !r.envelope.empty() && r.envelope.back() >= o.threshold
                   ? fmt::format(" (largest at the end: {})", lateral.name[r.holder])
                   : std::string());
  }
  an::write_ramp(scene, r, o, lateral.name, out.write_path());
  out.file->commit();
  fmt::print("  output    {}\n", out.path());
  if (!r.completed) {
    std::fflush(stdout);
    fmt::print(stderr, "ferrodyn: failure: the ramp stopped before its end: {}\n", r.message);
  }
  return plot(out.path(), a.no_plots, r.completed ? kExitOk : kExitRunFailure);
}

// ---------------------------------------------------------------- bifurcation
struct BranchArgs {
  std::string scene, output;
  double speed_max = NAN, speed_min = NAN, step = 2.0, bracket = 0.1;
  SettleArgs settle;
  bool no_plots = false, no_hopf = false, overwrite = false;
};

an::BranchOptions branch_options(const Scene& scene, const BranchArgs& a) {
  an::BranchOptions o;
  o.speed_start = a.speed_max;
  o.speed_stop = a.speed_min;
  if (std::isnan(a.speed_max) || std::isnan(a.speed_min))
    throw std::invalid_argument("--speed-max and --speed-min are required");
  if (!(a.speed_max > a.speed_min && a.speed_min > 0.0))
    throw std::invalid_argument("--speed-max/--speed-min: need speed-max > speed-min > 0");
  positive(a.step, "--step");
  positive(a.bracket, "--bracket");
  o.speed_step = a.step;
  o.bracket = a.bracket;
  o.settle = settle_options(scene, a.settle);
  return o;
}

an::KijRow run_branch(const Scene& base, const BranchArgs& a, const fc::ReductionFactors& k,
                      bool with_hopf, std::vector<std::string>* names, bool progress) {
  const Scene scene = an::with_reduction(base, k);
  auto o = branch_options(scene, a);
  const auto family = an::speed_family(scene);
  const auto probe = family(a.speed_max);
  const auto lateral = an::lateral_states(*probe);
  if (names) *names = lateral.name;
  o.settle.observed = lateral.index;
  const auto x0 = an::disturbed_state(scene, *probe, a.settle.disturbance);
  if (progress) {
    o.on_point = [&](const an::BranchPoint& p) {
      const auto& fit = p.run.fit;
      const std::string growth =
          fit.valid() ? fmt::format(" (sigma = {:.3g} +- {:.2g} /s, beta = {:.3g} /(s mm^2))",
                                    fit.sigma, fit.sigma_error, fit.beta * 1e-6)
                      : std::string();
      fmt::print(stderr,
                 "progress: K = ({}, {}) V = {:.4f} m/s{}: {} {:.4f} mm ({}) after {:.1f} s{}\n",
                 k.k11, k.k22, p.speed, p.bisection ? " (bisection)" : "",
                 an::to_string(p.run.outcome), p.run.amplitude[p.run.holder] * 1e3,
                 lateral.name[p.run.holder], p.run.time, growth);
    };
  }
  an::KijRow row;
  row.k = k;
  row.branch = an::follow_periodic_branch(family, x0, o);
  if (with_hopf)
    row.hopf_speed = scenarios::hopf_speed(scene, 0.5 * a.speed_min, 1.5 * a.speed_max, 64);
  return row;
}

// How the linear critical speed relates to the nonlinear one: the fold below the Hopf speed
// (by more than the bracket) is a subcritical bifurcation, where the linear speed promises
// stable running that a disturbance can break: it is non-conservative.
std::string linear_against_nonlinear(const an::BranchResult& b, double hopf) {
  const double width = b.bracket_high - b.bracket_low;
  if (!b.fold_found) return "";
  if (b.bracket_high < hopf - width) {
    return fmt::format(
        "non-conservative: the vehicle keeps a limit cycle {:.2f} m/s ({:.1f} %) below it "
        "(subcritical bifurcation: between the fold and the Hopf speed a disturbance can start "
        "hunting that the eigenvalues call stable)",
        hopf - *b.lowest_sustained, 100.0 * (hopf - *b.lowest_sustained) / hopf);
  }
  if (b.bracket_low > hopf + width) {
    return "the fold lies above the Hopf speed: the cycles near the fold did not settle within "
           "--t-max (or the disturbance missed the branch); lengthen the runs";
  }
  return "the fold bracket holds the Hopf speed: the cycle grows from zero there "
         "(supercritical bifurcation), the linear critical speed is the nonlinear one";
}

void print_branch(const an::KijRow& row, const std::vector<std::string>& names) {
  fmt::print("  {:>10} {:>10} {:>9} {:>5} {:>12}", "V [m/s]", "V [km/h]", "outcome", "bis.",
             "held by");
  for (const auto& n : names) fmt::print(" {:>14}", n + " [mm]");
  fmt::print("\n");
  for (const auto& p : row.branch.points) {
    fmt::print("  {:>10.4f} {:>10.3f} {:>9} {:>5} {:>12}", p.speed, p.speed * 3.6,
               an::to_string(p.run.outcome), p.bisection ? "yes" : "",
               an::sustained(p.run.outcome) ? names[p.run.holder] : "");
    for (double amp : p.run.amplitude) fmt::print(" {:>14.4f}", amp * 1e3);
    fmt::print("\n");
  }
  const auto& b = row.branch;
  if (b.fold_found) {
    const double a_fold = [&] {
      for (const auto& p : b.points)
        if (p.speed == *b.lowest_sustained && an::sustained(p.run.outcome))
          return p.run.amplitude[p.run.holder];
      return std::numeric_limits<double>::quiet_NaN();
    }();
    fmt::print("  nonlinear critical speed (lowest speed where any wheelset keeps a limit cycle): "
               "{:.4f} m/s = {:.2f} km/h, fold in [{:.4f}, {:.4f}] m/s, cycle held by {} "
               "({:.3f} mm)\n",
               *b.lowest_sustained, *b.lowest_sustained * 3.6, b.bracket_low, b.bracket_high,
               names[b.holder], a_fold * 1e3);
    // The A^2 line to zero is a result only where its assumption holds: a supercritical onset,
    // the amplitude growing from zero at the fold.
    if (b.supercritical) {
      fmt::print(
          "  onset     supercritical: amplitude^2 of the lowest cycles falls linearly to zero at "
          "{:.4f} m/s, inside the fold bracket\n",
          b.amplitude_squared_zero);
    } else {
      fmt::print("  onset     subcritical: the amplitude jumps from 0 to {:.3f} mm at the fold\n",
                 a_fold * 1e3);
    }
  } else if (b.lowest_sustained) {
    fmt::print("  sustained down to the lowest speed followed ({:.4f} m/s, held by {}): the fold "
               "lies below\n",
               *b.lowest_sustained, names[b.holder]);
  } else {
    fmt::print("  no sustained oscillation at the start speed {:.4f} m/s: the fold lies above\n",
               b.bracket_high);
  }
  if (row.hopf_speed) {
    const std::string relation = linear_against_nonlinear(b, *row.hopf_speed);
    fmt::print("  linear (Hopf) critical speed: {:.4f} m/s = {:.2f} km/h{}{}\n", *row.hopf_speed,
               *row.hopf_speed * 3.6, relation.empty() ? "" : ": ", relation);
  }
}

int do_branch(const BranchArgs& a) {
  const Scene scene = scenarios::load_scene(a.scene);
  (void)branch_options(scene, a);  // validate before starting
  AnalysisOutput out(a.output, sibling(scene.output.file, "_bifurcation.h5"), a.overwrite,
                     scenarios::scene_inputs(scene), a.no_plots);
  fmt::print("ferrodyn critical-speed bifurcation: {} ({}), K11 = {}, K22 = {}\n", scene.name,
             scene.path, a.settle.k11, a.settle.k22);
  std::vector<std::string> names;
  const auto row =
      run_branch(scene, a, fc::ReductionFactors::following_k22(a.settle.k11, a.settle.k22),
                 !a.no_hopf, &names, true);
  print_branch(row, names);
  const Scene reduced = an::with_reduction(scene, row.k);
  an::write_branch(reduced, row.branch, names, row.hopf_speed, out.write_path());
  out.file->commit();
  fmt::print("  output    {}\n", out.path());
  return plot(out.path(), a.no_plots, kExitOk);
}

// ---------------------------------------------------------------- eigen
struct EigenArgs {
  std::string scene;
  double speed_min = 1.0, speed_max = 150.0;
  int points = 150;
  double k11 = 1.0, k22 = 1.0;
  std::string output;
  bool no_plots = false, overwrite = false;
};

int do_eigen(const EigenArgs& a) {
  Scene scene = an::with_reduction(scenarios::load_scene(a.scene),
                                   fc::ReductionFactors::following_k22(a.k11, a.k22));
  if (!(a.speed_min > 0.0 && a.speed_max > a.speed_min) || a.points < 2)
    throw std::invalid_argument("--speed-min/--speed-max/--points: need 0 < min < max, points >= 2");
  scene.eigen.speed_min = a.speed_min;
  scene.eigen.speed_max = a.speed_max;
  scene.eigen.points = a.points;
  AnalysisOutput out(a.output, sibling(scene.output.file, "_eig.h5"), a.overwrite,
                     scenarios::scene_inputs(scene), a.no_plots);
  const auto r = scenarios::run_eigen(scene);
  fmt::print("ferrodyn critical-speed eigen: {} ({}), K11 = {}, K22 = {}\n", scene.name,
             scene.path, a.k11, a.k22);
  print_eigen_report(scene, r, 16);
  scenarios::write_eigen_report(scene, r, out.write_path());
  out.file->commit();
  fmt::print("  output    {}\n", out.path());
  return plot(out.path(), a.no_plots, kExitOk);
}

// ---------------------------------------------------------------- K_ij study
struct KijArgs {
  BranchArgs branch;
  std::vector<double> k;
  std::string coefficient = "both";
  int jobs = 1;
};

int do_kij(const KijArgs& a) {
  const Scene scene = scenarios::load_scene(a.branch.scene);
  if (a.k.empty()) throw std::invalid_argument("--k: give at least one reduction factor");
  if (a.coefficient != "both" && a.coefficient != "k11" && a.coefficient != "k22")
    throw std::invalid_argument(
        fmt::format("--coefficient: unknown '{}'; allowed: both, k11, k22", a.coefficient));
  std::vector<fc::ReductionFactors> ks;
  for (double k : a.k) {
    fc::ReductionFactors r =
        fc::ReductionFactors::following_k22(a.branch.settle.k11, a.branch.settle.k22);
    if (a.coefficient == "both") r = fc::ReductionFactors::uniform(k);
    if (a.coefficient == "k11") r.k11 = k;
    if (a.coefficient == "k22") r = fc::ReductionFactors::following_k22(r.k11, k);
    ks.push_back(r);
  }
  (void)branch_options(scene, a.branch);  // validate before starting
  AnalysisOutput out(a.branch.output, sibling(scene.output.file, "_kij.h5"), a.branch.overwrite,
                     scenarios::scene_inputs(scene), a.branch.no_plots);
  std::vector<an::KijRow> rows(ks.size());
  std::vector<std::string> names;
  std::mutex m;
  std::size_t done = 0;
  an::parallel_for(
      ks.size(),
      [&](std::size_t i) {
        std::vector<std::string> n;
        auto row = run_branch(scene, a.branch, ks[i], !a.branch.no_hopf, &n, false);
        std::lock_guard lock(m);
        rows[i] = std::move(row);
        names = n;
        ++done;
        fmt::print(stderr, "progress: K11 = {}, K22 = {} done ({}/{})\n", ks[i].k11, ks[i].k22,
                   done, ks.size());
      },
      a.jobs, [] { return InterruptGuard::signal_received() != 0; });
  if (InterruptGuard::signal_received() != 0) return 128 + InterruptGuard::signal_received();
  fmt::print("ferrodyn kij-study: {} ({}), reduction on {}\n", scene.name, scene.path,
             a.coefficient);
  fmt::print("  {:>5} {:>5} | {:>10} {:>10} {:>19} {:>10} {:>8} | {:>6} {:>10} {:>8}\n", "K11",
             "K22", "Vc [m/s]", "Vc [km/h]", "fold bracket [m/s]", "Hopf[km/h]", "Vc/Vc1",
             "thesis", "Vc [km/h]", "Vc/Vc1");
  const auto& thesis = an::thesis_table_4_1();
  const double vc1 = rows.front().branch.lowest_sustained.value_or(NAN);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& b = rows[i].branch;
    const double vc = b.fold_found ? *b.lowest_sustained : NAN;
    const double k = a.k[i];
    std::string th = "      -          -        -";
    for (const auto& t : thesis) {
      if (std::abs(t.k - k) < 1e-9)
        th = fmt::format("{:>6.1f} {:>10.0f} {:>8.3f}", t.k, t.critical_speed_kmh,
                         t.critical_speed_kmh / thesis.front().critical_speed_kmh);
    }
    fmt::print("  {:>5.2f} {:>5.2f} | {:>10.4f} {:>10.2f} [{:>8.4f}, {:>8.4f}] {:>10.2f} {:>8.3f} | {}\n",
               rows[i].k.k11, rows[i].k.k22, vc, vc * 3.6, b.bracket_low, b.bracket_high,
               rows[i].hopf_speed.value_or(NAN) * 3.6, vc / vc1, th);
  }
  if (std::abs(a.k.front() - 1.0) > 1e-12)
    fmt::print("  (ratios are to the first K in the list, {})\n", a.k.front());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].hopf_speed) continue;
    const std::string relation = linear_against_nonlinear(rows[i].branch, *rows[i].hopf_speed);
    if (!relation.empty())
      fmt::print("  K = ({:.2f}, {:.2f}): Hopf speed {}\n", rows[i].k.k11, rows[i].k.k22,
                 relation.substr(0, relation.find(" (")));
  }
  an::write_kij_study(scene, rows, out.write_path());
  out.file->commit();
  fmt::print("  output    {}\n", out.path());
  return plot(out.path(), a.branch.no_plots, kExitOk);
}

// ---------------------------------------------------------------- sweep
struct SweepArgs {
  std::string scene, output;
  double speed_min = NAN, speed_max = NAN;
  int points = 10;
  std::vector<double> k = {1.0};
  std::string coefficient = "both";
  SettleArgs settle;
  int jobs = 1;
  int max_new_points = -1;  // -1: no limit
  bool restart = false, quiet = false, no_plots = false, overwrite = false;
};

struct MpiContext {
  int rank = 0, size = 1;
  bool active = false;
};

MpiContext mpi_start() {
  MpiContext c;
#ifdef FERRO_WITH_MPI
  // Only under a launcher (mpirun sets these): a plain run stays a plain process.
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &c.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &c.size);
    c.active = true;
  }
#endif
  return c;
}

// Rank 0 receives every other rank's serialised results (one string each).
std::vector<std::string> mpi_gather(const MpiContext& c, const std::string& mine) {
  std::vector<std::string> all = {mine};
#ifdef FERRO_WITH_MPI
  if (!c.active) return all;
  int len = static_cast<int>(mine.size());
  std::vector<int> lens(static_cast<std::size_t>(c.size));
  MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> displ(static_cast<std::size_t>(c.size), 0);
  int total = 0;
  for (int i = 0; i < c.size; ++i) {
    displ[static_cast<std::size_t>(i)] = total;
    total += lens[static_cast<std::size_t>(i)];
  }
  std::string buf(static_cast<std::size_t>(c.rank == 0 ? total : 0), '\0');
  MPI_Gatherv(mine.data(), len, MPI_CHAR, buf.data(), lens.data(), displ.data(), MPI_CHAR, 0,
              MPI_COMM_WORLD);
  if (c.rank == 0) {
    all.clear();
    for (int i = 0; i < c.size; ++i)
      all.push_back(buf.substr(static_cast<std::size_t>(displ[static_cast<std::size_t>(i)]),
                               static_cast<std::size_t>(lens[static_cast<std::size_t>(i)])));
  }
#else
  (void)c;
#endif
  return all;
}

void mpi_barrier(const MpiContext& c) {
#ifdef FERRO_WITH_MPI
  if (c.active) MPI_Barrier(MPI_COMM_WORLD);
#else
  (void)c;
#endif
}

void mpi_finish(const MpiContext& c) {
#ifdef FERRO_WITH_MPI
  if (c.active) MPI_Finalize();
#else
  (void)c;
#endif
}

int do_sweep_ranked(const SweepArgs& a, const MpiContext& mpi) {
  const Scene scene = scenarios::load_scene(a.scene);
  if (std::isnan(a.speed_min) || std::isnan(a.speed_max) ||
      !(a.speed_max >= a.speed_min && a.speed_min > 0.0))
    throw std::invalid_argument("--speed-min/--speed-max: required, 0 < min <= max");
  if (a.points < 1 || (a.points == 1) != (a.speed_min == a.speed_max))
    throw std::invalid_argument("--points: >= 1 (1 only when min = max)");
  if (a.jobs < 1) throw std::invalid_argument("--jobs: must be >= 1");
  if (a.coefficient != "both" && a.coefficient != "k11" && a.coefficient != "k22")
    throw std::invalid_argument(
        fmt::format("--coefficient: unknown '{}'; allowed: both, k11, k22", a.coefficient));
  const auto settle = settle_options(scene, a.settle);
  std::vector<an::SweepPoint> points;
  for (double k : a.k) {
    fc::ReductionFactors r = fc::ReductionFactors::following_k22(a.settle.k11, a.settle.k22);
    if (a.coefficient == "both") r = fc::ReductionFactors::uniform(k);
    if (a.coefficient == "k11") r.k11 = k;
    if (a.coefficient == "k22") r = fc::ReductionFactors::following_k22(r.k11, k);
    (void)an::with_reduction(scene, r);  // validates the factors
    for (int i = 0; i < a.points; ++i) {
      const double v = a.points == 1 ? a.speed_min
                                     : a.speed_min + (a.speed_max - a.speed_min) * i /
                                                         static_cast<double>(a.points - 1);
      points.push_back({v, r});
    }
  }
  // Rank 0 writes the output: claimed before any point is computed.
  std::optional<AnalysisOutput> output;
  if (mpi.rank == 0) {
    output.emplace(a.output, sibling(scene.output.file, "_sweep.h5"), a.overwrite,
                   scenarios::scene_inputs(scene), a.no_plots);
  }
  const std::string out = a.output.empty() ? sibling(scene.output.file, "_sweep.h5") : a.output;
  const std::string journal_dir = out + ".points";
  // Everything that changes the numbers identifies the sweep.
  std::string signature = scene.text + " records-with-holder";
  for (const auto& p : points) signature += fmt::format(" {:.17g}/{:.17g}/{:.17g}", p.speed, p.k.k11, p.k.k22);
  signature += fmt::format(" {} {} {} {} {} {} {} {}", a.settle.disturbance, settle.segment,
                           settle.max_time, settle.output_interval, settle.zero_amplitude,
                           settle.max_amplitude, settle.amplitude.periods, settle.amplitude.rel_tol);
  if (mpi.rank == 0 && a.restart && fs::exists(journal_dir)) fs::remove_all(journal_dir);
  mpi_barrier(mpi);
  std::unique_ptr<an::SweepJournal> journal;
  if (mpi.rank == 0) journal = std::make_unique<an::SweepJournal>(journal_dir, signature);
  mpi_barrier(mpi);
  if (mpi.rank != 0) journal = std::make_unique<an::SweepJournal>(journal_dir, signature);
  const auto finished = journal->load();
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (finished.count(i) == 0 && static_cast<int>(i % static_cast<std::size_t>(mpi.size)) == mpi.rank)
      todo.push_back(i);
  }
  // Fastest first: above the critical speed a run hunts into flange contact and costs several
  // times a decaying one, so starting those first keeps the threads busy to the end instead of
  // leaving the dearest points for last (results are stored by index, whatever the order).
  std::stable_sort(todo.begin(), todo.end(), [&points](std::size_t l, std::size_t r) {
    return points[l].speed > points[r].speed;
  });
  if (a.max_new_points >= 0 && todo.size() > static_cast<std::size_t>(a.max_new_points))
    todo.resize(static_cast<std::size_t>(a.max_new_points));
  if (mpi.rank == 0) {
    fmt::print(stderr, "ferrodyn sweep: {} points ({} already finished in {}), {} rank(s) x {} "
               "thread(s)\n",
               points.size(), finished.size(), journal_dir, mpi.size, a.jobs);
  }
  const auto wall0 = std::chrono::steady_clock::now();
  std::size_t done = 0;
  an::PoolOptions pool;
  pool.jobs = a.jobs;
  pool.should_stop = [] { return InterruptGuard::signal_received() != 0; };
  pool.on_done = [&](const an::SweepPointResult& r) {
    journal->record(r);
    ++done;
    if (!a.quiet) {
      const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      fmt::print(stderr, "[rank {} {:>4}/{:<4} {:6.1f} s] V = {:8.4f} m/s K = ({:.3f}, {:.3f}): {} "
                 "{:.4f} mm (wheelset {})\n",
                 mpi.rank, done, todo.size(), el, r.point.speed, r.point.k.k11, r.point.k.k22,
                 an::to_string(r.outcome),
                 r.amplitude.empty() ? NAN : r.amplitude[r.holder] * 1e3, r.holder + 1);
    }
  };
  const auto resources = scenarios::build_resources(scene);
  const auto mine = an::run_pool(
      todo,
      [&](std::size_t i) {
        return an::run_sweep_point(scene, resources, i, points[i], a.settle.disturbance, settle);
      },
      pool);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  std::string text;
  for (const auto& r : mine) text += an::serialize(r) + "\n";
  const int sig = InterruptGuard::signal_received();
  const auto gathered = mpi_gather(mpi, text);
  if (mpi.rank != 0) return sig != 0 ? 128 + sig : kExitOk;
  // Rank 0: merge the journal (earlier runs) with what every rank computed now.
  std::map<std::size_t, an::SweepPointResult> all = finished;
  for (const auto& chunk : gathered) {
    std::size_t pos = 0;
    while (pos < chunk.size()) {
      const auto end = chunk.find('\n', pos);
      const auto line = chunk.substr(pos, end - pos);
      if (!line.empty()) {
        auto r = an::deserialize(line, "sweep gather");
        all[r.index] = r;
      }
      pos = end == std::string::npos ? chunk.size() : end + 1;
    }
  }
  for (const auto& [i, r] : journal->load()) all.emplace(i, r);  // other ranks' records
  if (sig != 0 || all.size() < points.size()) {
    fmt::print(stderr,
               "ferrodyn sweep: stopped with {} of {} points finished (recorded in {}); run the "
               "same command again to resume\n",
               all.size(), points.size(), journal_dir);
    return sig != 0 ? 128 + sig : kExitRunFailure;
  }
  std::vector<an::SweepPointResult> results;
  double cpu = 0.0;
  for (auto& [i, r] : all) {
    cpu += r.cpu_seconds;
    results.push_back(r);
  }
  const auto probe = scenarios::build_system(scene, points.front().speed);
  const auto names = an::lateral_states(*probe).name;
  an::write_sweep(scene, names, results, output->write_path());
  output->file->commit();
  fs::remove_all(journal_dir);  // complete: the HDF5 file holds every point
  fmt::print("ferrodyn sweep: {} ({}), {} points, {} rank(s) x {} thread(s)\n", scene.name,
             scene.path, points.size(), mpi.size, a.jobs);
  fmt::print("  {:>10} {:>6} {:>6} {:>9} {:>12}", "V [m/s]", "K11", "K22", "outcome", "held by");
  for (const auto& n : names) fmt::print(" {:>14}", n + " [mm]");
  fmt::print(" {:>9}\n", "cpu [s]");
  for (const auto& r : results) {
    fmt::print("  {:>10.4f} {:>6.3f} {:>6.3f} {:>9} {:>12}", r.point.speed, r.point.k.k11,
               r.point.k.k22, an::to_string(r.outcome),
               an::sustained(r.outcome) && r.holder < names.size() ? names[r.holder] : "");
    for (std::size_t j = 0; j < names.size(); ++j)
      fmt::print(" {:>14.5f}", j < r.amplitude.size() ? r.amplitude[j] * 1e3 : NAN);
    fmt::print(" {:>9.3f}\n", r.cpu_seconds);
  }
  fmt::print("  wall      {:.2f} s this invocation; CPU {:.2f} s over all points\n", wall, cpu);
  fmt::print("  output    {}\n", out);
  return plot(out, a.no_plots, kExitOk);
}

int do_sweep(const SweepArgs& a) {
  const MpiContext mpi = mpi_start();
  int rc = kExitRunFailure;
  try {
    rc = do_sweep_ranked(a, mpi);
  } catch (...) {
#ifdef FERRO_WITH_MPI
    if (mpi.active && mpi.size > 1) {
      // Another rank may wait in a collective: take the job down with this rank's error.
      try {
        throw;
      } catch (const std::exception& e) {
        fmt::print(stderr, "ferrodyn: rank {}: {}\n", mpi.rank, e.what());
      }
      MPI_Abort(MPI_COMM_WORLD, kExitRunFailure);
    }
#endif
    mpi_finish(mpi);
    throw;
  }
  mpi_finish(mpi);
  return rc;
}

void add_k_options(CLI::App* c, std::vector<double>& k, std::string& coefficient) {
  c->add_option("--k", k, "Reduction factors (one run per value)")->delimiter(',');
  c->add_option("--coefficient", coefficient, "Which factor --k sets: both (K11 = K22 = K23 = K33), k11, k22")->capture_default_str();
}

}  // namespace

void print_eigen_report(const Scene& scene, const scenarios::EigenReport& r,
                        std::size_t max_rows) {
  using vehicle::ModeClass;
  const auto cell = [](const vehicle::Mode& m) {
    return std::isnan(m.damping_ratio) ? fmt::format("{:>10} {:>8}", "-", "-")
                                       : fmt::format("{:>+10.5f} {:>8.3f}", m.damping_ratio,
                                                     m.frequency_hz);
  };
  const bool classified = !r.sweep.empty() && r.sweep.front().least_damped.kind !=
                                                  ModeClass::unclassified;
  const std::size_t stride = std::max<std::size_t>(1, (r.sweep.size() + max_rows - 1) / max_rows);
  if (classified) {
    // Classes other than hunting and contact only where the model has such modes.
    std::vector<ModeClass> shown = {ModeClass::hunting, ModeClass::contact};
    for (const auto c : {ModeClass::longitudinal, ModeClass::body, ModeClass::track}) {
      for (const auto& p : r.sweep) {
        if (!std::isnan(p.of(c).damping_ratio)) {
          shown.push_back(c);
          break;
        }
      }
    }
    fmt::print("  hunting mode (followed down from the highest speed by its shape) and the least "
               "damped mode of each other class: damping ratio, frequency [Hz]; shapes as "
               "kinetic-energy shares\n");
    fmt::print("  {:>8} {:>8}", "V [m/s]", "V [km/h]");
    for (const auto c : shown) fmt::print(" | {:<19}", vehicle::to_string(c));
    fmt::print(" | hunting mode shape\n");
    for (std::size_t i = 0; i < r.sweep.size(); i += stride) {
      const auto& p = r.sweep[i];
      fmt::print("  {:>8.3f} {:>8.2f}", p.speed, p.speed * 3.6);
      for (const auto c : shown) fmt::print(" | {}", cell(c == ModeClass::hunting ? p.hunting : p.of(c)));
      fmt::print(" | {}{}\n", p.hunting.shape(),
                 p.hunting_correlation < vehicle::kShapeTracked
                     ? " (branch lost above: least damped hunting-class mode)"
                     : "");
    }
  } else {
    fmt::print("  {:>10} {:>10} {:>14} {:>12}\n", "V [m/s]", "V [km/h]", "damping ratio",
               "freq [Hz]");
    for (std::size_t i = 0; i < r.sweep.size(); i += stride) {
      const auto& p = r.sweep[i];
      fmt::print("  {:>10.3f} {:>10.2f} {:>+14.5f} {:>12.4f}\n", p.speed, p.speed * 3.6,
                 p.least_damped.damping_ratio, p.least_damped.frequency_hz);
    }
  }
  if (r.critical_speed) {
    fmt::print("  Hopf speed ({} mode crosses zero damping): {:.6f} m/s = {:.3f} km/h\n",
               classified ? "a hunting" : "the least damped", *r.critical_speed,
               *r.critical_speed * 3.6);
  } else {
    fmt::print("  no {}critical speed in [{:g}, {:g}] m/s\n", classified ? "hunting " : "",
               scene.eigen.speed_min, scene.eigen.speed_max);
  }
  if (classified) {
    // Other classes that are unstable somewhere: reported, not taken for hunting.
    for (const auto c : {ModeClass::contact, ModeClass::longitudinal, ModeClass::body,
                         ModeClass::track}) {
      for (const auto& p : r.sweep) {
        if (p.of(c).damping_ratio <= -vehicle::kNeutralDamping) {
          fmt::print("  note      a {} mode is unstable at {:.3f} m/s ({:.3f} Hz, damping {:+.5f}, "
                     "{})\n",
                     vehicle::to_string(c), p.speed, p.of(c).frequency_hz, p.of(c).damping_ratio,
                     p.of(c).shape());
          break;
        }
      }
    }
    if (!r.modes_at_scene_speed.empty()) {
      fmt::print("  modes at the scene's speed {:.3f} m/s, least damped first (up to 12):\n",
                 scene.simulation.speed);
      std::size_t shown = 0;
      for (const auto& m : r.modes_at_scene_speed) {
        if (m.eigenvalue.imag() < 0.0) continue;  // one of each complex pair
        fmt::print("    {:<12} {:>+10.5f} {:>9.3f} Hz  {}\n", vehicle::to_string(m.kind),
                   m.damping_ratio, m.frequency_hz, m.shape());
        if (++shown == 12) break;
      }
    }
  }
}

void add_analysis_commands(CLI::App& app, VerbHandler& handler) {
  auto d = std::make_shared<AssessArgs>();
  auto* as = app.add_subcommand(
      "assess",
      "Assessment of a run as EN 14363 / UIC 518 / EN 12299 define it: running safety, track "
      "loading, stability, ride; table, HDF5 and plots along the track");
  as->add_option("run", d->file, "HDF5 output of `ferrodyn run` (vehicle scene)")->required();
  as->add_option("--category", d->category,
                 "Vehicle category (coach, locomotive, power_car, wagon); default: the vehicle "
                 "file's")
      ->check(CLI::IsMember({"coach", "locomotive", "power_car", "wagon"}));
  as->add_option("--mu", d->mu, "Friction coefficient in Nadal's limit (default: the run's)")
      ->check(number_in(0.0, 2.0, false, true, ""));
  as->add_option("--flange-angle-deg", d->flange_angle_deg,
                 "Flange angle in Nadal's limit [deg] (default: largest contact angle of each "
                 "wheel)")
      ->check(number_in(0.0, 90.0, true, true, "deg"));
  as->add_option("--section-length", d->section_length,
                 "Statistics over windows of this length [m] instead of the scene's sections")
      ->check(number_in(0.0, INFINITY, true, true, "m"));
  as->add_option("--f0", d->f0, "Instability frequency [Hz] (default: from the run's spectrum)")
      ->check(number_in(0.0, INFINITY, true, true, "Hz"));
  as->add_option("--floor-offset", d->floor_offset,
                 "Lateral offset of the vertical floor points [m] (0: centre line only)")
      ->check(number_in(0.0, INFINITY, false, true, "m"))
      ->capture_default_str();
  as->add_option("--y-over-q-limit", d->y_over_q_limit, "(Y/Q) limit of the 2 m mean")
      ->check(number_in(0.0, INFINITY, true, true, ""))
      ->capture_default_str();
  as->add_flag("--twist-test", d->twist_test, "Assess the wheel unloading dQ/Q0 too");
  as->add_flag("--no-twist-test", d->no_twist_test,
               "Do not assess dQ/Q0 even when the scene says it is the twist test");
  as->add_flag("--all", d->all_rows, "Print every section's row (default: the worst per item)");
  as->add_option("-o,--output", d->output, "Report file (default: <run>_assessment.h5)");
  as->add_flag("--no-plots", d->no_plots, "Do not draw plots");
  add_overwrite_flag(as, d->overwrite);
  as->callback([&handler, d] { handler = [d] { return do_assess(*d); }; });

  auto* cs = app.add_subcommand("critical-speed", "Critical speed: ramp, bifurcation, eigen");
  cs->require_subcommand(1);

  auto r = std::make_shared<RampArgs>();
  auto* ramp = cs->add_subcommand("ramp", "Decelerating run after a lateral disturbance");
  ramp->add_option("scene", r->scene, "Scene YAML file")->required();
  ramp->add_option("--speed-initial", r->speed_initial, "Start speed [m/s]")->capture_default_str();
  ramp->add_option("--deceleration", r->deceleration, "[m/s^2]")->capture_default_str();
  ramp->add_option("--speed-final", r->speed_final, "End speed [m/s] (default: 0.1 x start)");
  ramp->add_option("--hold", r->hold, "Constant-speed piece duration [s]")->capture_default_str();
  ramp->add_option("--threshold", r->threshold, "Envelope below which the oscillation died [m]")
      ->capture_default_str();
  ramp->add_option("--max-amplitude", r->max_amplitude, "Stop as diverged above this [m]")
      ->capture_default_str();
  ramp->add_option("--envelope-window", r->window, "Envelope trailing window [s]")->capture_default_str();
  ramp->add_option("--output-interval", r->interval, "Sampling [s]")->capture_default_str();
  ramp->add_option("--disturbance", r->disturbance, "Initial lateral offset [m]")->capture_default_str();
  ramp->add_option("--k11", r->k11, "Reduction factor on C11")->capture_default_str();
  ramp->add_option("--k22", r->k22, "Reduction factor on C22")->capture_default_str();
  ramp->add_option("-o,--output", r->output, "HDF5 output (default: <output.file stem>_ramp.h5)");
  ramp->add_flag("--no-plots", r->no_plots, "Do not draw plots");
  add_overwrite_flag(ramp, r->overwrite);
  ramp->callback([&handler, r] { handler = [r] { return do_ramp(*r); }; });

  auto b = std::make_shared<BranchArgs>();
  auto* bif = cs->add_subcommand(
      "bifurcation", "Limit-cycle amplitudes followed down the periodic branch to the fold");
  bif->add_option("scene", b->scene, "Scene YAML file")->required();
  bif->add_option("--speed-max", b->speed_max, "First (highest) speed [m/s]")->required();
  bif->add_option("--speed-min", b->speed_min, "Lowest speed followed [m/s]")->required();
  bif->add_option("--step", b->step, "Downward speed step [m/s]")->capture_default_str();
  bif->add_option("--bracket", b->bracket, "Fold bracket width [m/s]")->capture_default_str();
  add_settle_options(bif, b->settle);
  bif->add_option("-o,--output", b->output,
                  "HDF5 output (default: <output.file stem>_bifurcation.h5)");
  bif->add_flag("--no-hopf", b->no_hopf, "Skip the eigenvalue (Hopf) speed");
  bif->add_flag("--no-plots", b->no_plots, "Do not draw plots");
  add_overwrite_flag(bif, b->overwrite);
  bif->callback([&handler, b] { handler = [b] { return do_branch(*b); }; });

  auto e = std::make_shared<EigenArgs>();
  auto* eig = cs->add_subcommand("eigen", "Linear eigenvalues against speed: the Hopf speed");
  eig->add_option("scene", e->scene, "Scene YAML file")->required();
  eig->add_option("--speed-min", e->speed_min, "[m/s]")->capture_default_str();
  eig->add_option("--speed-max", e->speed_max, "[m/s]")->capture_default_str();
  eig->add_option("--points", e->points, "Speeds in the sweep")
      ->check(count_in(2, scenarios::kMaxEigenPoints))
      ->capture_default_str();
  eig->add_option("--k11", e->k11, "Reduction factor on C11")->capture_default_str();
  eig->add_option("--k22", e->k22, "Reduction factor on C22")->capture_default_str();
  eig->add_option("-o,--output", e->output, "HDF5 output (default: <output.file stem>_eig.h5)");
  eig->add_flag("--no-plots", e->no_plots, "Do not draw plots");
  add_overwrite_flag(eig, e->overwrite);
  eig->callback([&handler, e] { handler = [e] { return do_eigen(*e); }; });

  auto k = std::make_shared<KijArgs>();
  k->k = {1.0, 0.9, 0.8, 0.7, 0.6, 0.5};
  auto* kij = app.add_subcommand(
      "kij-study", "Nonlinear critical speed against Kalker reduction factors (Table 4.1 layout)");
  kij->add_option("scene", k->branch.scene, "Scene YAML file")->required();
  add_k_options(kij, k->k, k->coefficient);
  kij->add_option("--speed-max", k->branch.speed_max, "First (highest) speed [m/s]")->required();
  kij->add_option("--speed-min", k->branch.speed_min, "Lowest speed followed [m/s]")->required();
  kij->add_option("--step", k->branch.step, "Downward speed step [m/s]")->capture_default_str();
  kij->add_option("--bracket", k->branch.bracket, "Fold bracket width [m/s]")->capture_default_str();
  add_settle_options(kij, k->branch.settle);
  kij->add_option("-j,--jobs", k->jobs, "Worker threads (one K per thread)")
      ->check(count_in(1, kMaxJobs))
      ->capture_default_str();
  kij->add_option("-o,--output", k->branch.output, "HDF5 output (default: <stem>_kij.h5)");
  kij->add_flag("--no-hopf", k->branch.no_hopf, "Skip the eigenvalue (Hopf) speeds");
  kij->add_flag("--no-plots", k->branch.no_plots, "Do not draw plots");
  add_overwrite_flag(kij, k->branch.overwrite);
  kij->callback([&handler, k] { handler = [k] { return do_kij(*k); }; });

  auto s = std::make_shared<SweepArgs>();
  auto* sw = app.add_subcommand(
      "sweep", "Independent constant-speed runs over speeds x reduction factors, on threads and "
               "MPI ranks, resumable");
  sw->add_option("scene", s->scene, "Scene YAML file")->required();
  sw->add_option("--speed-min", s->speed_min, "[m/s]")->required();
  sw->add_option("--speed-max", s->speed_max, "[m/s]")->required();
  sw->add_option("--points", s->points, "Speeds between min and max")
      ->check(count_in(1, scenarios::kMaxEigenPoints))
      ->capture_default_str();
  add_k_options(sw, s->k, s->coefficient);
  add_settle_options(sw, s->settle);
  sw->add_option("-j,--jobs", s->jobs, "Worker threads per process")
      ->check(count_in(1, kMaxJobs))
      ->capture_default_str();
  sw->add_option("-o,--output", s->output,
                 "HDF5 output (default: <output.file stem>_sweep.h5); finished points are kept "
                 "in <output>.points/ until the sweep completes");
  sw->add_option("--max-new-points", s->max_new_points,
                 "Compute at most this many new points per process, then stop (resumable; for "
                 "batch-queue time limits)")
      ->check(count_in(0, std::numeric_limits<int>::max()));
  sw->add_flag("--restart", s->restart, "Forget finished points and start over");
  sw->add_flag("-q,--quiet", s->quiet, "No progress display");
  sw->add_flag("--no-plots", s->no_plots, "Do not draw plots");
  add_overwrite_flag(sw, s->overwrite);
  sw->callback([&handler, s] { handler = [s] { return do_sweep(*s); }; });
}

}  // namespace ferro::cli
