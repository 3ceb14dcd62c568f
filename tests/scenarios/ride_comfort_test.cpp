// EN 12299's N_MV and Sperling's Wz on synthetic floor accelerations against values computed by
// hand from the weighting functions' gains: sinusoids, and a band-limited noise of known rms (a
// sum of sinusoids with random phases on the 0.2 Hz grid, so every 5 s block holds the same
// mean square). Tolerance 1 % (the requirement); the Welch PSD's Parseval sum exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ferro/scenarios/analysis/ride_comfort.hpp"

namespace ferro::scenarios::analysis {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kOnePercent = 0.01;

// |Wd| and |Wb| by the ISO 8041 formulas (gain only), written out independently of the code.
double gain_wd(double f) {
  const std::complex<double> s(0.0, kTwoPi * f);
  const double w1 = kTwoPi * 0.4, w2 = kTwoPi * 100.0, w34 = kTwoPi * 2.0, q = 1.0 / std::sqrt(2.0);
  return std::abs(s * s / (s * s + w1 / q * s + w1 * w1) * (w2 * w2) /
                  (s * s + w2 / q * s + w2 * w2) * (1.0 + s / w34) /
                  (1.0 + s / (0.63 * w34) + s * s / (w34 * w34)));
}
double gain_wb(double f) {
  const std::complex<double> s(0.0, kTwoPi * f);
  const double w1 = kTwoPi * 0.4, w2 = kTwoPi * 100.0, w34 = kTwoPi * 16.0, q = 1.0 / std::sqrt(2.0);
  const double w5 = kTwoPi * 2.5, w6 = kTwoPi * 4.0;
  return std::abs(s * s / (s * s + w1 / q * s + w1 * w1) * (w2 * w2) /
                  (s * s + w2 / q * s + w2 * w2) * (1.0 + s / w34) /
                  (1.0 + s / (0.55 * w34) + s * s / (w34 * w34)) * 1.024 *
                  (s * s + w5 / 0.9 * s + w5 * w5) / (s * s + w6 / 0.95 * s + w6 * w6));
}
// Sperling's B_z by its formula.
double bz(double f) {
  return 0.588 * std::sqrt((1.911 * f * f + std::pow(0.25 * f * f, 2)) /
                           (std::pow(1.0 - 0.2777 * f * f, 2) +
                            std::pow(1.563 * f - 0.0368 * f * f * f, 2)));
}

struct Tone {
  double f, amplitude, phase;
};

std::vector<double> synth(const std::vector<Tone>& tones, double fs, std::size_t n) {
  std::vector<double> x(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / fs;
    for (const auto& k : tones) x[i] += k.amplitude * std::sin(kTwoPi * k.f * t + k.phase);
  }
  return x;
}

// Band-limited noise: tones every 0.2 Hz in [f_lo, f_hi] with random phases, rms `rms`.
std::vector<Tone> noise(double f_lo, double f_hi, double rms, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> phase(0.0, kTwoPi);
  std::vector<Tone> t;
  for (double f = f_lo; f <= f_hi + 1e-9; f += 0.2) t.push_back({f, 0.0, phase(gen)});
  const double a = rms * std::sqrt(2.0 / static_cast<double>(t.size()));
  for (auto& k : t) k.amplitude = a;
  return t;
}

// Weighted rms of tones by hand: sqrt(sum |W(f)|^2 A^2 / 2).
template <class G>
double weighted_rms(const std::vector<Tone>& tones, G gain) {
  double s = 0.0;
  for (const auto& k : tones) s += std::pow(gain(k.f) * k.amplitude, 2) / 2.0;
  return std::sqrt(s);
}

constexpr double kFs = 200.0;
const std::size_t kFiveMinutes = static_cast<std::size_t>(300.0 * kFs);

TEST(ComfortIndex, SinusoidsGiveNmvFromTheWeightingGains) {
  // x: 0.6 m/s^2 at 1 Hz, y: 0.4 m/s^2 at 3.2 Hz, z: 0.5 m/s^2 at 6 Hz (whole periods per
  // 5 s block).
  const std::vector<Tone> tx{{1.0, 0.6, 0.3}}, ty{{3.2, 0.4, 1.0}}, tz{{6.0, 0.5, 2.0}};
  const auto c = comfort_index(synth(tx, kFs, kFiveMinutes), synth(ty, kFs, kFiveMinutes),
                               synth(tz, kFs, kFiveMinutes), kFs);
  const double ax = weighted_rms(tx, gain_wd), ay = weighted_rms(ty, gain_wd),
               az = weighted_rms(tz, gain_wb);
  const double expect = 6.0 * std::sqrt(ax * ax + ay * ay + az * az);
  ASSERT_EQ(c.block_rms_x.size(), 60u);
  EXPECT_FALSE(c.short_record);
  EXPECT_NEAR(c.a_x95, ax, kOnePercent * ax);
  EXPECT_NEAR(c.a_y95, ay, kOnePercent * ay);
  EXPECT_NEAR(c.a_z95, az, kOnePercent * az);
  EXPECT_NEAR(c.n_mv, expect, kOnePercent * expect);
  std::printf("N_MV sinusoids: %.5f (by hand %.5f)\n", c.n_mv, expect);
}

TEST(ComfortIndex, BandLimitedNoiseOfKnownRms) {
  const auto tx = noise(0.6, 8.0, 0.2, 1), ty = noise(0.6, 8.0, 0.3, 2), tz = noise(1.0, 15.0, 0.4, 3);
  const auto c = comfort_index(synth(tx, kFs, kFiveMinutes), synth(ty, kFs, kFiveMinutes),
                               synth(tz, kFs, kFiveMinutes), kFs);
  const double ax = weighted_rms(tx, gain_wd), ay = weighted_rms(ty, gain_wd),
               az = weighted_rms(tz, gain_wb);
  const double expect = 6.0 * std::sqrt(ax * ax + ay * ay + az * az);
  EXPECT_NEAR(c.n_mv, expect, kOnePercent * expect);
  std::printf("N_MV noise: %.5f (by hand %.5f)\n", c.n_mv, expect);
}

TEST(SperlingIndex, SinusoidAndNoiseFromTheWeightingGains) {
  // Sinusoid of rms a: Wz = (100 sqrt(2) B(f) a)^0.3.
  for (const Tone& t : {Tone{1.0, 0.5, 0.0}, Tone{4.0, 0.3, 0.5}, Tone{10.0, 0.8, 1.0}}) {
    const auto x = synth({t}, kFs, static_cast<std::size_t>(60.0 * kFs));
    for (bool lateral : {false, true}) {
      const double b = (lateral ? 1.25 : 1.0) * bz(t.f);
      const double expect = std::pow(100.0 * std::sqrt(2.0) * b * t.amplitude / std::sqrt(2.0), 0.3);
      EXPECT_NEAR(sperling_index(x, kFs, lateral), expect, kOnePercent * expect) << t.f;
    }
  }
  // Noise: Wz = (2 sum (100 B)^2 A^2/2)^0.15 over its tones (all inside 0.5-30 Hz).
  const auto tones = noise(1.0, 20.0, 0.3, 4);
  double s = 0.0;
  for (const auto& k : tones) s += std::pow(100.0 * bz(k.f) * k.amplitude, 2) / 2.0;
  const double expect = std::pow(2.0 * s, 0.15);
  const double wz = sperling_index(synth(tones, kFs, static_cast<std::size_t>(60.0 * kFs)), kFs, false);
  EXPECT_NEAR(wz, expect, kOnePercent * expect);
  std::printf("Wz noise: %.5f (by hand %.5f)\n", wz, expect);
}

TEST(WelchPsd, ParsevalAndPeak) {
  // A sinusoid of amplitude 2 at 5 Hz: the density integrates to its mean square 2 (the Hann
  // segments' leakage stays inside the spectrum) and peaks at 5 Hz.
  const auto x = synth({{5.0, 2.0, 0.0}}, kFs, static_cast<std::size_t>(40.0 * kFs));
  const auto s = welch_psd(x, kFs, static_cast<std::size_t>(5.0 * kFs));
  double sum = 0.0;
  for (double d : s.density) sum += d * s.df;
  EXPECT_NEAR(sum, 2.0, 1e-3 * 2.0);
  EXPECT_NEAR(dominant_frequency(s, 1.0, 20.0), 5.0, 1e-12);
  EXPECT_NEAR(s.df, 0.2, 1e-12);
}

}  // namespace
}  // namespace ferro::scenarios::analysis
