#pragma once
// Statistics of signals along the track, as EN 14363 processes them: sliding means and sliding
// rms values over windows of track length, percentiles, and per-section statistics.
//
// References: EN 14363:2016 / UIC 518 processing (sliding mean over 2 m sampled every 0.5 m,
//   sliding rms over 100 m sampled every 10 m, percentiles 0.15 % / 50 % / 99.85 % per section),
//   as tabulated by gensys.se/course/UIC518_tests.html; Hyndman & Fan, "Sample quantiles in
//   statistical packages", The American Statistician 50(4) 1996 (definition 7).
// Known deviations: the standard does not say how a percentile interpolates between samples;
//   definition 7 of Hyndman & Fan (linear between order statistics, numpy's default) is used.
//   Window means integrate the linear interpolant of the samples over the position (exact for
//   piecewise-linear signals); a window mean needs the whole window on the run.

#include <string>
#include <vector>

namespace ferro::scenarios::analysis {

/// A signal averaged over a window sliding along the track.
struct SlidingMean {
  std::vector<double> position;  ///< window centres [m]
  std::vector<double> mean;      ///< window averages [signal unit] (rms for sliding_rms)
};

/// Mean of `values` over windows [s - window/2, s + window/2] of the position, for centres s
/// every `step` from position.front() + window/2 to position.back() - window/2. `position` must
/// be non-decreasing (a vehicle at rest repeats its position: those samples carry no length).
/// Throws std::invalid_argument for mismatched sizes, a decreasing position, non-positive
/// window or step, or a track shorter than the window.
[[nodiscard]] SlidingMean sliding_mean(const std::vector<double>& position,
                                       const std::vector<double>& values, double window = 2.0,
                                       double step = 0.5);

/// Root mean square over the same windows: sqrt(sliding mean of values^2) (the square of the
/// linear interpolant is integrated exactly).
[[nodiscard]] SlidingMean sliding_rms(const std::vector<double>& position,
                                      const std::vector<double>& values, double window = 100.0,
                                      double step = 10.0);

/// p-th quantile (p in [0, 1]) of the values, linear between order statistics: with the
/// values sorted, x[h] at rank h = (n - 1) p, interpolated between floor(h) and floor(h) + 1.
/// Throws std::invalid_argument for no values or p outside [0, 1].
[[nodiscard]] double percentile(std::vector<double> values, double p);

/// A stretch of track the statistics are taken over.
struct TrackSection {
  std::string name;     ///< e.g. "3 curve R 1200" or "window 2"
  std::string kind;     ///< straight | transition | curve | window
  double start = 0.0;   ///< [m]
  double end = 0.0;     ///< [m]
  double radius = 0.0;  ///< signed radius of a curve [m]; 0 for straight track and windows
  double cant = 0.0;    ///< [m]
};

/// Statistics of one signal in one section.
struct SectionStatistics {
  std::size_t samples = 0;      ///< values in the section (0: none, the rest is NaN)
  double p_low = 0.0;           ///< 0.15 % percentile
  double p_median = 0.0;        ///< 50 %
  double p_high = 0.0;          ///< 99.85 %
  double max_abs = 0.0;         ///< largest |value|
  double max_abs_position = 0.0;  ///< where [m]
  double rms = 0.0;             ///< root mean square of the values
  double max = 0.0;             ///< largest value
  double max_position = 0.0;    ///< where [m]
  /// max(|p_low|, |p_high|): the value the standards compare with a symmetric limit.
  [[nodiscard]] double extreme() const;
};

inline constexpr double kPercentileLow = 0.0015;
inline constexpr double kPercentileHigh = 0.9985;

/// Statistics of the values whose position lies in [section.start, section.end).
[[nodiscard]] SectionStatistics section_statistics(const std::vector<double>& position,
                                                   const std::vector<double>& values,
                                                   const TrackSection& section);

}  // namespace ferro::scenarios::analysis
