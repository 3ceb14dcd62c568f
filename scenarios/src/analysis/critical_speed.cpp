// Ramping and periodic-branch critical speeds (see the header).
#include "ferro/scenarios/analysis/critical_speed.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

namespace ferro::scenarios::analysis {

namespace {

/// Half the peak-to-peak of `signal` over the trailing `window` of `time` at each sample
/// (monotone deques for the running minimum and maximum).
std::vector<double> trailing_envelope(const std::vector<double>& time,
                                      const std::vector<double>& signal, double window) {
  const std::size_t n = time.size();
  std::vector<double> envelope(n, 0.0);
  std::deque<std::size_t> qmax, qmin;
  std::size_t start = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (!qmax.empty() && signal[qmax.back()] <= signal[i]) qmax.pop_back();
    while (!qmin.empty() && signal[qmin.back()] >= signal[i]) qmin.pop_back();
    qmax.push_back(i);
    qmin.push_back(i);
    while (time[i] - time[start] > window) ++start;
    while (qmax.front() < start) qmax.pop_front();
    while (qmin.front() < start) qmin.pop_front();
    envelope[i] = 0.5 * (signal[qmax.front()] - signal[qmin.front()]);
  }
  return envelope;
}

}  // namespace

RampResult ramp_down(const vehicle::SystemAtSpeed& factory, std::span<const double> x0,
                     const RampOptions& o) {
  if (!(o.speed_initial > o.speed_final && o.speed_final >= 0.0 && o.deceleration > 0.0 &&
        o.hold > 0.0 && o.output_interval > 0.0 && o.envelope_window > 0.0 && o.threshold > 0.0 &&
        o.max_amplitude > o.threshold))
    throw std::invalid_argument(
        "ramp: need speed_initial > speed_final >= 0, deceleration > 0, hold > 0, "
        "output_interval > 0, envelope_window > 0, max_amplitude > threshold > 0");
  RampResult r;
  std::vector<double> x(x0.begin(), x0.end());
  if (o.observed.empty()) throw std::invalid_argument("ramp: no observed state");
  for (auto i : o.observed)
    if (i >= x.size()) throw std::invalid_argument("ramp: observed state out of range");
  const std::size_t m = o.observed.size();
  r.signals.assign(m, {});
  auto integrator = vehicle::make_integrator(o.solver);
  const double t_end = (o.speed_initial - o.speed_final) / o.deceleration;
  for (double t0 = 0.0; t0 < t_end - 1e-12; t0 += o.hold) {
    const double t1 = std::min(t0 + o.hold, t_end);
    const double v = o.speed_initial - o.deceleration * 0.5 * (t0 + t1);
    const auto system = factory(v);
    const auto grid = vehicle::output_grid(t0, t1, o.output_interval);
    const bool first = r.time.empty();
    std::size_t diverged = m;  // the observed state that left the bounds, m: none
    const auto observer = [&](double t, std::span<const double> xs) {
      if (!first && t == t0) return true;  // the piece's start is the previous piece's end
      r.time.push_back(t);
      r.speed.push_back(o.speed_initial - o.deceleration * t);
      for (std::size_t j = 0; j < m; ++j) {
        const double value = xs[o.observed[j]];
        r.signals[j].push_back(value);
        if (!(std::abs(value) <= o.max_amplitude) && diverged == m) diverged = j;
      }
      return diverged == m;
    };
    const auto res = integrator->integrate(*system, x, grid, observer);
    x = res.state;
    if (diverged < m) {
      r.completed = false;
      r.holder = diverged;
      r.message = fmt::format(
          "diverged: observed state {} above {} at t = {:.6g} s (V = {:.4g} m/s); start slower "
          "or use a model with flange contact",
          diverged + 1, o.max_amplitude, res.t_reached,
          o.speed_initial - o.deceleration * res.t_reached);
      break;
    }
    if (res.status != vehicle::IntegrationResult::Status::kCompleted) {
      r.completed = false;
      r.message = fmt::format("solver stopped at t = {:.6g} s (V = {:.4g} m/s): {}",
                              res.t_reached, o.speed_initial - o.deceleration * res.t_reached,
                              res.message);
      break;
    }
  }
  // Envelopes: each observed state's, and the system's (their largest).
  const std::size_t n = r.time.size();
  r.envelope.assign(n, 0.0);
  for (std::size_t j = 0; j < m; ++j) {
    r.envelopes.push_back(trailing_envelope(r.time, r.signals[j], o.envelope_window));
    for (std::size_t i = 0; i < n; ++i) r.envelope[i] = std::max(r.envelope[i], r.envelopes[j][i]);
  }
  if (n > 0) {
    const auto peak = std::max_element(r.envelope.begin(), r.envelope.end()) - r.envelope.begin();
    // A trailing maximum first reaches its largest value when the signal does: no lag.
    r.peak_speed = r.completed ? r.speed[static_cast<std::size_t>(peak)] : NAN;
    std::size_t first_full = 0;
    while (first_full + 1 < n && r.time[first_full] - r.time[0] < o.envelope_window) ++first_full;
    r.envelope_growth =
        r.envelope[first_full] > 0.0
            ? std::max(1.0, r.envelope[static_cast<std::size_t>(peak)] / r.envelope[first_full])
            : NAN;
  }
  // The decay point: the last time the system's envelope was above the threshold. Only
  // meaningful once a full window has passed.
  std::optional<std::size_t> last_above;
  for (std::size_t i = 0; i < n; ++i)
    if (r.envelope[i] >= o.threshold) last_above = i;
  const auto largest_at = [&](std::size_t i) {
    std::size_t h = 0;
    for (std::size_t j = 1; j < m; ++j)
      if (r.envelopes[j][i] > r.envelopes[h][i]) h = j;
    return h;
  };
  if (r.completed && n > 0) r.holder = largest_at(last_above.value_or(n - 1));
  if (last_above && *last_above + 1 < n && r.completed) {
    r.decay_time = r.time[*last_above + 1];
    r.decay_speed = r.speed[*last_above + 1];
  }
  return r;
}

BranchResult follow_periodic_branch(const vehicle::SystemAtSpeed& factory,
                                    std::span<const double> x_disturbed, const BranchOptions& o) {
  if (!(o.speed_start > o.speed_stop && o.speed_stop > 0.0 && o.speed_step > 0.0 &&
        o.bracket > 0.0))
    throw std::invalid_argument(
        "branch: need speed_start > speed_stop > 0, speed_step > 0 and bracket > 0");
  BranchResult out;
  const auto run = [&](double v, std::span<const double> x, bool bisection) {
    const auto system = factory(v);
    out.points.push_back({v, run_until_settled(*system, x, o.settle), bisection});
    if (o.on_point) o.on_point(out.points.back());
    return out.points.back().run;
  };
  // The state a lower speed starts from: a settled (or approached) cycle's final state; after a
  // growing or diverged run, the state that run started from (a blown-up state is no cycle).
  const auto next_start = [](const SettleResult& r, const std::vector<double>& started) {
    return r.outcome == Oscillation::kSteady || r.outcome == Oscillation::kApproaching
               ? r.final_state
               : started;
  };
  std::vector<double> start(x_disturbed.begin(), x_disturbed.end());
  auto r = run(o.speed_start, start, false);
  if (!sustained(r.outcome)) {
    out.bracket_high = o.speed_start;
    out.bracket_low = NAN;
    return out;
  }
  double upper = o.speed_start;
  std::vector<double> x_upper = next_start(r, start);
  double lower = NAN;
  for (double v = o.speed_start - o.speed_step; v >= o.speed_stop - 1e-9; v -= o.speed_step) {
    r = run(v, x_upper, false);
    if (!sustained(r.outcome)) {
      lower = v;
      break;
    }
    x_upper = next_start(r, x_upper);
    upper = v;
  }
  const auto holder_at = [&out](double v) {
    for (const auto& p : out.points)
      if (p.speed == v && sustained(p.run.outcome)) return p.run.holder;
    return std::size_t{0};
  };
  if (std::isnan(lower)) {
    out.lowest_sustained = upper;
    out.bracket_high = upper;
    out.holder = holder_at(upper);
    return out;
  }
  while (upper - lower > o.bracket) {
    const double mid = 0.5 * (upper + lower);
    r = run(mid, x_upper, true);
    if (sustained(r.outcome)) {
      upper = mid;
      x_upper = next_start(r, x_upper);
    } else {
      lower = mid;
    }
  }
  out.fold_found = true;
  out.lowest_sustained = upper;
  out.bracket_low = lower;
  out.bracket_high = upper;
  out.holder = holder_at(upper);
  // Onset: A^2 against V through the lowest cycles, by least squares (each cycle's amplitude is
  // that of the state holding it, its largest).
  std::vector<std::pair<double, double>> cycles;  // (V, A^2)
  for (const auto& p : out.points) {
    if (p.run.outcome != Oscillation::kSteady && p.run.outcome != Oscillation::kApproaching)
      continue;
    const double a = p.run.amplitude[p.run.holder];
    cycles.emplace_back(p.speed, a * a);
  }
  std::sort(cycles.begin(), cycles.end());
  if (cycles.size() > static_cast<std::size_t>(BranchResult::kOnsetPoints))
    cycles.resize(BranchResult::kOnsetPoints);
  if (cycles.size() >= 2) {
    double mv = 0.0, ma = 0.0;
    for (const auto& [v, a2] : cycles) {
      mv += v / static_cast<double>(cycles.size());
      ma += a2 / static_cast<double>(cycles.size());
    }
    double svv = 0.0, sva = 0.0;
    for (const auto& [v, a2] : cycles) {
      svv += (v - mv) * (v - mv);
      sva += (v - mv) * (a2 - ma);
    }
    if (svv > 0.0 && sva > 0.0) {
      out.amplitude_squared_zero = mv - ma * svv / sva;
      const double width = upper - lower;
      out.supercritical = out.amplitude_squared_zero >= lower - width &&
                          out.amplitude_squared_zero <= upper + width;
    }
  }
  return out;
}

}  // namespace ferro::scenarios::analysis
