// Steady amplitude detection and constant-speed runs to a settled oscillation (see header).
#include "ferro/scenarios/analysis/limit_cycle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ferro::scenarios::analysis {

std::string to_string(Oscillation o) {
  switch (o) {
    case Oscillation::kDecayed: return "decayed";
    case Oscillation::kSteady: return "steady";
    case Oscillation::kDiverged: return "diverged";
    case Oscillation::kGrowing: return "growing";
    case Oscillation::kDecaying: return "decaying";
  }
  return "?";
}

bool sustained(Oscillation o) {
  return o == Oscillation::kSteady || o == Oscillation::kDiverged || o == Oscillation::kGrowing;
}

namespace {

std::pair<double, double> min_max(std::span<const double> x, std::size_t from, std::size_t to) {
  const auto [lo, hi] = std::minmax_element(x.begin() + static_cast<long>(from),
                                            x.begin() + static_cast<long>(to));
  return {*lo, *hi};
}

}  // namespace

SteadyAmplitude steady_amplitude(std::span<const double> t, std::span<const double> x,
                                 const AmplitudeOptions& options) {
  if (t.size() != x.size()) throw std::invalid_argument("steady_amplitude: sizes differ");
  if (options.periods < 1) throw std::invalid_argument("steady_amplitude: periods must be >= 1");
  SteadyAmplitude out;
  out.previous = out.period = NAN;
  if (x.size() < 4) return out;
  // Mid-line and hysteresis band from the last half of the series.
  const std::size_t half = x.size() / 2;
  const auto [lo, hi] = min_max(x, half, x.size());
  const double mid = 0.5 * (lo + hi);
  const double band = 0.1 * (hi - lo);
  out.amplitude = 0.5 * (hi - lo);
  out.mean = mid;
  // Up-crossings of the mid-line, each armed by a visit below mid - band (hysteresis against
  // ripples), located by linear interpolation.
  std::vector<std::size_t> up;
  std::vector<double> up_time;
  bool armed = false;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (x[i - 1] < mid - band) armed = true;
    if (armed && x[i - 1] < mid && x[i] >= mid) {
      up.push_back(i);
      up_time.push_back(t[i - 1] + (mid - x[i - 1]) / (x[i] - x[i - 1]) * (t[i] - t[i - 1]));
      armed = false;
    }
  }
  out.crossings = static_cast<int>(up.size());
  const auto n = static_cast<std::size_t>(options.periods);
  if (up.size() < n + 1 || !(hi > lo)) return out;
  const std::size_t last = up.size() - 1;
  const auto [l1, h1] = min_max(x, up[last - n], up[last]);
  out.amplitude = 0.5 * (h1 - l1);
  out.mean = 0.5 * (h1 + l1);
  out.period = (up_time[last] - up_time[last - n]) / static_cast<double>(n);
  if (up.size() >= 2 * n + 1) {
    const auto [l0, h0] = min_max(x, up[last - 2 * n], up[last - n]);
    out.previous = 0.5 * (h0 - l0);
    out.converged = std::abs(out.amplitude - out.previous) <= options.rel_tol * out.amplitude;
  }
  return out;
}

SettleResult run_until_settled(const vehicle::OdeSystem& system, std::span<const double> x0,
                               const SettleOptions& options) {
  if (options.observed.empty() || options.reference >= options.observed.size())
    throw std::invalid_argument("settle: no observed state, or reference out of range");
  for (auto i : options.observed)
    if (i >= system.size())
      throw std::invalid_argument(fmt::format("settle: observed state {} out of range", i));
  if (!(options.segment > 0.0 && options.max_time >= options.segment &&
        options.output_interval > 0.0 && options.zero_amplitude > 0.0 &&
        options.max_amplitude > options.zero_amplitude))
    throw std::invalid_argument(
        "settle: need segment > 0, max_time >= segment, output_interval > 0 and "
        "0 < zero_amplitude < max_amplitude");
  SettleResult r;
  r.final_state.assign(x0.begin(), x0.end());
  const std::size_t m = options.observed.size();
  auto integrator = vehicle::make_integrator(options.solver);
  double previous_segment_amplitude = NAN, last_segment_amplitude = NAN;
  std::vector<double> last_times;
  std::vector<std::vector<double>> last_series;
  for (double t0 = 0.0; t0 < options.max_time - 1e-12; t0 += options.segment) {
    const double t1 = std::min(t0 + options.segment, options.max_time);
    const auto grid = vehicle::output_grid(t0, t1, options.output_interval);
    // The amplitude is measured over this segment and the one before (so a segment needs only
    // N periods); the previous segment's last sample is this one's first.
    std::vector<double> times = std::move(last_times);
    std::vector<std::vector<double>> series = std::move(last_series);
    series.resize(m);
    if (!times.empty()) {
      times.pop_back();
      for (auto& sj : series) sj.pop_back();
    }
    const std::size_t fresh = times.size();
    bool left_bounds = false;
    const auto observer = [&](double t, std::span<const double> x) {
      times.push_back(t);
      for (std::size_t j = 0; j < m; ++j) series[j].push_back(x[options.observed[j]]);
      if (std::abs(x[options.observed[options.reference]]) > options.max_amplitude ||
          !std::isfinite(x[options.observed[options.reference]])) {
        left_bounds = true;
        return false;
      }
      return true;
    };
    const auto res = integrator->integrate(system, r.final_state, grid, observer);
    r.rhs_evaluations += res.rhs_evaluations;
    r.time = res.t_reached;
    r.final_state = res.state;
    if (!left_bounds && res.status == vehicle::IntegrationResult::Status::kSolverFailure &&
        t0 == 0.0) {
      // A failure before the reference state has swung once across zero and back is no
      // oscillation: the start itself cannot be integrated.
      const auto& ref = series[options.reference];
      int sign_changes = 0;
      for (std::size_t i = 1; i < ref.size(); ++i)
        if ((ref[i] > 0.0) != (ref[i - 1] > 0.0)) ++sign_changes;
      if (sign_changes < 2) {
        throw std::runtime_error(fmt::format(
            "the run failed at its start, before one oscillation (t = {:.3g} s: {}); the "
            "initial state cannot be integrated (a disturbance that puts a wheel into the rail?)",
            res.t_reached, res.message));
      }
    }
    if (left_bounds || res.status == vehicle::IntegrationResult::Status::kSolverFailure) {
      r.outcome = Oscillation::kDiverged;
      r.message = left_bounds ? fmt::format("amplitude above {} at t = {:.4g} s",
                                            options.max_amplitude, res.t_reached)
                              : res.message;
      r.amplitude.assign(m, NAN);
      for (std::size_t j = 0; j < m; ++j) {
        double peak = 0.0;
        for (double v : series[j]) peak = std::max(peak, std::abs(v));
        r.amplitude[j] = peak;
      }
      r.period = NAN;
      return r;
    }
    last_times.assign(times.begin() + static_cast<long>(fresh), times.end());
    last_series.assign(m, {});
    for (std::size_t j = 0; j < m; ++j)
      last_series[j].assign(series[j].begin() + static_cast<long>(fresh), series[j].end());
    r.amplitude.assign(m, 0.0);
    SteadyAmplitude ref;
    for (std::size_t j = 0; j < m; ++j) {
      const auto a = steady_amplitude(times, series[j], options.amplitude);
      r.amplitude[j] = a.amplitude;
      if (j == options.reference) ref = a;
    }
    r.period = ref.period;
    previous_segment_amplitude = last_segment_amplitude;
    last_segment_amplitude = ref.amplitude;
    if (ref.amplitude < options.zero_amplitude) {
      r.outcome = Oscillation::kDecayed;
      r.amplitude.assign(m, 0.0);
      return r;
    }
    // Settled: converged within this segment and consistent with the previous one.
    const bool consistent =
        std::isnan(previous_segment_amplitude) ||
        std::abs(ref.amplitude - previous_segment_amplitude) <=
            10.0 * options.amplitude.rel_tol * ref.amplitude;
    if (ref.converged && consistent && t0 > 0.0) {
      r.outcome = Oscillation::kSteady;
      return r;
    }
  }
  const bool growing = !std::isnan(previous_segment_amplitude) &&
                       last_segment_amplitude > previous_segment_amplitude;
  r.outcome = growing ? Oscillation::kGrowing : Oscillation::kDecaying;
  r.message = fmt::format("not settled after {} s", options.max_time);
  return r;
}

}  // namespace ferro::scenarios::analysis
