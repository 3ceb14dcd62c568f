// Text reports of the analyses (see the header).
#include "ferro/scenarios/analysis/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace ferro::scenarios::analysis {
namespace {

// Envelope growth from the first full window to the peak above which the peak is shown: any
// growth at all (1 means the envelope is largest in its first window).
constexpr double kGrowthShown = 1.0;

}  // namespace

std::string derailment_report(const std::string& run_file, const DerailmentOptions& o,
                              const DerailmentReport& r) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "ferrodyn derailment: {} (mu = {}, {} m sliding mean every {} m)\n", run_file,
                 o.mu, o.window, o.step);
  fmt::format_to(out, "  {:<18} {:>8} {:>9} {:>8} {:>9} {:>7} {:>8} {:>9}  {}\n", "wheel",
                 "max Y/Q", "at [m]", "flange", "Nadal", "raw", "dQ/Q0", "at [m]", "verdict");
  for (const auto& w : r.wheels) {
    fmt::format_to(
        out, "  {:<18} {:>8.3f} {:>9.2f} {:>6.1f}deg {:>9.3f} {:>7.3f} {:>8.3f} {:>9.2f}  {}\n",
        w.name, w.max_y_over_q, w.max_y_over_q_position, w.flange_angle * 180.0 / M_PI, w.nadal,
        w.max_y_over_q_raw, w.max_unloading, w.max_unloading_position,
        w.pass_nadal && w.pass_unloading ? "pass" : "FAIL");
  }
  fmt::format_to(out, "  {:<18} {:>12} {:>9} {:>14} {:>12}  {}\n", "axle", "max sum Y [kN]",
                 "at [m]", "Prud'homme [kN]", "P [kN]", "verdict");
  for (const auto& x : r.axles) {
    fmt::format_to(out, "  {:<18} {:>12.2f} {:>9.2f} {:>14.2f} {:>12.2f}  {}\n", x.name,
                   x.max_sum_y / 1e3, x.max_sum_y_position, x.limit / 1e3, x.axle_load / 1e3,
                   x.pass ? "pass" : "FAIL");
  }
  fmt::format_to(out, "  verdict   {}\n", r.pass ? "pass" : "FAIL");
  return text;
}

std::string ramp_report(const RampStudy& study, const RampRequest& request) {
  std::string text;
  auto out = std::back_inserter(text);
  const Scene& scene = study.scene;
  const auto& o = study.options;
  const auto& r = study.result;
  fmt::format_to(out, "ferrodyn critical-speed ramp: {} ({}), K11 = {}, K22 = {}\n", scene.name,
                 scene.path, request.k11, request.k22);
  fmt::format_to(
      out, "  ramp      {:.3f} -> {:.3f} m/s at -{} m/s^2, pieces of {} s, {} + {} m at start\n",
      o.speed_initial, o.speed_final, o.deceleration, o.hold, study.observed, request.disturbance);
  if (!r.completed) fmt::format_to(out, "  stopped   {}\n", r.message);
  if (r.decay_speed) {
    fmt::format_to(out,
                   "  decay     {} envelope below {} m for good at t = {:.3f} s: V = {:.3f} m/s = "
                   "{:.2f} km/h\n",
                   study.observed, o.threshold, r.decay_time, *r.decay_speed, *r.decay_speed * 3.6);
  } else {
    fmt::format_to(out, "  decay     none: the envelope {} below {} m over the whole ramp\n",
                   r.envelope.empty() || r.envelope.back() >= o.threshold ? "never stays" : "stays",
                   o.threshold);
  }
  // The envelope's maximum is where its growth turns into decay; that is the Hopf speed only
  // while the oscillation is small enough to be linear (not on a flange-limited cycle).
  if (!std::isnan(r.peak_speed) && r.envelope_growth > kGrowthShown) {
    const auto peak = std::max_element(r.envelope.begin(), r.envelope.end());
    fmt::format_to(
        out,
        "  growth    the envelope grows x{:.4g} to its maximum {:.4g} mm at V = {:.3f} m/s = "
        "{:.2f} km/h, where growth turns to decay (the Hopf speed if the oscillation is "
        "still linear there)\n",
        r.envelope_growth, *peak * 1e3, r.peak_speed, r.peak_speed * 3.6);
  } else if (!std::isnan(r.peak_speed)) {
    fmt::format_to(out,
                   "  growth    none: the envelope is largest in its first window (the disturbance "
                   "decays or settles)\n");
  }
  return text;
}

std::string branch_report(const KijRow& row, const std::vector<std::string>& names) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "  {:>10} {:>10} {:>9} {:>5}", "V [m/s]", "V [km/h]", "outcome", "bis.");
  for (const auto& n : names) fmt::format_to(out, " {:>14}", n + " [mm]");
  fmt::format_to(out, "\n");
  for (const auto& p : row.branch.points) {
    fmt::format_to(out, "  {:>10.4f} {:>10.3f} {:>9} {:>5}", p.speed, p.speed * 3.6,
                   to_string(p.run.outcome), p.bisection ? "yes" : "");
    for (double amp : p.run.amplitude) fmt::format_to(out, " {:>14.4f}", amp * 1e3);
    fmt::format_to(out, "\n");
  }
  const auto& b = row.branch;
  if (b.fold_found) {
    fmt::format_to(
        out,
        "  nonlinear critical speed (lowest sustained oscillation): {:.4f} m/s = {:.2f} km/h, "
        "fold in [{:.4f}, {:.4f}] m/s\n",
        *b.lowest_sustained, *b.lowest_sustained * 3.6, b.bracket_low, b.bracket_high);
    if (!std::isnan(b.amplitude_squared_zero)) {
      fmt::format_to(
          out,
          "  onset     amplitude^2 of the lowest cycles extrapolates to zero at {:.4f} m/s = "
          "{:.2f} km/h: {}\n",
          b.amplitude_squared_zero, b.amplitude_squared_zero * 3.6,
          b.supercritical ? "supercritical (the amplitude grows from zero at the fold)"
                          : "subcritical (a finite cycle at the fold)");
    } else {
      fmt::format_to(
          out,
          "  onset     no amplitude^2 line to zero: fewer than two cycles, or their amplitude "
          "does not fall towards the fold (subcritical)\n");
    }
  } else if (b.lowest_sustained) {
    fmt::format_to(
        out, "  sustained down to the lowest speed followed ({:.4f} m/s): the fold lies below\n",
        *b.lowest_sustained);
  } else {
    fmt::format_to(
        out, "  no sustained oscillation at the start speed {:.4f} m/s: the fold lies above\n",
        b.bracket_high);
  }
  if (row.hopf_speed) {
    fmt::format_to(out, "  linear (Hopf) critical speed: {:.4f} m/s = {:.2f} km/h\n",
                   *row.hopf_speed, *row.hopf_speed * 3.6);
  }
  return text;
}

std::string kij_study_report(const Scene& scene, const KijStudyRequest& request,
                             const KijStudy& study) {
  std::string text;
  auto out = std::back_inserter(text);
  const auto& rows = study.rows;
  fmt::format_to(out, "ferrodyn kij-study: {} ({}), reduction on {}\n", scene.name, scene.path,
                 request.coefficient);
  fmt::format_to(out, "  {:>5} {:>5} | {:>10} {:>10} {:>19} {:>10} {:>8} | {:>6} {:>10} {:>8}\n",
                 "K11", "K22", "Vc [m/s]", "Vc [km/h]", "fold bracket [m/s]", "Hopf[km/h]",
                 "Vc/Vc1", "thesis", "Vc [km/h]", "Vc/Vc1");
  const auto& thesis = thesis_table_4_1();
  const double vc1 = rows.front().branch.lowest_sustained.value_or(NAN);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& b = rows[i].branch;
    const double vc = b.fold_found ? *b.lowest_sustained : NAN;
    const double k = request.k[i];
    std::string th = "      -          -        -";
    for (const auto& t : thesis) {
      if (std::abs(t.k - k) < 1e-9)
        th = fmt::format("{:>6.1f} {:>10.0f} {:>8.3f}", t.k, t.critical_speed_kmh,
                         t.critical_speed_kmh / thesis.front().critical_speed_kmh);
    }
    fmt::format_to(
        out,
        "  {:>5.2f} {:>5.2f} | {:>10.4f} {:>10.2f} [{:>8.4f}, {:>8.4f}] {:>10.2f} {:>8.3f} | {}\n",
        rows[i].k.k11, rows[i].k.k22, vc, vc * 3.6, b.bracket_low, b.bracket_high,
        rows[i].hopf_speed.value_or(NAN) * 3.6, vc / vc1, th);
  }
  if (std::abs(request.k.front() - 1.0) > 1e-12)
    fmt::format_to(out, "  (ratios are to the first K in the list, {})\n", request.k.front());
  return text;
}

std::string sweep_report(const Scene& scene, const SweepRequest& a, const SweepOutcome& r,
                         int ranks) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "ferrodyn sweep: {} ({}), {} points, {} rank(s) x {} thread(s)\n", scene.name,
                 scene.path, r.total, ranks, a.jobs);
  fmt::format_to(out, "  {:>10} {:>6} {:>6} {:>9} {:>14} {:>9}\n", "V [m/s]", "K11", "K22",
                 "outcome", r.wheelset_names.front() + " [mm]", "cpu [s]");
  for (const auto& p : r.results) {
    fmt::format_to(out, "  {:>10.4f} {:>6.3f} {:>6.3f} {:>9} {:>14.5f} {:>9.3f}\n", p.point.speed,
                   p.point.k.k11, p.point.k.k22, to_string(p.outcome),
                   p.amplitude.empty() ? NAN : p.amplitude.front() * 1e3, p.cpu_seconds);
  }
  fmt::format_to(out, "  wall      {:.2f} s this invocation; CPU {:.2f} s over all points\n",
                 r.wall_seconds, r.cpu_seconds);
  return text;
}

}  // namespace ferro::scenarios::analysis
