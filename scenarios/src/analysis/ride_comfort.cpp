// Ride comfort: EN 12299 N_MV, Sperling's Wz, Welch PSD (see the header for references).
#include "ferro/scenarios/analysis/ride_comfort.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <mutex>
#include <stdexcept>

#include "ferro/scenarios/analysis/track_statistics.hpp"

namespace ferro::scenarios::analysis {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;

// The ISO 8041 band limits, a-v transition and (when f5 > 0) upward step.
AnalogFilter iso8041_weighting(double f3, double f4, double q4, double f5, double q5, double f6,
                               double q6, double k) {
  constexpr double f1 = 0.4, f2 = 100.0;
  const double q12 = 1.0 / std::sqrt(2.0);
  const double w1 = kTwoPi * f1, w2 = kTwoPi * f2, w3 = kTwoPi * f3, w4 = kTwoPi * f4;
  AnalogFilter w;
  w.sections.push_back({1.0, 0.0, 0.0, 1.0, w1 / q12, w1 * w1, f1});         // H_h
  w.sections.push_back({0.0, 0.0, w2 * w2, 1.0, w2 / q12, w2 * w2, f2});     // H_l
  w.sections.push_back({0.0, 1.0 / w3, 1.0, 1.0 / (w4 * w4), 1.0 / (q4 * w4), 1.0, f4});  // H_t
  if (f5 > 0.0) {
    const double w5 = kTwoPi * f5, w6 = kTwoPi * f6;
    w.sections.push_back({1.0, w5 / q5, w5 * w5, 1.0, w6 / q6, w6 * w6, f6});  // H_s
  }
  w.gain = k;
  return w;
}

std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

AnalogFilter weighting_wb() { return iso8041_weighting(16.0, 16.0, 0.55, 2.5, 0.9, 4.0, 0.95, 1.024); }

AnalogFilter weighting_wd() { return iso8041_weighting(2.0, 2.0, 0.63, 0.0, 1.0, 0.0, 1.0, 1.0); }

double sperling_weighting(double f, bool lateral) {
  const double f2 = f * f;
  const double num = 1.911 * f2 + std::pow(0.25 * f2, 2);
  const double den = std::pow(1.0 - 0.2777 * f2, 2) + std::pow(1.563 * f - 0.0368 * f2 * f, 2);
  const double bz = 0.588 * std::sqrt(num / den);
  return lateral ? 1.25 * bz : bz;
}

Spectrum welch_psd(std::span<const double> x, double sample_rate, std::size_t segment) {
  if (!(sample_rate > 0.0))
    throw std::invalid_argument(fmt::format("PSD: sample rate must be > 0 Hz, got {}", sample_rate));
  if (x.size() < 2) throw std::invalid_argument("PSD: at least two samples are needed");
  const std::size_t m = std::clamp<std::size_t>(segment, 2, x.size());
  const std::size_t hop = std::max<std::size_t>(1, m / 2);
  std::vector<double> w(m), buf(m);
  double w2 = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    w[i] = 0.5 - 0.5 * std::cos(kTwoPi * static_cast<double>(i) / static_cast<double>(m));
    w2 += w[i] * w[i];
  }
  Spectrum s;
  s.df = sample_rate / static_cast<double>(m);
  const std::size_t bins = m / 2 + 1;
  s.frequency.resize(bins);
  s.density.assign(bins, 0.0);
  for (std::size_t k = 0; k < bins; ++k) s.frequency[k] = s.df * static_cast<double>(k);
  std::vector<std::complex<double>> spec(bins);
  fftw_plan plan;
  {
    std::lock_guard lock(planner_mutex());
    plan = fftw_plan_dft_r2c_1d(static_cast<int>(m), buf.data(),
                                reinterpret_cast<fftw_complex*>(spec.data()), FFTW_ESTIMATE);
  }
  std::size_t segments = 0;
  for (std::size_t start = 0; start + m <= x.size(); start += hop) {
    double mean = 0.0;
    for (std::size_t i = 0; i < m; ++i) mean += x[start + i];
    mean /= static_cast<double>(m);
    for (std::size_t i = 0; i < m; ++i) buf[i] = (x[start + i] - mean) * w[i];
    fftw_execute(plan);
    for (std::size_t k = 0; k < bins; ++k) {
      const bool edge = k == 0 || 2 * k == m;
      s.density[k] += (edge ? 1.0 : 2.0) * std::norm(spec[k]) / (sample_rate * w2);
    }
    ++segments;
  }
  {
    std::lock_guard lock(planner_mutex());
    fftw_destroy_plan(plan);
  }
  for (double& d : s.density) d /= static_cast<double>(segments);
  return s;
}

double dominant_frequency(const Spectrum& s, double f_min, double f_max) {
  double best = -1.0, where = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t k = 0; k < s.frequency.size(); ++k) {
    if (s.frequency[k] < f_min || s.frequency[k] > f_max) continue;
    if (s.density[k] > best) {
      best = s.density[k];
      where = s.frequency[k];
    }
  }
  return where;
}

namespace {

std::vector<double> block_rms(const std::vector<double>& a, std::size_t block) {
  std::vector<double> out;
  if (a.size() < block) block = a.size();
  for (std::size_t start = 0; block > 0 && start + block <= a.size(); start += block) {
    double sq = 0.0;
    for (std::size_t i = start; i < start + block; ++i) sq += a[i] * a[i];
    out.push_back(std::sqrt(sq / static_cast<double>(block)));
  }
  return out;
}

}  // namespace

ComfortIndex comfort_index(std::span<const double> ax, std::span<const double> ay,
                           std::span<const double> az, double sample_rate, double block_seconds) {
  if (ax.size() != ay.size() || ay.size() != az.size())
    throw std::invalid_argument(fmt::format("comfort index: {} / {} / {} samples in x / y / z",
                                            ax.size(), ay.size(), az.size()));
  if (ax.empty()) throw std::invalid_argument("comfort index: no samples");
  // The 0.4 Hz band limit settles within ~6 s (decay 1.78 /s): zero-pad 20 s.
  constexpr double kSettle = 20.0;
  const auto wd = weighting_wd(), wb = weighting_wb();
  const auto block = static_cast<std::size_t>(std::llround(block_seconds * sample_rate));
  ComfortIndex c;
  c.block_rms_x = block_rms(apply_analog(wd, ax, sample_rate, kSettle), block);
  c.block_rms_y = block_rms(apply_analog(wd, ay, sample_rate, kSettle), block);
  c.block_rms_z = block_rms(apply_analog(wb, az, sample_rate, kSettle), block);
  c.a_x95 = percentile(c.block_rms_x, 0.95);
  c.a_y95 = percentile(c.block_rms_y, 0.95);
  c.a_z95 = percentile(c.block_rms_z, 0.95);
  c.n_mv = 6.0 * std::sqrt(c.a_x95 * c.a_x95 + c.a_y95 * c.a_y95 + c.a_z95 * c.a_z95);
  c.short_record = c.block_rms_x.size() < 60;
  return c;
}

double sperling_index(std::span<const double> a, double sample_rate, bool lateral) {
  constexpr double kSegmentSeconds = 5.0, kLow = 0.5, kHigh = 30.0;
  const auto segment = static_cast<std::size_t>(std::llround(kSegmentSeconds * sample_rate));
  const Spectrum s = welch_psd(a, sample_rate, segment);
  double sum = 0.0;
  for (std::size_t k = 0; k < s.frequency.size(); ++k) {
    const double f = s.frequency[k];
    if (f < kLow || f > kHigh) continue;
    const double b = 100.0 * sperling_weighting(f, lateral);
    sum += b * b * s.density[k] * s.df;
  }
  return std::pow(2.0 * sum, 0.15);
}

std::string comfort_class(double n_mv) {
  if (n_mv < 1.0) return "very comfortable";
  if (n_mv < 2.0) return "comfortable";
  if (n_mv < 4.0) return "medium";
  if (n_mv < 5.0) return "uncomfortable";
  return "very uncomfortable";
}

}  // namespace ferro::scenarios::analysis
