// The assessment's filters against their closed-form transfer functions, gain and phase at ten
// frequencies each: Butterworth low-, high- and band-pass by the bilinear transform with
// prewarping (the digital filter's response is the analog prototype's at the warped frequency
// K tan(pi f / fs), exactly), measured by running the filter over sinusoids; forward-backward
// application (squared gain, zero phase, -3 dB at the nominal corner); the EN 12299 / ISO 8041
// weightings Wb and Wd applied in the frequency domain against the ISO 8041 formulas and
// published values.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "ferro/scenarios/analysis/ride_comfort.hpp"
#include "ferro/scenarios/analysis/signal_filter.hpp"

namespace ferro::scenarios::analysis {
namespace {

using cd = std::complex<double>;
constexpr double kTwoPi = 2.0 * M_PI;

// Closed form of an order-n Butterworth low-pass at analog angular frequency w, corner wc:
// 1 / prod_k (1 - (w/wc)^2 + j (w/wc) 2 sin((2k-1) pi / 2n)) (poles on the circle).
cd butterworth_lp(int n, double w, double wc) {
  const double u = w / wc;
  cd h(1.0, 0.0);
  for (int k = 1; k <= n / 2; ++k)
    h /= cd(1.0 - u * u, 2.0 * std::sin((2.0 * k - 1.0) * M_PI / (2.0 * n)) * u);
  return h;
}
// High-pass: the low-pass at wc^2 / w with the sign of j flipped: prod (-(u^2)) / (...).
cd butterworth_hp(int n, double w, double wc) {
  const double u = w / wc;
  cd h(1.0, 0.0);
  for (int k = 1; k <= n / 2; ++k)
    h *= cd(-u * u, 0.0) / cd(1.0 - u * u, 2.0 * std::sin((2.0 * k - 1.0) * M_PI / (2.0 * n)) * u);
  return h;
}
// The analog frequency the bilinear transform prewarped at fw maps the digital f to [rad/s].
double warped(double f, double fw, double fs) {
  return kTwoPi * fw / std::tan(M_PI * fw / fs) * std::tan(M_PI * f / fs);
}

// Gain and phase of a filter's steady response to a unit sinusoid: least-squares fit of
// a sin + b cos over the last `periods` whole periods of the output.
cd measured_response(const std::vector<double>& y, double f, double fs, std::size_t from,
                     std::size_t to) {
  double ss = 0, sc = 0, cc = 0, ys = 0, yc = 0;
  for (std::size_t i = from; i < to; ++i) {
    const double t = static_cast<double>(i) / fs;
    const double s = std::sin(kTwoPi * f * t), c = std::cos(kTwoPi * f * t);
    ss += s * s, sc += s * c, cc += c * c, ys += y[i] * s, yc += y[i] * c;
  }
  const double det = ss * cc - sc * sc;
  const double a = (ys * cc - yc * sc) / det, b = (yc * ss - ys * sc) / det;
  // y = a sin + b cos = Re{(a - j b)... }: gain sqrt(a^2+b^2), phase atan2(b, a).
  return std::polar(std::hypot(a, b), std::atan2(b, a));
}

std::vector<double> sine(double f, double fs, std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = std::sin(kTwoPi * f * static_cast<double>(i) / fs);
  return x;
}

// Fit error of the least-squares response over a long record: rounding only.
constexpr double kFit = 1e-7;

struct Case {
  double fs;
  std::vector<double> freqs;  // ten frequencies [Hz]
};

TEST(ButterworthFilter, LowPassGainAndPhaseAgainstClosedForm) {
  const int n = 4;
  const double fc = 20.0;
  for (const Case& c : {Case{200.0, {0.5, 2, 5, 10, 15, 20, 25, 35, 50, 80}},
                        Case{5000.0, {0.5, 2, 5, 10, 15, 20, 25, 35, 50, 150}}}) {
    const auto d = bilinear(butterworth_lowpass_analog(n, fc), c.fs);
    for (double f : c.freqs) {
      const cd expect = butterworth_lp(n, warped(f, fc, c.fs), kTwoPi * fc);
      // The design's own response evaluation.
      const cd h = d.response(f);
      EXPECT_NEAR(std::abs(h), std::abs(expect), 1e-12) << c.fs << " Hz, f = " << f;
      EXPECT_NEAR(std::arg(h / expect), 0.0, 1e-10) << f;
      // The filtering code over a sinusoid (settled after 2 s; fit over a whole number of
      // samples far longer than the period).
      const std::size_t len = static_cast<std::size_t>(12.0 * c.fs);
      const auto y = filter(d, sine(f, c.fs, len));
      const cd m = measured_response(y, f, c.fs, len / 3, len);
      EXPECT_NEAR(std::abs(m), std::abs(expect), kFit + 1e-6 * std::abs(expect)) << f;
      if (std::abs(expect) > 1e-6) EXPECT_NEAR(std::arg(m / expect), 0.0, 1e-6) << f;
    }
    // At the corner the prewarped design is exactly -3 dB.
    EXPECT_NEAR(std::abs(d.response(fc)), 1.0 / std::sqrt(2.0), 1e-12);
  }
}

TEST(ButterworthFilter, HighAndBandPassGainAndPhaseAgainstClosedForm) {
  const int n = 4;
  const double fs = 200.0, fl = 0.4, fh = 10.0;
  const auto hp = bilinear(butterworth_highpass_analog(n, fl), fs);
  const auto bp = bilinear(butterworth_bandpass_analog(n, fl, fh), fs);
  for (double f : {0.1, 0.2, 0.4, 0.7, 1.0, 3.0, 7.0, 10.0, 14.0, 40.0}) {
    const cd e_hp = butterworth_hp(n, warped(f, fl, fs), kTwoPi * fl);
    const cd e_bp = e_hp * butterworth_lp(n, warped(f, fh, fs), kTwoPi * fh);
    EXPECT_NEAR(std::abs(hp.response(f)), std::abs(e_hp), 1e-12) << f;
    EXPECT_NEAR(std::arg(hp.response(f) / e_hp), 0.0, 1e-9) << f;
    EXPECT_NEAR(std::abs(bp.response(f)), std::abs(e_bp), 1e-12) << f;
    EXPECT_NEAR(std::arg(bp.response(f) / e_bp), 0.0, 1e-9) << f;
    // Filtering a sinusoid: settle for 60 s (the 0.4 Hz high-pass), fit over the next 60 s.
    const std::size_t len = static_cast<std::size_t>(120.0 * fs);
    const cd m = measured_response(filter(bp, sine(f, fs, len)), f, fs, len / 2, len);
    EXPECT_NEAR(std::abs(m), std::abs(e_bp), kFit + 1e-6 * std::abs(e_bp)) << f;
    if (std::abs(e_bp) > 1e-4) EXPECT_NEAR(std::arg(m / e_bp), 0.0, 1e-5) << f;
  }
}

TEST(ButterworthFilter, ForwardBackwardIsZeroPhaseWithSquaredGain) {
  const int n = 4;
  const double fs = 200.0, fc = 20.0;
  // Corner moved so that the squared gain is 1/sqrt(2) at 20 Hz; prewarped at 20 Hz.
  const double fc1 = zero_phase_lowpass_corner(n, fc);
  EXPECT_NEAR(fc1, fc * std::pow(std::sqrt(2.0) - 1.0, -1.0 / 8.0), 1e-12);
  const auto analog = zero_phase_lowpass(n, fc);
  const auto d = bilinear(analog, fs);
  const std::size_t len = static_cast<std::size_t>(20.0 * fs);
  for (double f : {0.5, 2.0, 5.0, 10.0, 15.0, 18.0, 20.0, 24.0, 30.0, 45.0}) {
    const cd one = butterworth_lp(n, warped(f, fc, fs), kTwoPi * fc1);
    const auto y = filtfilt(d, sine(f, fs, len), edge_padding(analog, fs));
    // Away from the ends (the reflection's transients), gain |H|^2 and no phase.
    const cd m = measured_response(y, f, fs, len / 4, 3 * len / 4);
    EXPECT_NEAR(std::abs(m), std::norm(one), kFit + 1e-6 * std::norm(one)) << f;
    if (std::norm(one) > 1e-6) EXPECT_NEAR(std::arg(m), 0.0, 1e-6) << f;
  }
  // -3 dB at the nominal corner, whatever the sampling rate.
  for (double rate : {50.0, 200.0, 5000.0})
    EXPECT_NEAR(std::norm(bilinear(analog, rate).response(fc)), 1.0 / std::sqrt(2.0), 1e-12);
}

TEST(ButterworthFilter, ZeroPhaseBandPassAgainstClosedForm) {
  const int n = 4;
  const double fs = 1000.0, fl = 0.4, fh = 10.0;
  const double fl1 = zero_phase_highpass_corner(n, fl), fh1 = zero_phase_lowpass_corner(n, fh);
  const auto analog = zero_phase_bandpass(n, fl, fh);
  const auto d = bilinear(analog, fs);
  const std::size_t len = static_cast<std::size_t>(200.0 * fs);
  for (double f : {0.2, 0.4, 0.8, 1.5, 2.0, 4.0, 7.0, 10.0, 13.0, 25.0}) {
    const cd one = butterworth_hp(n, warped(f, fl, fs), kTwoPi * fl1) *
                   butterworth_lp(n, warped(f, fh, fs), kTwoPi * fh1);
    const auto y = filtfilt(d, sine(f, fs, len), edge_padding(analog, fs));
    const cd m = measured_response(y, f, fs, len / 4, 3 * len / 4);
    EXPECT_NEAR(std::abs(m), std::norm(one), kFit + 1e-6 * std::norm(one)) << f;
    if (std::norm(one) > 1e-6) EXPECT_NEAR(std::arg(m), 0.0, 1e-6) << f;
  }
  EXPECT_NEAR(std::norm(d.response(fl)), 1.0 / std::sqrt(2.0), 1e-6);  // the LP's 1e-7 aside
  EXPECT_NEAR(std::norm(d.response(fh)), 1.0 / std::sqrt(2.0), 1e-6);
}

TEST(ButterworthFilter, ConstantPassesAndEdgesStartAtSteadyState) {
  const auto lp = bilinear(butterworth_lowpass_analog(4, 20.0), 1000.0);
  const std::vector<double> c(500, 3.25);
  for (double v : filter(lp, c)) EXPECT_NEAR(v, 3.25, 1e-12);
  for (double v : filtfilt(lp, c, 100)) EXPECT_NEAR(v, 3.25, 1e-12);
  // A ramp passes a low-pass zero-phase filter unchanged (odd reflection keeps it a ramp).
  std::vector<double> r(2000);
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = 0.01 * static_cast<double>(i);
  const auto y = filtfilt(lp, r, 400);
  for (std::size_t i = 0; i < r.size(); ++i) EXPECT_NEAR(y[i], r[i], 1e-9) << i;
  EXPECT_THROW((void)bilinear(butterworth_lowpass_analog(4, 120.0), 200.0), std::invalid_argument);
  EXPECT_THROW((void)butterworth_lowpass_analog(3, 20.0), std::invalid_argument);
}

// ISO 8041 weighting by its formula (HVM200 manual table 3.1), written out here.
cd iso8041(double f, double f3, double f4, double q4, double f5, double q5, double f6, double q6,
           double k) {
  const cd s(0.0, kTwoPi * f);
  const double w1 = kTwoPi * 0.4, w2 = kTwoPi * 100.0, q1 = 1.0 / std::sqrt(2.0);
  const double w3 = kTwoPi * f3, w4 = kTwoPi * f4;
  cd h = s * s / (s * s + w1 / q1 * s + w1 * w1);
  h *= w2 * w2 / (s * s + w2 / q1 * s + w2 * w2);
  h *= (1.0 + s / w3) / (1.0 + s / (q4 * w4) + s * s / (w4 * w4));
  if (f5 > 0.0) {
    const double w5 = kTwoPi * f5, w6 = kTwoPi * f6;
    h *= k * (s * s + w5 / q5 * s + w5 * w5) / (s * s + w6 / q6 * s + w6 * w6);
  }
  return h;
}
cd wb_formula(double f) { return iso8041(f, 16, 16, 0.55, 2.5, 0.9, 4, 0.95, 1.024); }
cd wd_formula(double f) { return iso8041(f, 2, 2, 0.63, 0, 1, 0, 1, 1); }

TEST(ComfortWeighting, PublishedValuesAt100RadPerSecond) {
  // ZETLAB's table of ISO 2631 weightings at 100 rad/s (15.915 Hz): Wb 0.8126, Wd 0.1261 (4
  // digits).
  const double f = 100.0 / kTwoPi;
  EXPECT_NEAR(std::abs(weighting_wb().response(f)), 0.8126, 5e-5);
  EXPECT_NEAR(std::abs(weighting_wd().response(f)), 0.1261, 5e-5);
}

TEST(ComfortWeighting, FrequencyDomainApplicationMatchesTheFormulas) {
  const double fs = 200.0;
  const std::size_t len = static_cast<std::size_t>(60.0 * fs);
  for (double f : {0.3, 0.5, 1.0, 2.0, 3.0, 5.0, 8.0, 12.0, 20.0, 40.0}) {
    for (bool vertical : {true, false}) {
      const auto w = vertical ? weighting_wb() : weighting_wd();
      const cd expect = vertical ? wb_formula(f) : wd_formula(f);
      EXPECT_NEAR(std::abs(w.response(f)), std::abs(expect), 1e-12 * std::abs(expect)) << f;
      const auto y = apply_analog(w, sine(f, fs, len), fs, 20.0);
      // Settled after 30 s (0.4 Hz band limit, decay 1.78 /s); the record's end is no edge for
      // a causal filter.
      const cd m = measured_response(y, f, fs, len / 2, len);
      EXPECT_NEAR(std::abs(m), std::abs(expect), 1e-6 * std::abs(expect) + 1e-9) << f;
      EXPECT_NEAR(std::arg(m / expect), 0.0, 1e-5) << f << (vertical ? " Wb" : " Wd");
    }
  }
}

}  // namespace
}  // namespace ferro::scenarios::analysis
