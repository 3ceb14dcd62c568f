// Steady amplitude detection and constant-speed runs to a settled oscillation (see header).
#include "ferro/scenarios/analysis/limit_cycle.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
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
    case Oscillation::kApproaching:
      return "approaching";
  }
  return "?";
}

bool sustained(Oscillation o) {
  return o == Oscillation::kSteady || o == Oscillation::kDiverged || o == Oscillation::kGrowing ||
         o == Oscillation::kApproaching;
}

namespace {

std::pair<double, double> min_max(std::span<const double> x, std::size_t from, std::size_t to) {
  const auto [lo, hi] = std::minmax_element(x.begin() + static_cast<long>(from),
                                            x.begin() + static_cast<long>(to));
  return {*lo, *hi};
}

/// Extremum of the parabola through (i-1, i, i+1) of x, equally spaced samples.
double parabolic_peak(std::span<const double> x, std::size_t i) {
  if (i == 0 || i + 1 >= x.size()) return x[i];
  const double a = 0.5 * (x[i - 1] + x[i + 1]) - x[i], b = 0.5 * (x[i + 1] - x[i - 1]);
  return a == 0.0 ? x[i] : x[i] - b * b / (4.0 * a);
}

/// Up-crossings of the mid-line, each armed by a visit below mid - band (hysteresis against
/// ripples): the sample index after each crossing and its interpolated time.
void up_crossings(std::span<const double> t, std::span<const double> x, double mid, double band,
                  std::vector<std::size_t>& index, std::vector<double>& time) {
  index.clear();
  time.clear();
  bool armed = false;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (x[i - 1] < mid - band) armed = true;
    if (armed && x[i - 1] < mid && x[i] >= mid) {
      index.push_back(i);
      time.push_back(t[i - 1] + (mid - x[i - 1]) / (x[i] - x[i - 1]) * (t[i] - t[i - 1]));
      armed = false;
    }
  }
}

// Two standard errors: a conclusion holds with ~95 % confidence.
constexpr double kSignificance = 2.0;

/// Where d s/dt = 2 s g(s), g(s) = c[0] + c[1] u + c[2] u^2 with u = s - s_mean, takes s from
/// s_now: the nearest zero of g in the direction of g's sign; 0 (rest) or +inf.
double destination_of(const std::array<double, 3>& c, double s_mean, double s_now) {
  const auto g = [&](double s) {
    const double u = s - s_mean;
    return c[0] + c[1] * u + c[2] * u * u;
  };
  const double g_now = g(s_now);
  if (g_now == 0.0) return s_now;
  // Zeros of g as roots in u.
  std::vector<double> zeros;
  if (c[2] != 0.0) {
    const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
    if (disc >= 0.0) {
      const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
      if (q != 0.0) zeros.push_back(q / c[2] + s_mean);
      if (q != 0.0) zeros.push_back(c[0] / q + s_mean);
    }
  } else if (c[1] != 0.0) {
    zeros.push_back(-c[0] / c[1] + s_mean);
  }
  if (g_now < 0.0) {
    double best = 0.0;
    for (double z : zeros)
      if (z > 0.0 && z < s_now) best = std::max(best, z);
    return best;
  }
  double best = INFINITY;
  for (double z : zeros)
    if (z > s_now) best = std::min(best, z);
  return best;
}

}  // namespace

bool AmplitudeEquation::valid() const {
  return periods >= kMinPeriods && std::isfinite(sigma) && std::isfinite(beta) &&
         std::isfinite(sigma_error) && !std::isnan(destination);
}

double AmplitudeEquation::cycle_amplitude() const {
  return valid() && conclusive && destination > 0.0 && std::isfinite(destination) ? destination
                                                                                  : NAN;
}

bool AmplitudeEquation::sustained() const {
  return valid() && conclusive && destination > 0.0;
}

AmplitudeEquation fit_amplitude_equation(std::span<const double> t, std::span<const double> x) {
  if (t.size() != x.size()) throw std::invalid_argument("fit_amplitude_equation: sizes differ");
  AmplitudeEquation fit;
  if (x.size() < 8) return fit;
  // Mid-line from the whole series; hysteresis band from its last fifth, where a decaying
  // oscillation is smallest.
  const auto [lo, hi] = min_max(x, 0, x.size());
  const auto [lo5, hi5] = min_max(x, x.size() - x.size() / 5, x.size());
  std::vector<std::size_t> up;
  std::vector<double> up_time;
  up_crossings(t, x, 0.5 * (lo + hi), 0.1 * (hi5 - lo5), up, up_time);
  // Envelope: half the peak-to-peak of each period (peaks refined by parabolas through the
  // samples), at the period's mid-time.
  std::vector<double> amp, tm;
  for (std::size_t k = 0; k + 1 < up.size(); ++k) {
    const auto b = x.begin() + static_cast<long>(up[k]);
    const auto e = x.begin() + static_cast<long>(up[k + 1]);
    const auto imax = static_cast<std::size_t>(std::max_element(b, e) - x.begin());
    const auto imin = static_cast<std::size_t>(std::min_element(b, e) - x.begin());
    const double a = 0.5 * (parabolic_peak(x, imax) - parabolic_peak(x, imin));
    if (!(a > 0.0)) return fit;
    amp.push_back(a);
    tm.push_back(0.5 * (up_time[k] + up_time[k + 1]));
  }
  if (amp.size() < 3) return fit;
  // Log-derivative by central differences at each inner period, against s = A^2.
  std::vector<double> g, s;
  for (std::size_t k = 1; k + 1 < amp.size(); ++k) {
    g.push_back((std::log(amp[k + 1]) - std::log(amp[k - 1])) / (tm[k + 1] - tm[k - 1]));
    s.push_back(amp[k] * amp[k]);
  }
  const auto n = static_cast<Eigen::Index>(g.size());
  fit.periods = static_cast<int>(n);
  fit.amplitude = amp.back();
  if (fit.periods < AmplitudeEquation::kMinPeriods) return fit;
  double s_mean = 0.0;
  for (double v : s) s_mean += v / static_cast<double>(n);
  // Least squares in u = s - s_mean (conditioning), degree 2, or 1 when the curvature is not
  // significant (or there are too few samples for it).
  const auto solve = [&](int degree, Eigen::VectorXd& c, Eigen::MatrixXd& cov) {
    Eigen::MatrixXd X(n, degree + 1);
    Eigen::VectorXd y(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const double u = s[static_cast<std::size_t>(k)] - s_mean;
      for (int j = 0; j <= degree; ++j) X(k, j) = std::pow(u, j);
      y[k] = g[static_cast<std::size_t>(k)];
    }
    const Eigen::MatrixXd XtX = X.transpose() * X;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(XtX);
    if (ldlt.info() != Eigen::Success || !(XtX.determinant() > 0.0)) return false;
    c = ldlt.solve(X.transpose() * y);
    const double dof = static_cast<double>(n - degree - 1);
    if (!(dof > 0.0)) return false;
    const double s2 = (y - X * c).squaredNorm() / dof;
    cov = s2 * ldlt.solve(Eigen::MatrixXd::Identity(degree + 1, degree + 1));
    return c.allFinite() && cov.allFinite();
  };
  Eigen::VectorXd c;
  Eigen::MatrixXd cov;
  int degree = 1;
  if (n >= AmplitudeEquation::kMinPeriods + 1 && solve(2, c, cov) &&
      std::abs(c[2]) > kSignificance * std::sqrt(cov(2, 2))) {
    degree = 2;
  } else if (!solve(1, c, cov)) {
    return fit;
  }
  std::array<double, 3> coef = {c[0], c[1], degree == 2 ? c[2] : 0.0};
  // Landau form about s = 0.
  // d/ds and value of 1, u, u^2 at s = 0 (u = s - s_mean), truncated to the fitted degree.
  const Eigen::Vector3d at_zero_full(1.0, -s_mean, s_mean * s_mean);
  const Eigen::Vector3d slope_at_zero_full(0.0, 1.0, -2.0 * s_mean);
  const Eigen::VectorXd at_zero = at_zero_full.head(degree + 1);
  const Eigen::VectorXd slope_at_zero = slope_at_zero_full.head(degree + 1);
  fit.sigma = at_zero.dot(c);
  fit.sigma_error = std::sqrt(at_zero.dot(cov * at_zero));
  fit.beta = -slope_at_zero.dot(c);
  fit.beta_error = std::sqrt(slope_at_zero.dot(cov * slope_at_zero));
  fit.gamma = -coef[2];
  // Destination from the last amplitude, and whether it stays rest / not rest when the law is
  // shifted and tilted by two standard errors.
  const double s_now = fit.amplitude * fit.amplitude;
  const double d = destination_of(coef, s_mean, s_now);
  fit.destination = std::sqrt(d);
  fit.conclusive = true;
  const double level = kSignificance * std::sqrt(cov(0, 0));
  const double tilt = kSignificance * std::sqrt(cov(1, 1));
  for (const auto& [dl, dt] : {std::pair{level, 0.0}, std::pair{-level, 0.0}, std::pair{0.0, tilt},
                               std::pair{0.0, -tilt}}) {
    const std::array<double, 3> shifted = {coef[0] + dl, coef[1] + dt, coef[2]};
    if ((destination_of(shifted, s_mean, s_now) > 0.0) != (d > 0.0)) fit.conclusive = false;
  }
  return fit;
}

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
  std::vector<std::size_t> up;
  std::vector<double> up_time;
  up_crossings(t, x, mid, band, up, up_time);
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

namespace {

/// An observed state whose amplitude is below this share of the largest one's counts as settled
/// whatever it still does (a decaying transient beside a cycle): 1 % is below the resolution of
/// an amplitude table in mm to two digits at the cycles of interest.
constexpr double kNegligibleShare = 0.01;

/// Order of the outcomes from least to most sustained: a system takes the most sustained of its
/// observed states.
int sustain_rank(Oscillation o) {
  switch (o) {
    case Oscillation::kDecayed: return 0;
    case Oscillation::kDecaying: return 1;
    case Oscillation::kSteady: return 2;
    case Oscillation::kApproaching: return 3;
    case Oscillation::kGrowing: return 4;
    case Oscillation::kDiverged: return 5;
  }
  return 0;
}

/// Throws std::invalid_argument for options run_until_settled cannot work with.
void check_settle_options(const vehicle::OdeSystem& system, const SettleOptions& options) {
  if (options.observed.empty()) throw std::invalid_argument("settle: no observed state");
  for (auto i : options.observed)
    if (i >= system.size())
      throw std::invalid_argument(fmt::format("settle: observed state {} out of range", i));
  if (!(options.segment > 0.0 && options.max_time >= options.segment &&
        options.output_interval > 0.0 && options.zero_amplitude > 0.0 &&
        options.max_amplitude > options.zero_amplitude))
    throw std::invalid_argument(
        "settle: need segment > 0, max_time >= segment, output_interval > 0 and "
        "0 < zero_amplitude < max_amplitude");
}

/// Samples of the observed states: times and, per observed state, its values.
struct ObservedSeries {
  std::vector<double> times;
  std::vector<std::vector<double>> series;
};

/// What the segments so far leave to the next one and to the decision at the time limit.
struct SettleHistory {
  explicit SettleHistory(std::size_t m)
      : previous_segment_amplitude(m, NAN), last_segment_amplitude(m, NAN), last_period(m, NAN) {}
  // Per observed state: its amplitude over the segment before the last, and over the last.
  std::vector<double> previous_segment_amplitude, last_segment_amplitude;
  std::vector<double> last_period;
  ObservedSeries last;    ///< the last segment's own samples
  ObservedSeries window;  ///< last two segments, for the fits
};

/// One segment integrated from r.final_state over [t0, t1], the observed states sampled into
/// `samples` (which holds the previous segment's samples on entry); `left_bounds` is the
/// observed state that left [-max_amplitude, max_amplitude], or m when none did.
vehicle::IntegrationResult integrate_segment(vehicle::Integrator& integrator,
                                             const vehicle::OdeSystem& system,
                                             const SettleOptions& options, double t0, double t1,
                                             SettleResult& r, ObservedSeries& samples,
                                             std::size_t& left_bounds) {
  const std::size_t m = options.observed.size();
  const auto grid = vehicle::output_grid(t0, t1, options.output_interval);
  left_bounds = m;
  const auto observer = [&](double t, std::span<const double> x) {
    samples.times.push_back(t);
    for (std::size_t j = 0; j < m; ++j) samples.series[j].push_back(x[options.observed[j]]);
    for (std::size_t j = 0; j < m; ++j) {
      const double v = x[options.observed[j]];
      if (!(std::abs(v) <= options.max_amplitude)) {
        left_bounds = j;
        return false;
      }
    }
    return true;
  };
  auto res = integrator.integrate(system, r.final_state, grid, observer);
  r.rhs_evaluations += res.rhs_evaluations;
  r.time = res.t_reached;
  r.final_state = res.state;
  return res;
}

/// A failure before any observed state has swung once across zero and back is no oscillation:
/// the start itself cannot be integrated (std::runtime_error).
void throw_if_failed_at_start(const std::vector<std::vector<double>>& series,
                              const vehicle::IntegrationResult& res) {
  int sign_changes = 0;
  for (const auto& s : series) {
    int changes = 0;
    for (std::size_t i = 1; i < s.size(); ++i)
      if ((s[i] > 0.0) != (s[i - 1] > 0.0)) ++changes;
    sign_changes = std::max(sign_changes, changes);
  }
  if (sign_changes < 2) {
    throw std::runtime_error(fmt::format(
        "the run failed at its start, before one oscillation (t = {:.3g} s: {}); the "
        "initial state cannot be integrated (a disturbance that puts a wheel into the rail?)",
        res.t_reached, res.message));
  }
}

/// The outcome of a run that left the amplitude bounds (`left_bounds` < m) or whose solver
/// failed: diverged, with each observed state's peak as its amplitude.
void set_diverged(SettleResult& r, const std::vector<std::vector<double>>& series,
                  std::size_t left_bounds, const vehicle::IntegrationResult& res,
                  const SettleOptions& options) {
  const std::size_t m = series.size();
  const bool out_of_bounds = left_bounds < m;
  r.outcome = Oscillation::kDiverged;
  r.message = out_of_bounds ? fmt::format("observed state {} above {} at t = {:.4g} s",
                                          left_bounds + 1, options.max_amplitude, res.t_reached)
                            : res.message;
  r.amplitude.assign(m, NAN);
  for (std::size_t j = 0; j < m; ++j) {
    double peak = 0.0;
    for (double v : series[j]) peak = std::max(peak, std::abs(v));
    r.amplitude[j] = peak;
  }
  r.holder =
      out_of_bounds
          ? left_bounds
          : static_cast<std::size_t>(std::max_element(r.amplitude.begin(), r.amplitude.end()) -
                                     r.amplitude.begin());
  r.period = NAN;
}

/// Measures the amplitudes of a segment that stayed in bounds (`samples`: it and the one
/// before; its own samples start at `fresh`), keeps them in `history`, and decides whether the
/// run has decayed or settled (true, with r's outcome set) or goes on (false).
bool judge_segment(SettleResult& r, SettleHistory& history, const ObservedSeries& samples,
                   std::size_t fresh, double t0, const SettleOptions& options) {
  const std::size_t m = options.observed.size();
  const auto& times = samples.times;
  const auto& series = samples.series;
  history.window.times = times;
  history.window.series = series;
  history.last.times.assign(times.begin() + static_cast<long>(fresh), times.end());
  history.last.series.assign(m, {});
  for (std::size_t j = 0; j < m; ++j)
    history.last.series[j].assign(series[j].begin() + static_cast<long>(fresh), series[j].end());
  r.amplitude.assign(m, 0.0);
  std::vector<SteadyAmplitude> steady(m);
  for (std::size_t j = 0; j < m; ++j) {
    steady[j] = steady_amplitude(times, series[j], options.amplitude);
    r.amplitude[j] = steady[j].amplitude;
    history.last_period[j] = steady[j].period;
  }
  history.previous_segment_amplitude = history.last_segment_amplitude;
  history.last_segment_amplitude = r.amplitude;
  // The largest oscillation holds the system's.
  r.holder = static_cast<std::size_t>(std::max_element(r.amplitude.begin(), r.amplitude.end()) -
                                      r.amplitude.begin());
  const SteadyAmplitude& held = steady[r.holder];
  r.period = held.period;
  if (held.amplitude < options.zero_amplitude) {
    r.outcome = Oscillation::kDecayed;
    r.amplitude.assign(m, 0.0);
    return true;
  }
  // Settled: converged within this segment and consistent with the previous one.
  const double before = history.previous_segment_amplitude[r.holder];
  const bool consistent =
      std::isnan(before) ||
      std::abs(held.amplitude - before) <= 10.0 * options.amplitude.rel_tol * held.amplitude;
  // The other observed states must have settled too (converged, or negligible beside the
  // holder), so that the amplitude of every one is that of the cycle, not of a transient.
  bool others_settled = true;
  for (std::size_t j = 0; j < m; ++j) {
    const double negligible = std::max(options.zero_amplitude, kNegligibleShare * held.amplitude);
    if (j != r.holder && !steady[j].converged && !(steady[j].amplitude < negligible))
      others_settled = false;
  }
  if (held.converged && consistent && others_settled && t0 > 0.0) {
    r.outcome = Oscillation::kSteady;
    return true;
  }
  return false;
}

/// Where each observed state is heading at the time limit: the amplitude equation fitted to its
/// last two segments (into r.fits) decides, or, when it cannot tell the sign of the growth, the
/// trend; a state at rest or negligible beside the largest does not decide (decayed).
std::vector<Oscillation> headings_at_time_limit(SettleResult& r, const SettleHistory& history,
                                                const SettleOptions& options) {
  const std::size_t m = options.observed.size();
  const auto& last_segment_amplitude = history.last_segment_amplitude;
  r.fits.assign(m, AmplitudeEquation{});
  std::vector<Oscillation> heading(m, Oscillation::kDecaying);
  const double largest =
      *std::max_element(last_segment_amplitude.begin(), last_segment_amplitude.end());
  for (std::size_t j = 0; j < m; ++j) {
    const double a = last_segment_amplitude[j];
    // A state at rest, or negligible beside the largest oscillation (a motion the others force
    // on it), does not decide: its trend is noise on the scale of the vehicle's oscillation.
    if (!(a >= options.zero_amplitude) || a < kNegligibleShare * largest) {
      heading[j] = Oscillation::kDecayed;
      continue;
    }
    AmplitudeEquation& fit = r.fits[j] =
        fit_amplitude_equation(history.window.times, history.window.series[j]);
    if (fit.valid() && fit.conclusive) {
      heading[j] = !std::isnan(fit.cycle_amplitude()) ? Oscillation::kApproaching
                   : fit.sustained()                  ? Oscillation::kGrowing
                                                      : Oscillation::kDecaying;
    } else {
      const double b = history.previous_segment_amplitude[j];
      heading[j] = !std::isnan(b) && a > b ? Oscillation::kGrowing : Oscillation::kDecaying;
    }
  }
  return heading;
}

/// The outcome of a run ended by the time limit: the system takes the most sustained heading of
/// its observed states; among equals, the largest predicted cycle (approaching) or the largest
/// amplitude (otherwise). The message says what decided.
void decide_at_time_limit(SettleResult& r, const SettleHistory& history,
                          const SettleOptions& options) {
  const std::size_t m = options.observed.size();
  r.message = fmt::format("not settled after {} s", options.max_time);
  const std::vector<Oscillation> heading = headings_at_time_limit(r, history, options);
  const auto size_of = [&](std::size_t j) {
    return heading[j] == Oscillation::kApproaching ? r.fits[j].cycle_amplitude()
                                                   : history.last_segment_amplitude[j];
  };
  std::size_t holder = 0;
  for (std::size_t j = 1; j < m; ++j) {
    const int a = sustain_rank(heading[j]), b = sustain_rank(heading[holder]);
    if (a > b || (a == b && size_of(j) > size_of(holder))) holder = j;
  }
  r.holder = holder;
  r.period = history.last_period[holder];
  r.outcome = heading[holder] == Oscillation::kDecayed ? Oscillation::kDecaying : heading[holder];
  r.fit = r.fits[holder];
  const std::string who = m > 1 ? fmt::format("observed state {}: ", holder + 1) : std::string();
  if (r.outcome == Oscillation::kApproaching) {
    const double cycle = r.fit.cycle_amplitude();
    const double scale = cycle / r.amplitude[holder];
    for (double& a : r.amplitude) a *= scale;
    r.message +=
        fmt::format("; {}amplitude equation: cycle of {:.4g} (sigma = {:.3g} +- {:.2g} /s)", who,
                    cycle, r.fit.sigma, r.fit.sigma_error);
  } else if (r.fit.valid() && r.fit.conclusive) {
    r.message +=
        fmt::format("; {}amplitude equation: {} (sigma = {:.3g} +- {:.2g} /s)", who,
                    r.outcome == Oscillation::kGrowing ? "unbounded growth" : "decay to rest",
                    r.fit.sigma, r.fit.sigma_error);
  } else {
    r.message += fmt::format("; {}{} by trend", who,
                             r.outcome == Oscillation::kGrowing ? "growing" : "decaying");
  }
}

}  // namespace

SettleResult run_until_settled(const vehicle::OdeSystem& system, std::span<const double> x0,
                               const SettleOptions& options) {
  check_settle_options(system, options);
  SettleResult r;
  r.final_state.assign(x0.begin(), x0.end());
  const std::size_t m = options.observed.size();
  auto integrator = vehicle::make_integrator(options.solver);
  SettleHistory history(m);
  for (double t0 = 0.0; t0 < options.max_time - 1e-12; t0 += options.segment) {
    const double t1 = std::min(t0 + options.segment, options.max_time);
    // The amplitude is measured over this segment and the one before (so a segment needs only
    // N periods); the previous segment's last sample is this one's first.
    ObservedSeries samples = std::move(history.last);
    samples.series.resize(m);
    if (!samples.times.empty()) {
      samples.times.pop_back();
      for (auto& sj : samples.series) sj.pop_back();
    }
    const std::size_t fresh = samples.times.size();
    std::size_t left_bounds = m;
    const auto res =
        integrate_segment(*integrator, system, options, t0, t1, r, samples, left_bounds);
    const bool out_of_bounds = left_bounds < m;
    const bool failed = res.status == vehicle::IntegrationResult::Status::kSolverFailure;
    if (!out_of_bounds && failed && t0 == 0.0) throw_if_failed_at_start(samples.series, res);
    if (out_of_bounds || failed) {
      set_diverged(r, samples.series, left_bounds, res, options);
      return r;
    }
    if (judge_segment(r, history, samples, fresh, t0, options)) return r;
  }
  decide_at_time_limit(r, history, options);
  return r;
}

}  // namespace ferro::scenarios::analysis
