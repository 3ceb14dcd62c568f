// The critical-speed studies of a scene (see the header).
#include "ferro/scenarios/analysis/studies.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "ferro/scenarios/analysis/sweep.hpp"
#include "ferro/scenarios/report.hpp"
#include "ferro/scenarios/run.hpp"
#include "ferro/scenarios/vehicle_file.hpp"

namespace ferro::scenarios::analysis {
namespace {

void positive(double v, const char* key, Spelling sp) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(fmt::format("{}: must be > 0, got {}", spelled(key, sp), v));
}

}  // namespace

SettleOptions settle_options(const Scene& scene, const SettleRequest& s, Spelling sp) {
  positive(s.segment, "segment", sp);
  positive(s.t_max, "t_max", sp);
  positive(s.output_interval, "output_interval", sp);
  positive(s.zero_amplitude, "zero_amplitude", sp);
  positive(s.max_amplitude, "max_amplitude", sp);
  positive(s.rel_tol, "rel_tol", sp);
  if (s.periods < 1)
    throw std::invalid_argument(fmt::format("{}: must be >= 1", spelled("periods", sp)));
  if (s.t_max < s.segment)
    throw std::invalid_argument(
        fmt::format("{}: must be >= {}", spelled("t_max", sp), spelled("segment", sp)));
  if (s.max_amplitude <= s.zero_amplitude)
    throw std::invalid_argument(fmt::format("{}: must be > {}", spelled("max_amplitude", sp),
                                            spelled("zero_amplitude", sp)));
  SettleOptions o;
  o.solver = scene.solver;
  o.segment = s.segment;
  o.max_time = s.t_max;
  o.output_interval = s.output_interval;
  o.zero_amplitude = s.zero_amplitude;
  o.max_amplitude = s.max_amplitude;
  o.amplitude.periods = s.periods;
  o.amplitude.rel_tol = s.rel_tol;
  return o;
}

RampStudy run_ramp(const Scene& base, const RampRequest& a, Spelling sp) {
  RampStudy study;
  study.scene = with_reduction(base, contact::ReductionFactors::following_k22(a.k11, a.k22));
  RampOptions& o = study.options;
  o.speed_initial = a.speed_initial;
  o.deceleration = a.deceleration;
  o.speed_final = std::isnan(a.speed_final) ? 0.1 * a.speed_initial : a.speed_final;
  positive(a.speed_initial, "speed_initial", sp);
  positive(a.deceleration, "deceleration", sp);
  positive(a.hold, "hold", sp);
  positive(a.threshold, "threshold", sp);
  positive(a.envelope_window, "envelope_window", sp);
  positive(a.output_interval, "output_interval", sp);
  if (!(o.speed_final >= 0.0 && o.speed_final < o.speed_initial))
    throw std::invalid_argument(fmt::format("{}: allowed [0, {})", spelled("speed_final", sp),
                                            spelled("speed_initial", sp)));
  o.hold = a.hold;
  o.threshold = a.threshold;
  o.max_amplitude = a.max_amplitude;
  o.envelope_window = a.envelope_window;
  o.output_interval = a.output_interval;
  o.solver = study.scene.solver;
  const auto family = speed_family(study.scene);
  const auto probe = family(o.speed_initial);
  const auto lateral = lateral_states(*probe);
  o.observed = lateral.index;
  study.observed = lateral.name;
  const auto x0 = disturbed_state(study.scene, *probe, a.disturbance);
  study.result = ramp_down(family, x0, o);
  return study;
}

BranchOptions branch_options(const Scene& scene, const BranchRequest& a, Spelling sp) {
  BranchOptions o;
  o.speed_start = a.speed_max;
  o.speed_stop = a.speed_min;
  const std::string max = spelled("speed_max", sp), min = spelled("speed_min", sp);
  if (std::isnan(a.speed_max) || std::isnan(a.speed_min))
    throw std::invalid_argument(fmt::format("{} and {} are required", max, min));
  if (!(a.speed_max > a.speed_min && a.speed_min > 0.0))
    throw std::invalid_argument(fmt::format("{}/{}: need {} > {} > 0", max, min, max, min));
  positive(a.step, "step", sp);
  positive(a.bracket, "bracket", sp);
  o.speed_step = a.step;
  o.bracket = a.bracket;
  o.settle = settle_options(scene, a.settle, sp);
  return o;
}

KijRow run_bifurcation(const Scene& base, const BranchRequest& a,
                       const contact::ReductionFactors& k,
                       std::vector<std::string>* names,
                       const std::function<void(const BranchPoint&)>& on_point, Spelling sp) {
  const Scene scene = with_reduction(base, k);
  auto o = branch_options(scene, a, sp);
  const auto family = speed_family(scene);
  const auto probe = family(a.speed_max);
  const auto lateral = lateral_states(*probe);
  if (names) *names = lateral.name;
  o.settle.observed = lateral.index;
  const auto x0 = disturbed_state(scene, *probe, a.settle.disturbance);
  o.on_point = on_point;
  KijRow row;
  row.k = k;
  row.branch = follow_periodic_branch(family, x0, o);
  if (a.hopf) row.hopf_speed = hopf_speed(scene, 0.5 * a.speed_min, 1.5 * a.speed_max, 64);
  return row;
}

std::vector<contact::ReductionFactors> study_reductions(const std::vector<double>& k,
                                                        const std::string& coefficient,
                                                        const contact::ReductionFactors& base,
                                                        Spelling sp) {
  if (coefficient != "both" && coefficient != "k11" && coefficient != "k22")
    throw std::invalid_argument(fmt::format("{}: unknown '{}'; allowed: both, k11, k22",
                                            spelled("coefficient", sp), coefficient));
  std::vector<contact::ReductionFactors> out;
  for (double v : k) {
    contact::ReductionFactors r = base;
    if (coefficient == "both") r = contact::ReductionFactors::uniform(v);
    if (coefficient == "k11") r.k11 = v;
    if (coefficient == "k22") r = contact::ReductionFactors::following_k22(r.k11, v);
    out.push_back(r);
  }
  return out;
}

KijStudy run_kij_study(const Scene& scene, const KijStudyRequest& a,
                       const std::function<bool()>& should_stop,
                       const std::function<void(const KijRow&, std::size_t, std::size_t)>& on_row,
                       Spelling sp) {
  if (a.k.empty())
    throw std::invalid_argument(
        fmt::format("{}: give at least one reduction factor", spelled("k", sp)));
  const auto ks =
      study_reductions(a.k, a.coefficient, a.branch.settle.reduction(), sp);
  (void)branch_options(scene, a.branch, sp);  // validate before starting
  if (a.jobs < 1) throw std::invalid_argument(fmt::format("{}: must be >= 1", spelled("jobs", sp)));
  KijStudy study;
  study.rows.resize(ks.size());
  std::mutex m;
  std::size_t done = 0;
  parallel_for(
      ks.size(),
      [&](std::size_t i) {
        std::vector<std::string> n;
        auto row = run_bifurcation(scene, a.branch, ks[i], &n, {}, sp);
        std::lock_guard lock(m);
        study.rows[i] = std::move(row);
        study.names = n;
        ++done;
        if (on_row) on_row(study.rows[i], done, ks.size());
      },
      a.jobs, should_stop);
  study.interrupted = done < ks.size() || (should_stop && should_stop());
  return study;
}

AssessmentOptions assessment_options(const AssessmentRequest& a, Spelling sp) {
  AssessmentOptions o;
  if (!std::isnan(a.mu)) {
    if (!(a.mu >= 0.0 && a.mu < 2.0))
      throw std::invalid_argument(fmt::format("{}: allowed [0, 2), got {}", spelled("mu", sp), a.mu));
    o.mu = a.mu;
  }
  if (!std::isnan(a.flange_angle_deg)) {
    if (!(a.flange_angle_deg > 0.0 && a.flange_angle_deg < 90.0))
      throw std::invalid_argument(fmt::format("{}: allowed (0, 90), got {}",
                                              spelled("flange_angle_deg", sp), a.flange_angle_deg));
    o.flange_angle = a.flange_angle_deg * M_PI / 180.0;
  }
  if (a.section_length != 0.0) positive(a.section_length, "section_length", sp);
  o.section_length = a.section_length;
  if (!std::isnan(a.f0)) positive(a.f0, "f0", sp);
  o.f0 = a.f0;
  if (!(a.floor_offset >= 0.0) || !std::isfinite(a.floor_offset))
    throw std::invalid_argument(
        fmt::format("{}: must be >= 0 m, got {}", spelled("floor_offset", sp), a.floor_offset));
  o.floor_offset = a.floor_offset;
  positive(a.y_over_q_limit, "y_over_q_limit", sp);
  o.y_over_q_limit = a.y_over_q_limit;
  const auto& categories = vehicle_categories();
  if (!a.category.empty() &&
      std::find(categories.begin(), categories.end(), a.category) == categories.end()) {
    throw std::invalid_argument(fmt::format("{}: '{}' is not a category; allowed: {}",
                                            spelled("category", sp), a.category,
                                            fmt::join(categories, ", ")));
  }
  o.category = a.category;
  if (a.twist_test && a.no_twist_test) {
    throw std::invalid_argument(fmt::format("{} and {}: give one of them",
                                            spelled("twist_test", sp), spelled("no_twist_test", sp)));
  }
  if (a.twist_test) o.twist_test = true;
  if (a.no_twist_test) o.twist_test = false;
  return o;
}

Parameters parameters(SettleRequest& s) {
  return {
      {"disturbance", "m", "lateral offset added to the leading wheelset at the start",
       &s.disturbance},
      {"segment", "s", "simulated time per convergence check", &s.segment},
      {"t_max", "s", "simulated time limit per speed", &s.t_max},
      {"output_interval", "s", "sampling of the lateral states", &s.output_interval},
      {"zero_amplitude", "m", "below: the oscillation decayed", &s.zero_amplitude},
      {"max_amplitude", "m", "above: diverged", &s.max_amplitude},
      {"periods", "", "periods the steady amplitude is measured over", &s.periods},
      {"rel_tol", "-", "relative amplitude change that counts as settled", &s.rel_tol},
      {"k11", "-", "reduction factor on C11", &s.k11},
      {"k22", "-", "reduction factor on C22", &s.k22},
  };
}

Parameters parameters(RampRequest& r) {
  return {
      {"speed_initial", "m/s", "start speed", &r.speed_initial},
      {"deceleration", "m/s^2", "deceleration", &r.deceleration},
      {"speed_final", "m/s", "end speed (default: 0.1 x the start speed)", &r.speed_final,
       false},
      {"hold", "s", "duration of each constant-speed piece", &r.hold},
      {"threshold", "m", "envelope below which the oscillation died", &r.threshold},
      {"max_amplitude", "m", "stop as diverged above this", &r.max_amplitude},
      {"envelope_window", "s", "envelope trailing window", &r.envelope_window},
      {"output_interval", "s", "sampling", &r.output_interval},
      {"disturbance", "m", "initial lateral offset of the leading wheelset", &r.disturbance},
      {"k11", "-", "reduction factor on C11", &r.k11},
      {"k22", "-", "reduction factor on C22", &r.k22},
  };
}

Parameters parameters(BranchRequest& b) {
  Parameters p = {
      {"speed_max", "m/s", "first (highest) speed", &b.speed_max, false},
      {"speed_min", "m/s", "lowest speed followed", &b.speed_min, false},
      {"step", "m/s", "downward speed step", &b.step},
      {"bracket", "m/s", "fold bracket width", &b.bracket},
      {"hopf", "", "the eigenvalue (Hopf) speed in [0.5 speed_min, 1.5 speed_max]", &b.hopf},
  };
  for (auto& s : parameters(b.settle)) p.push_back(std::move(s));
  return p;
}

Parameters parameters(KijStudyRequest& k) {
  Parameters p = {
      {"k", "-", "reduction factors, one branch each", &k.k},
      {"coefficient", "",
       "which factor k sets: both (K11 = K22 = K23 = K33), k11, k22", &k.coefficient},
      Parameter{"jobs", "", "worker threads (one factor per thread)", &k.jobs}.counting(
          {1, kMaxJobs}),
  };
  for (auto& b : parameters(k.branch)) p.push_back(std::move(b));
  return p;
}

Parameters parameters(AssessmentRequest& a) {
  return {
      Parameter{"mu", "-", "friction coefficient in Nadal's limit (default: the run's)", &a.mu,
                false}
          .within({0.0, 2.0, false, true, ""}),
      Parameter{"flange_angle_deg", "deg",
                "flange angle in Nadal's limit (default: the largest contact angle of each wheel)",
                &a.flange_angle_deg, false}
          .within({0.0, 90.0, true, true, "deg"}),
      Parameter{"section_length", "m", "statistics over windows of this length instead of the "
                "scene's sections", &a.section_length, false}
          .within({0.0, kNoBound, true, true, "m"}),
      Parameter{"f0", "Hz", "instability frequency (default: from the run's spectrum)", &a.f0,
                false}
          .within({0.0, kNoBound, true, true, "Hz"}),
      Parameter{"floor_offset", "m",
                "lateral offset of the vertical floor points (0: centre line only)",
                &a.floor_offset}
          .within({0.0, kNoBound, false, true, "m"}),
      Parameter{"y_over_q_limit", "-", "(Y/Q) limit of the 2 m mean", &a.y_over_q_limit}
          .within({0.0, kNoBound, true, true, ""}),
      {"category", "", "vehicle category: coach, locomotive, power_car, wagon (default: the "
       "vehicle file's)", &a.category, false},
      {"twist_test", "", "assess the wheel unloading dQ/Q0 too", &a.twist_test},
      {"no_twist_test", "", "do not assess dQ/Q0 even when the scene says it is the twist test",
       &a.no_twist_test},
  };
}

RunOverrides EigenRequest::eigen_study_range() {
  RunOverrides r;
  r.speed_min = 1.0;
  r.speed_max = 150.0;
  r.points = 150;
  return r;
}

Scene eigen_study_scene(const Scene& scene, const EigenRequest& request, Spelling spelling) {
  Scene s = with_reduction(scene, contact::ReductionFactors::following_k22(request.k11, request.k22));
  apply_overrides(s, request.range, spelling);
  return s;
}

std::string eigen_study_report(const Scene& scene, const EigenRequest& request,
                               const EigenReport& report) {
  return fmt::format("ferrodyn critical-speed eigen: {} ({}), K11 = {}, K22 = {}\n", scene.name,
                     scene.path, request.k11, request.k22) +
         eigen_modes_report(scene, report, 16);
}

Parameters parameters(EigenRequest& e) {
  Parameters p = select_parameters(scenarios::parameters(e.range), {"speed_min", "speed_max", "points"});
  p.push_back({"k11", "-", "reduction factor on C11", &e.k11});
  p.push_back({"k22", "-", "reduction factor on C22", &e.k22});
  return p;
}

}  // namespace ferro::scenarios::analysis
