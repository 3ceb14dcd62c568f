// Text reports of the analyses (see the header).
#include "ferro/scenarios/analysis/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace ferro::scenarios::analysis {
namespace {

// How the linear critical speed relates to the nonlinear one: the fold below the Hopf speed
// (by more than the bracket) is a subcritical bifurcation, where the linear speed promises
// stable running that a disturbance can break: it is non-conservative.
std::string linear_against_nonlinear(const BranchResult& b, double hopf) {
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
           "t_max (or the disturbance missed the branch); lengthen the runs";
  }
  return "the fold bracket holds the Hopf speed: the cycle grows from zero there "
         "(supercritical bifurcation), the linear critical speed is the nonlinear one";
}

}  // namespace

std::string assessment_report(const std::string& run_file, const Assessment& r, bool all_rows) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "ferrodyn assess: {} ({}, category {}, alpha {:g}; output every {:.3g} ms)\n",
                 run_file, r.vehicle, r.category, r.alpha, 1e3 / r.sample_rate);
  fmt::format_to(out, "  sections: ");
  for (std::size_t i = 0; i < r.sections.size(); ++i)
    fmt::format_to(out, "{}{} [{:.1f}, {:.1f}) m", i ? "; " : "", r.sections[i].name,
                   r.sections[i].start, r.sections[i].end);
  if (std::isnan(r.f0)) {
    fmt::format_to(out, "\n  stability not assessed (see the notes)");
  } else {
    fmt::format_to(out, "\n  f0 = {:.2f} Hz ({})", r.f0,
                   r.f0_from_spectrum ? "peak of the sum-Y spectrum" : "given");
  }
  fmt::format_to(out, ", Nadal mu = {:g}{}\n", r.mu, r.twist_test ? ", twist test" : "");
  // One line per quantity and item: its worst section, or every row.
  std::vector<const AssessmentRow*> shown;
  const auto score = [](const AssessmentRow& x) {
    return std::isnan(x.limit) || x.limit <= 0.0 ? x.value : x.value / x.limit;
  };
  for (const auto& row : r.rows) {
    if (all_rows) {
      shown.push_back(&row);
      continue;
    }
    auto it = std::find_if(shown.begin(), shown.end(), [&](const AssessmentRow* s) {
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
  const auto rank = [&](const AssessmentRow* x) {
    return std::find(groups.begin(), groups.end(), x->group) - groups.begin();
  };
  std::stable_sort(shown.begin(), shown.end(),
                   [&](const auto* lhs, const auto* rhs) { return rank(lhs) < rank(rhs); });
  const auto value_text = [](double v, const std::string& unit) {
    if (std::isnan(v)) return std::string("-");
    if (unit == "N") return fmt::format("{:.2f} kN", v / 1e3);
    return fmt::format("{:.3f}", v);
  };
  const auto verdict_text = [](const AssessmentRow& x) -> std::string {
    if (x.verdict != Verdict::info || std::isnan(x.limit)) return to_string(x.verdict);
    return x.value > x.limit ? "info: above" : "info: below";
  };
  std::string group;
  for (const auto* row : shown) {
    if (row->group != group) {
      group = row->group;
      fmt::format_to(out, "  {}\n  {:<44} {:<34} {:>12} {:>12} {:>10}  {:<22} {}\n", group,
                     "quantity", "item", "value", "limit", "at [m]", "section", "verdict");
    }
    fmt::format_to(out, "  {:<44} {:<34} {:>12} {:>12} {:>10}  {:<22} {}\n", row->quantity,
                   row->item, value_text(row->value, row->unit), value_text(row->limit, row->unit),
                   std::isnan(row->position) ? std::string("-")
                                             : fmt::format("{:.1f}", row->position),
                   row->section, verdict_text(*row));
  }
  for (const auto& n : r.notes) fmt::format_to(out, "  note: {}\n", n);
  if (r.accelerations_derived)
    fmt::format_to(out,
                   "  note: floor and bogie-frame accelerations derived from the bodies' rigid "
                   "motion (the run has no acceleration sensors)\n");
  fmt::format_to(out, "  verdict   {}\n", r.pass ? "pass" : "FAIL");
  return text;
}

std::string ramp_report(const RampStudy& study, const RampRequest& request) {
  std::string text;
  auto out = std::back_inserter(text);
  const Scene& scene = study.scene;
  const auto& o = study.options;
  const auto& r = study.result;
  const auto& names = study.observed;
  const auto name = [&names](std::size_t i) {
    return i < names.size() ? names[i] : std::string("?");
  };
  fmt::format_to(out, "ferrodyn critical-speed ramp: {} ({}), K11 = {}, K22 = {}\n", scene.name,
                 scene.path, request.k11, request.k22);
  fmt::format_to(
      out, "  ramp      {:.3f} -> {:.3f} m/s at -{} m/s^2, pieces of {} s, {} + {} m at start\n",
      o.speed_initial, o.speed_final, o.deceleration, o.hold, name(0), request.disturbance);
  if (!r.completed) fmt::format_to(out, "  stopped   {}\n", r.message);
  if (r.decay_speed) {
    fmt::format_to(out,
                   "  decay     every wheelset's envelope below {} m for good at t = {:.3f} s: V = "
                   "{:.3f} m/s = {:.2f} km/h (the last to die out: {})\n",
                   o.threshold, r.decay_time, *r.decay_speed, *r.decay_speed * 3.6,
                   name(r.holder));
  } else {
    fmt::format_to(out, "  decay     none: the vehicle's envelope {} below {} m over the whole ramp{}\n",
                   r.envelope.empty() || r.envelope.back() >= o.threshold ? "never stays" : "stays",
                   o.threshold,
                   r.completed && !r.envelope.empty() && r.envelope.back() >= o.threshold
                       ? fmt::format(" (largest at the end: {})", name(r.holder))
                       : std::string());
  }
  return text;
}

std::string branch_heading(const Scene& scene, const BranchRequest& request) {
  return fmt::format("ferrodyn critical-speed bifurcation: {} ({}), K11 = {}, K22 = {}\n",
                     scene.name, scene.path, request.settle.k11, request.settle.k22);
}

std::string branch_report(const KijRow& row, const std::vector<std::string>& names) {
  std::string text;
  auto out = std::back_inserter(text);
  const auto name = [&names](std::size_t i) {
    return i < names.size() ? names[i] : std::string("?");
  };
  fmt::format_to(out, "  {:>10} {:>10} {:>9} {:>5} {:>12}", "V [m/s]", "V [km/h]", "outcome",
                 "bis.", "held by");
  for (const auto& n : names) fmt::format_to(out, " {:>14}", n + " [mm]");
  fmt::format_to(out, "\n");
  for (const auto& p : row.branch.points) {
    fmt::format_to(out, "  {:>10.4f} {:>10.3f} {:>9} {:>5} {:>12}", p.speed, p.speed * 3.6,
                   to_string(p.run.outcome), p.bisection ? "yes" : "",
                   sustained(p.run.outcome) ? name(p.run.holder) : std::string());
    for (double amp : p.run.amplitude) fmt::format_to(out, " {:>14.4f}", amp * 1e3);
    fmt::format_to(out, "\n");
  }
  const auto& b = row.branch;
  if (b.fold_found) {
    const double a_fold = [&] {
      for (const auto& p : b.points)
        if (p.speed == *b.lowest_sustained && sustained(p.run.outcome))
          return p.run.amplitude[p.run.holder];
      return std::numeric_limits<double>::quiet_NaN();
    }();
    fmt::format_to(
        out,
        "  nonlinear critical speed (lowest speed where any wheelset keeps a limit cycle): "
        "{:.4f} m/s = {:.2f} km/h, fold in [{:.4f}, {:.4f}] m/s, cycle held by {} ({:.3f} mm)\n",
        *b.lowest_sustained, *b.lowest_sustained * 3.6, b.bracket_low, b.bracket_high,
        name(b.holder), a_fold * 1e3);
    // The A^2 line to zero is a result only where its assumption holds: a supercritical onset,
    // the amplitude growing from zero at the fold.
    if (b.supercritical) {
      fmt::format_to(
          out,
          "  onset     supercritical: amplitude^2 of the lowest cycles falls linearly to zero at "
          "{:.4f} m/s, inside the fold bracket\n",
          b.amplitude_squared_zero);
    } else {
      fmt::format_to(out,
                     "  onset     subcritical: the amplitude jumps from 0 to {:.3f} mm at the "
                     "fold\n",
                     a_fold * 1e3);
    }
  } else if (b.lowest_sustained) {
    fmt::format_to(out,
                   "  sustained down to the lowest speed followed ({:.4f} m/s, held by {}): the "
                   "fold lies below\n",
                   *b.lowest_sustained, name(b.holder));
  } else {
    fmt::format_to(
        out, "  no sustained oscillation at the start speed {:.4f} m/s: the fold lies above\n",
        b.bracket_high);
  }
  if (row.hopf_speed) {
    const std::string relation = linear_against_nonlinear(b, *row.hopf_speed);
    fmt::format_to(out, "  linear (Hopf) critical speed: {:.4f} m/s = {:.2f} km/h{}{}\n",
                   *row.hopf_speed, *row.hopf_speed * 3.6, relation.empty() ? "" : ": ",
                   relation);
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
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!rows[i].hopf_speed) continue;
    const std::string relation = linear_against_nonlinear(rows[i].branch, *rows[i].hopf_speed);
    if (!relation.empty())
      fmt::format_to(out, "  K = ({:.2f}, {:.2f}): Hopf speed {}\n", rows[i].k.k11,
                     rows[i].k.k22, relation.substr(0, relation.find(" (")));
  }
  return text;
}

std::string sweep_report(const Scene& scene, const SweepRequest& a, const SweepOutcome& r,
                         int ranks) {
  std::string text;
  auto out = std::back_inserter(text);
  const auto& names = r.wheelset_names;
  fmt::format_to(out, "ferrodyn sweep: {} ({}), {} points, {} rank(s) x {} thread(s)\n", scene.name,
                 scene.path, r.total, ranks, a.jobs);
  fmt::format_to(out, "  {:>10} {:>6} {:>6} {:>9} {:>12}", "V [m/s]", "K11", "K22", "outcome",
                 "held by");
  for (const auto& n : names) fmt::format_to(out, " {:>14}", n + " [mm]");
  fmt::format_to(out, " {:>9}\n", "cpu [s]");
  for (const auto& p : r.results) {
    fmt::format_to(out, "  {:>10.4f} {:>6.3f} {:>6.3f} {:>9} {:>12}", p.point.speed,
                   p.point.k.k11, p.point.k.k22, to_string(p.outcome),
                   sustained(p.outcome) && p.holder < names.size() ? names[p.holder]
                                                                    : std::string());
    for (std::size_t j = 0; j < names.size(); ++j)
      fmt::format_to(out, " {:>14.5f}", j < p.amplitude.size() ? p.amplitude[j] * 1e3 : NAN);
    fmt::format_to(out, " {:>9.3f}\n", p.cpu_seconds);
  }
  fmt::format_to(out, "  wall      {:.2f} s this invocation; CPU {:.2f} s over all points\n",
                 r.wall_seconds, r.cpu_seconds);
  return text;
}

}  // namespace ferro::scenarios::analysis
