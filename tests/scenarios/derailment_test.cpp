// Derailment criteria against closed forms: Nadal's limit (Toumi 2016 eq. 149), the 2 m sliding
// mean of analytic signals, Prud'homme's limit, and the assessment read from a run file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "ferro/scenarios/analysis/derailment.hpp"
#include "ferro/scenarios/h5_output.hpp"

namespace ferro::scenarios::analysis {
namespace {

constexpr double kDeg = M_PI / 180.0;
// Closed forms evaluated in double precision: only rounding separates them.
constexpr double kRoundoff = 1e-12;
// The thesis rounds Nadal's 70 deg, mu 0.36 limit to two digits (1.2).
constexpr double kThesisRounding = 5e-3;

TEST(Nadal, ThesisValue70DegMu036) {
  EXPECT_NEAR(nadal_limit(70.0 * kDeg, 0.36), 1.2, kThesisRounding);
}

TEST(Nadal, ClosedFormMu05) {
  // tan 70 = 2.7474774194546; (2.7474774 - 0.5) / (1 + 0.5 * 2.7474774) = 0.9468091
  EXPECT_NEAR(nadal_limit(70.0 * kDeg, 0.5), 0.946809103396597, kRoundoff);
  // The thesis's derailment case quotes 0.94 at mu = 0.5.
  EXPECT_NEAR(nadal_limit(70.0 * kDeg, 0.5), 0.94, 1e-2);
}

TEST(Nadal, FrictionlessIsTangentAndBadInputThrows) {
  EXPECT_NEAR(nadal_limit(60.0 * kDeg, 0.0), std::sqrt(3.0), kRoundoff);
  EXPECT_THROW((void)nadal_limit(95.0 * kDeg, 0.3), std::invalid_argument);
  EXPECT_THROW((void)nadal_limit(60.0 * kDeg, -0.1), std::invalid_argument);
}

TEST(Prudhomme, ClosedForm) {
  // P = 120 kN: 0.85 (10 + 40) kN = 42.5 kN.
  EXPECT_NEAR(prudhomme_limit(120.0e3), 42.5e3, kRoundoff * 42.5e3);
}

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

TEST(Derailment, AssessmentFromRunFile) {
  // A 100 m run at 10 m/s: wheelset 1 left wheel carries Y = 0.5 Q0 sin^2 bump centred at 60 m
  // (flange contact at 70 deg), the right wheel unloads by 30 % there.
  const double q0 = 60.0e3, v = 10.0, dt = 1e-3;
  std::vector<double> t, pos;
  std::vector<std::vector<double>> sig(6);
  for (long i = 0; i <= 10000; ++i) {
    const double ti = dt * static_cast<double>(i), s = v * ti;
    const double bump = std::abs(s - 60.0) < 5.0 ? std::pow(std::cos(M_PI * (s - 60.0) / 10.0), 2) : 0.0;
    t.push_back(ti);
    pos.push_back(s);
    sig[0].push_back(0.9 * q0 * bump);          // left Y
    sig[1].push_back(q0 * (1.0 + 0.3 * bump));  // left Q
    sig[2].push_back((3.0 + 67.0 * bump) * kDeg);
    sig[3].push_back(-0.1 * q0 * bump);         // right Y
    sig[4].push_back(q0 * (1.0 - 0.3 * bump));  // right Q
    sig[5].push_back(3.0 * kDeg);
  }
  const auto path = (std::filesystem::temp_directory_path() / "ferro_derailment_test.h5").string();
  {
    H5File f = H5File::create(path);
    const std::vector<std::string> names = {
        "position", "wheelset_1.left.Y", "wheelset_1.left.Q", "wheelset_1.left.contact_angle",
        "wheelset_1.right.Y", "wheelset_1.right.Q", "wheelset_1.right.contact_angle"};
    std::vector<vehicle::SignalInfo> ch;
    for (const auto& n : names) ch.push_back({n, "SI", ""});
    TimeSeriesWriter w(f, ch, 10.0);
    std::vector<double> row(names.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
      row[0] = pos[i];
      for (int j = 0; j < 6; ++j) row[static_cast<std::size_t>(j) + 1] = sig[static_cast<std::size_t>(j)][i];
      w.append(t[i], row);
    }
    w.flush();
  }
  DerailmentOptions o;
  o.mu = 0.5;
  const auto r = assess_derailment_file(path, o);
  ASSERT_EQ(r.wheels.size(), 2u);
  ASSERT_EQ(r.axles.size(), 1u);
  const auto& l = r.wheels[0];
  // Peak raw Y/Q = 0.9/1.3 at the bump centre.
  EXPECT_NEAR(l.max_y_over_q_raw, 0.9 / 1.3, 1e-6);
  EXPECT_NEAR(l.max_y_over_q_position, 60.0, 0.25);  // symmetric bump: the centre window
  EXPECT_NEAR(l.flange_angle, 70.0 * kDeg, 1e-9);
  EXPECT_NEAR(l.nadal, nadal_limit(70.0 * kDeg, 0.5), kRoundoff);
  EXPECT_TRUE(l.pass_nadal);  // 0.69 < 0.947
  EXPECT_TRUE(std::isnan(r.wheels[1].nadal));  // tread contact at 3 deg: tan 3 deg < mu
  EXPECT_TRUE(r.wheels[1].pass_nadal);
  EXPECT_NEAR(r.wheels[1].max_unloading, 0.3, 1e-6);
  EXPECT_NEAR(r.wheels[1].max_unloading_position, 60.0, 1e-6);
  // Sum Y = 0.8 Q0 cos^2: the 2 m mean at the centre is 0.8 Q0 (1/2 + sin(pi/5)/(2 pi/5)/... ):
  // mean of cos^2(pi u/10) over |u| < 1 = 1/2 + sin(2 pi/10)/(2 * 2 pi/10).
  const double mean_cos2 = 0.5 + std::sin(M_PI / 5.0) / (2.0 * M_PI / 5.0);
  EXPECT_NEAR(r.axles[0].max_sum_y, 0.8 * q0 * mean_cos2, 1e-5 * q0);
  EXPECT_NEAR(r.axles[0].limit, prudhomme_limit(2.0 * q0), kRoundoff * q0);
  EXPECT_FALSE(r.axles[0].pass);  // 46.8 kN > 0.85 (10 + 40) kN = 42.5 kN
  EXPECT_FALSE(r.pass);
  std::filesystem::remove(path);
}

TEST(Derailment, MissingSignalIsNamed) {
  const auto path = (std::filesystem::temp_directory_path() / "ferro_derailment_bad.h5").string();
  {
    H5File f = H5File::create(path);
    TimeSeriesWriter w(f, {{"position", "m", ""}}, 10.0);
    w.append(0.0, std::vector<double>{0.0});
    w.flush();
  }
  try {
    (void)assess_derailment_file(path, {});
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("wheelset_1.left.Y"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace ferro::scenarios::analysis
