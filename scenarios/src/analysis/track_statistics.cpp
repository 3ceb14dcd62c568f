// Statistics along the track (see the header for references and known deviations).
#include "ferro/scenarios/analysis/track_statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ferro::scenarios::analysis {

namespace {

// Integral over [lo, hi] of the piecewise-linear interpolant of (s, f), or of its square when
// `squared`, walking the intervals that overlap the window from index `first` on.
double window_integral(const std::vector<double>& s, const std::vector<double>& f, double lo,
                       double hi, std::size_t& first, bool squared) {
  while (first + 1 < s.size() && s[first + 1] <= lo) ++first;
  double sum = 0.0;
  for (std::size_t i = first; i + 1 < s.size() && s[i] < hi; ++i) {
    const double a = s[i], b = s[i + 1];
    if (b <= a) continue;  // vehicle at rest: no length
    const double x0 = std::max(a, lo), x1 = std::min(b, hi);
    if (x1 <= x0) continue;
    const double slope = (f[i + 1] - f[i]) / (b - a);
    const double f0 = f[i] + slope * (x0 - a), f1 = f[i] + slope * (x1 - a);
    // Simpson is exact for the square of a linear function.
    sum += squared ? (x1 - x0) * (f0 * f0 + f0 * f1 + f1 * f1) / 3.0 : 0.5 * (f0 + f1) * (x1 - x0);
  }
  return sum;
}

SlidingMean sliding_window(const std::vector<double>& position, const std::vector<double>& values,
                           double window, double step, bool squared, const char* what) {
  if (position.size() != values.size())
    throw std::invalid_argument(fmt::format("{}: {} positions but {} values", what,
                                            position.size(), values.size()));
  if (!(window > 0.0)) throw std::invalid_argument(fmt::format("{}: window must be > 0 m", what));
  if (!(step > 0.0)) throw std::invalid_argument(fmt::format("{}: step must be > 0 m", what));
  for (std::size_t i = 1; i < position.size(); ++i) {
    if (position[i] < position[i - 1])
      throw std::invalid_argument(
          fmt::format("{}: position decreases at sample {} ({} m after {} m)", what, i,
                      position[i], position[i - 1]));
  }
  if (position.size() < 2 || position.back() - position.front() < window)
    throw std::invalid_argument(fmt::format(
        "{}: the run covers {} m of track, less than the {} m window", what,
        position.empty() ? 0.0 : position.back() - position.front(), window));
  SlidingMean out;
  const double first_centre = position.front() + 0.5 * window;
  const double last_centre = position.back() - 0.5 * window;
  // Tolerance on the last centre: a run ending exactly on a step keeps that point.
  const double slack = 1e-9 * std::max(1.0, std::abs(last_centre));
  std::size_t first = 0;
  for (long k = 0;; ++k) {
    const double c = first_centre + static_cast<double>(k) * step;
    if (c > last_centre + slack) break;
    out.position.push_back(c);
    const double m =
        window_integral(position, values, c - 0.5 * window, c + 0.5 * window, first, squared) /
        window;
    out.mean.push_back(squared ? std::sqrt(std::max(0.0, m)) : m);
  }
  return out;
}

}  // namespace

SlidingMean sliding_mean(const std::vector<double>& position, const std::vector<double>& values,
                         double window, double step) {
  return sliding_window(position, values, window, step, false, "sliding mean");
}

SlidingMean sliding_rms(const std::vector<double>& position, const std::vector<double>& values,
                        double window, double step) {
  return sliding_window(position, values, window, step, true, "sliding rms");
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) throw std::invalid_argument("percentile: no values");
  if (!(p >= 0.0 && p <= 1.0))
    throw std::invalid_argument(fmt::format("percentile: p must lie in [0, 1], got {}", p));
  const double h = static_cast<double>(values.size() - 1) * p;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(lo), values.end());
  const double x_lo = values[lo];
  if (lo + 1 >= values.size()) return x_lo;
  // The next order statistic is the smallest of the values above rank lo.
  const double x_hi = *std::min_element(values.begin() + static_cast<long>(lo) + 1, values.end());
  return x_lo + (h - static_cast<double>(lo)) * (x_hi - x_lo);
}

double SectionStatistics::extreme() const { return std::max(std::abs(p_low), std::abs(p_high)); }

SectionStatistics section_statistics(const std::vector<double>& position,
                                     const std::vector<double>& values,
                                     const TrackSection& section) {
  if (position.size() != values.size())
    throw std::invalid_argument(fmt::format("section statistics: {} positions but {} values",
                                            position.size(), values.size()));
  SectionStatistics st;
  std::vector<double> in;
  for (std::size_t i = 0; i < position.size(); ++i) {
    if (position[i] < section.start || position[i] >= section.end) continue;
    in.push_back(values[i]);
    if (std::abs(values[i]) > st.max_abs || in.size() == 1) {
      st.max_abs = std::abs(values[i]);
      st.max_abs_position = position[i];
    }
    if (values[i] > st.max || in.size() == 1) {
      st.max = values[i];
      st.max_position = position[i];
    }
  }
  st.samples = in.size();
  if (in.empty()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    st.p_low = st.p_median = st.p_high = st.max_abs = st.max_abs_position = st.rms = nan;
    st.max = st.max_position = nan;
    return st;
  }
  double sq = 0.0;
  for (double v : in) sq += v * v;
  st.rms = std::sqrt(sq / static_cast<double>(in.size()));
  st.p_low = percentile(in, kPercentileLow);
  st.p_median = percentile(in, 0.5);
  st.p_high = percentile(in, kPercentileHigh);
  return st;
}

}  // namespace ferro::scenarios::analysis
