// Statistics along the track against closed forms: the sliding mean and rms over windows of
// track length (analytic signals), the percentile (a hand-computed case), section statistics.
#include <gtest/gtest.h>

#include <cmath>

#include "ferro/scenarios/analysis/track_statistics.hpp"

namespace ferro::scenarios::analysis {
namespace {

// Closed forms evaluated in double precision: only rounding separates them.
constexpr double kRoundoff = 1e-12;

std::vector<double> grid(double from, double to, double ds) {
  std::vector<double> s;
  const auto n = static_cast<long>(std::lround((to - from) / ds));
  for (long i = 0; i <= n; ++i) s.push_back(from + ds * static_cast<double>(i));
  return s;
}

TEST(SlidingMean, RampIsExact) {
  const auto s = grid(0.0, 20.0, 0.01);
  std::vector<double> f;
  for (double x : s) f.push_back(3.0 * x - 1.0);
  const auto m = sliding_mean(s, f, 2.0, 0.5);
  ASSERT_EQ(m.position.size(), 37u);  // centres 1, 1.5, ..., 19
  EXPECT_NEAR(m.position.front(), 1.0, kRoundoff);
  EXPECT_NEAR(m.position.back(), 19.0, 1e-9);
  for (std::size_t i = 0; i < m.mean.size(); ++i)
    EXPECT_NEAR(m.mean[i], 3.0 * m.position[i] - 1.0, 1e-9) << m.position[i];
}

TEST(SlidingMean, StepGivesLinearTransition) {
  // Unit step at s = 10 sampled every 1 mm: the window mean is the share of the window past the
  // step, (c + 1 - 10)/2 inside |c - 10| < 1; the interpolated step spreads over one sample.
  const double ds = 1e-3;
  const auto s = grid(0.0, 20.0, ds);
  std::vector<double> f;
  for (double x : s) f.push_back(x >= 10.0 - 1e-12 ? 1.0 : 0.0);
  const auto m = sliding_mean(s, f, 2.0, 0.5);
  const double tol = ds / 2.0;  // the step's interpolation over one sample, over a 2 m window
  for (std::size_t i = 0; i < m.mean.size(); ++i) {
    const double c = m.position[i];
    const double expected = std::clamp((c + 1.0 - 10.0) / 2.0, 0.0, 1.0);
    EXPECT_NEAR(m.mean[i], expected, tol) << c;
  }
}

TEST(SlidingMean, SinusoidWindowAverage) {
  // mean of sin(k s) over [c - w/2, c + w/2] = sin(k c) sin(k w/2) / (k w/2).
  const double k = 2.0 * M_PI / 3.0, w = 2.0, ds = 5e-3;
  const auto s = grid(0.0, 30.0, ds);
  std::vector<double> f;
  for (double x : s) f.push_back(std::sin(k * x));
  const auto m = sliding_mean(s, f, w, 0.5);
  // Trapezoid error of the interpolant: k^2 ds^2 / 12 relative.
  const double tol = k * k * ds * ds / 12.0 + 1e-12;
  for (std::size_t i = 0; i < m.mean.size(); ++i) {
    const double c = m.position[i];
    EXPECT_NEAR(m.mean[i], std::sin(k * c) * std::sin(k * w / 2) / (k * w / 2), tol) << c;
  }
}

TEST(SlidingMean, StandstillSamplesCarryNoLengthAndBadInputThrows) {
  std::vector<double> s = {0.0, 1.0, 1.0, 1.0, 2.0, 3.0};
  std::vector<double> f = {0.0, 1.0, 100.0, 1.0, 2.0, 3.0};  // the spike happens at rest
  // Linear f = s outside the rest: the spike at a repeated position has no length, but the
  // interpolant jumps there; the mean over [0, 2] of the interpolant is still (1/2 + 3/2)/2 = 1.
  const auto m = sliding_mean(s, f, 2.0, 0.5);
  ASSERT_FALSE(m.mean.empty());
  EXPECT_NEAR(m.mean.front(), 1.0, kRoundoff);
  EXPECT_THROW((void)sliding_mean({0.0, 2.0, 1.0}, {0, 0, 0}, 0.5, 0.5), std::invalid_argument);
  EXPECT_THROW((void)sliding_mean({0.0, 1.0}, {0, 0}, 2.0, 0.5), std::invalid_argument);
  EXPECT_THROW((void)sliding_mean({0.0, 1.0}, {0}, 0.5, 0.5), std::invalid_argument);
}

TEST(SlidingRms, SinusoidOverWholePeriodsAndRampExact) {
  // rms of A sin(k s) over a window of whole periods is A / sqrt(2).
  const double k = 2.0 * M_PI / 5.0, a = 3.0;
  const auto s = grid(0.0, 300.0, 1e-3);
  std::vector<double> f;
  for (double x : s) f.push_back(a * std::sin(k * x));
  const auto r = sliding_rms(s, f, 100.0, 10.0);  // 100 m = 20 periods
  ASSERT_EQ(r.position.size(), 21u);
  // Trapezoid-like error of integrating the interpolant's square: k^2 ds^2 / 12 relative.
  const double tol = a * k * k * 1e-6 / 12.0 + 1e-12;
  for (double v : r.mean) EXPECT_NEAR(v, a / std::sqrt(2.0), tol);
  // The square of a linear interpolant is integrated exactly: f = s over [c - 50, c + 50] has
  // mean square c^2 + 50^2 / 3.
  const auto ramp = sliding_rms(s, s, 100.0, 10.0);
  for (std::size_t i = 0; i < ramp.mean.size(); ++i) {
    const double c = ramp.position[i];
    EXPECT_NEAR(ramp.mean[i], std::sqrt(c * c + 2500.0 / 3.0), 1e-9 * c) << c;
  }
}

TEST(Percentile, HandComputedCase) {
  // Sorted: 1 2 3 4 10 (n = 5). Rank h = (n - 1) p: p = 0.9985 -> h = 3.994, between 4 and 10:
  // 4 + 0.994 * 6 = 9.964; p = 0.0015 -> h = 0.006: 1 + 0.006 * 1 = 1.006; p = 0.5 -> 3;
  // p = 0.95 -> h = 3.8: 4 + 0.8 * 6 = 8.8.
  const std::vector<double> v = {4.0, 10.0, 1.0, 3.0, 2.0};
  EXPECT_NEAR(percentile(v, 0.9985), 9.964, kRoundoff);
  EXPECT_NEAR(percentile(v, 0.0015), 1.006, kRoundoff);
  EXPECT_NEAR(percentile(v, 0.5), 3.0, kRoundoff);
  EXPECT_NEAR(percentile(v, 0.95), 8.8, kRoundoff);
  EXPECT_NEAR(percentile(v, 1.0), 10.0, kRoundoff);
  EXPECT_NEAR(percentile(v, 0.0), 1.0, kRoundoff);
  EXPECT_NEAR(percentile({7.0}, 0.3), 7.0, kRoundoff);
  EXPECT_THROW((void)percentile({}, 0.5), std::invalid_argument);
  EXPECT_THROW((void)percentile(v, 1.5), std::invalid_argument);
}

TEST(SectionStatistics, ValuesInsideTheSectionOnly) {
  // 0..99 at positions 0..99; section [10, 20): values 10..19.
  std::vector<double> s, f;
  for (int i = 0; i < 100; ++i) {
    s.push_back(i);
    f.push_back(i % 2 == 0 ? i : -i);
  }
  const TrackSection sec{"a", "curve", 10.0, 20.0, 500.0, 0.1};
  const auto st = section_statistics(s, f, sec);
  EXPECT_EQ(st.samples, 10u);
  EXPECT_NEAR(st.max_abs, 19.0, kRoundoff);
  EXPECT_NEAR(st.max_abs_position, 19.0, kRoundoff);
  // Sorted: -19 -17 -15 -13 -11 10 12 14 16 18; median h = 4.5: (-11 + 10)/2.
  EXPECT_NEAR(st.p_median, -0.5, kRoundoff);
  // 99.85 %: h = 8.9865 between 16 and 18.
  EXPECT_NEAR(st.p_high, 16.0 + 0.9865 * 2.0, 1e-12);
  EXPECT_NEAR(st.extreme(), 19.0 - 0.0135 * 2.0, 1e-12);  // |p_low| = 19 - 0.0135 * 2
  double sq = 0.0;
  for (int i = 10; i < 20; ++i) sq += i * i;
  EXPECT_NEAR(st.rms, std::sqrt(sq / 10.0), kRoundoff);
  const auto none = section_statistics(s, f, {"b", "straight", 200.0, 300.0, 0.0, 0.0});
  EXPECT_EQ(none.samples, 0u);
  EXPECT_TRUE(std::isnan(none.p_high));
}

}  // namespace
}  // namespace ferro::scenarios::analysis
