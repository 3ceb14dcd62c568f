// Stochastic irregularities: the realisation's estimated spectrum (Welch, several seeds)
// matches its target PSD within 10 % over the band; Parseval; FFT grid against the direct sum of
// cosines; seeding; the published spectra's constants.
//
// Oracles: the PSD formulas themselves (spectra.hpp, evaluated independently of the synthesis),
// a Welch estimate computed with the test's own radix-2 FFT (not FFTW), the direct cosine sum.

#include "ferro/track/stochastic_irregularity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

namespace ferro::track {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// In-place iterative radix-2 FFT (forward, e^{-i...}); n must be a power of two.
void fft(std::vector<std::complex<double>>& a) {
  const std::size_t n = a.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const std::complex<double> w_len = std::polar(1.0, -kTwoPi / static_cast<double>(len));
    for (std::size_t i = 0; i < n; i += len) {
      std::complex<double> w(1.0, 0.0);
      for (std::size_t k = 0; k < len / 2; ++k) {
        const auto u = a[i + k], v = a[i + k + len / 2] * w;
        a[i + k] = u + v;
        a[i + k + len / 2] = u - v;
        w *= w_len;
      }
    }
  }
}

// Welch estimate of the one-sided PSD in m^2/(rad/m): Hann windows of `seg` samples, 50 %
// overlap, accumulated into `psd` (size seg/2 + 1), returns the number of segments added.
int welch_accumulate(const std::vector<double>& x, double ds, std::size_t seg,
                     std::vector<double>& psd) {
  std::vector<double> w(seg);
  double w2 = 0.0;
  for (std::size_t i = 0; i < seg; ++i) {
    w[i] = 0.5 * (1.0 - std::cos(kTwoPi * static_cast<double>(i) / static_cast<double>(seg)));
    w2 += w[i] * w[i];
  }
  int count = 0;
  std::vector<std::complex<double>> buf(seg);
  for (std::size_t start = 0; start + seg <= x.size(); start += seg / 2) {
    for (std::size_t i = 0; i < seg; ++i) buf[i] = x[start + i] * w[i];
    fft(buf);
    // One-sided density per cycle/m is 2 ds |X|^2 / sum w^2; per rad/m divide by 2 pi.
    for (std::size_t k = 1; k < seg / 2; ++k) {
      psd[k] += 2.0 * ds * std::norm(buf[k]) / w2 / kTwoPi;
    }
    ++count;
  }
  return count;
}

struct BandCheck {
  double worst = 0.0;  // largest |estimate / target - 1| over the bands
  int bands = 0;
};

// Averages the Welch estimate over seeds and compares it with the target in third-octave bands
// lying inside [lambda_min, lambda_max] with a margin of one third-octave at each edge (the
// Hann main lobe smears the band edges over ~2 bins).
BandCheck check_spectrum(TrackSpectrum spectrum, IrregularityChannel channel, int seeds) {
  StochasticIrregularitySpec spec;
  spec.spectrum = spectrum;
  spec.channels = {channel};
  spec.wavelength_min = 2.0;
  spec.wavelength_max = 120.0;
  spec.length = 40000.0;
  const double ds = 0.25;        // sampling step of the estimate [m], 8 samples per 2 m wave
  const std::size_t seg = 4096;  // 1024 m segments: 0.0061 rad/m resolution
  std::vector<double> psd(seg / 2 + 1, 0.0);
  int segments = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    spec.seed = static_cast<std::uint64_t>(seed) * 7919u;
    const StochasticIrregularity irr(spec);
    std::vector<double> x(static_cast<std::size_t>(spec.length / ds));
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] = irr.at(static_cast<double>(i) * ds).value(channel);
    }
    segments += welch_accumulate(x, ds, seg, psd);
  }
  const double d_omega = kTwoPi / (static_cast<double>(seg) * ds);
  const double lo = kTwoPi / spec.wavelength_max * std::cbrt(2.0);
  const double hi = kTwoPi / spec.wavelength_min / std::cbrt(2.0);
  BandCheck out;
  for (double band_lo = lo; band_lo * std::cbrt(2.0) <= hi; band_lo *= std::cbrt(2.0)) {
    const double band_hi = band_lo * std::cbrt(2.0);
    double est = 0.0, target = 0.0;
    for (std::size_t k = 1; k < seg / 2; ++k) {
      const double omega = static_cast<double>(k) * d_omega;
      if (omega < band_lo || omega >= band_hi) continue;
      est += psd[k] / segments;
      target += one_sided_psd(spectrum, channel, omega);
    }
    if (target == 0.0) continue;
    if (std::getenv("FERRO_TRACK_VERBOSE") != nullptr) {
      std::printf("  band %.4f-%.4f rad/m: estimate/target - 1 = %+.4f\n", band_lo, band_hi,
                  est / target - 1.0);
    }
    out.worst = std::max(out.worst, std::abs(est / target - 1.0));
    ++out.bands;
  }
  return out;
}

// A stochastic realisation's estimated spectrum matches its target within
// 10 % over the band. 4 seeds x 40 km give ~300 Welch segments; the narrowest third-octave band
// (lowest) spans ~3 bins, so the estimate's relative standard deviation there is ~3-4 %, and a
// 10 % tolerance is ~2.5 sigma in the worst band (the others are far tighter). Observed worst
// band errors: 3.1 %, 3.2 %, 3.1 % (run with FERRO_TRACK_VERBOSE=1 to print every band). A
// one-/two-sided mix-up would be a 100 % error, a wrong dOmega or FFT scaling likewise.
constexpr double kSpectrumTolerance = 0.10;

TEST(StochasticIrregularity, welch_spectrum_matches_erri_low_lateral) {
  const auto r = check_spectrum(TrackSpectrum::kErriLow, IrregularityChannel::kLateral, 4);
  EXPECT_GE(r.bands, 15);
  EXPECT_LT(r.worst, kSpectrumTolerance) << "worst third-octave band error";
  RecordProperty("worst_band_error", std::to_string(r.worst));
  std::printf("erri_low lateral: %d bands, worst error %.4f\n", r.bands, r.worst);
}

TEST(StochasticIrregularity, welch_spectrum_matches_erri_high_cross_level) {
  const auto r = check_spectrum(TrackSpectrum::kErriHigh, IrregularityChannel::kCrossLevel, 4);
  EXPECT_GE(r.bands, 15);
  EXPECT_LT(r.worst, kSpectrumTolerance);
  std::printf("erri_high cross_level: %d bands, worst error %.4f\n", r.bands, r.worst);
}

TEST(StochasticIrregularity, welch_spectrum_matches_fra_class_4_vertical) {
  const auto r = check_spectrum(TrackSpectrum::kFraClass4, IrregularityChannel::kVertical, 4);
  EXPECT_GE(r.bands, 15);
  EXPECT_LT(r.worst, kSpectrumTolerance);
  std::printf("fra_4 vertical: %d bands, worst error %.4f\n", r.bands, r.worst);
}

StochasticIrregularitySpec small_spec() {
  StochasticIrregularitySpec spec;
  spec.spectrum = TrackSpectrum::kErriHigh;
  spec.length = 3000.0;
  spec.wavelength_min = 3.0;
  spec.wavelength_max = 150.0;
  spec.start_s = -200.0;
  spec.seed = 42;
  return spec;
}

// The variance of the discrete realisation equals the integral of the PSD over the band
// (midpoint rule on the FFT grid) and, by Parseval, the mean square over one period.
TEST(StochasticIrregularity, variance_parseval_and_band_integral) {
  const StochasticIrregularity irr(small_spec());
  for (const auto c : {IrregularityChannel::kLateral, IrregularityChannel::kVertical,
                       IrregularityChannel::kCrossLevel, IrregularityChannel::kGauge}) {
    // Band integral by a fine trapezoid rule (independent of the FFT grid).
    const double lo = kTwoPi / 150.0, hi = kTwoPi / 3.0;
    const int n = 200000;
    double integral = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double w = lo + (hi - lo) * i / n;
      integral += (i == 0 || i == n ? 0.5 : 1.0) * one_sided_psd(TrackSpectrum::kErriHigh, c, w);
    }
    integral *= (hi - lo) / n;
    // Grid sum vs integral: band edges fall within one dOmega = 2 pi / 4915 m of a line, an
    // error of ~S(edge) dOmega / integral < 1 %.
    EXPECT_NEAR(irr.variance(c) / integral, 1.0, 0.01) << to_string(c);
    // Parseval over the period at the grid nodes: exact up to rounding.
    double mean_square = 0.0;
    const auto nodes = static_cast<std::size_t>(std::llround(irr.period() / irr.grid_spacing()));
    for (std::size_t j = 0; j < nodes; ++j) {
      const double v = irr.at(-200.0 + static_cast<double>(j) * irr.grid_spacing()).value(c);
      mean_square += v * v;
    }
    mean_square /= static_cast<double>(nodes);
    EXPECT_NEAR(mean_square / irr.variance(c), 1.0, 1e-9) << to_string(c);
  }
  // ERRI high lateral alignment over 3-150 m: standard deviation of a few mm.
  EXPECT_GT(std::sqrt(irr.variance(IrregularityChannel::kLateral)), 1e-3);
  EXPECT_LT(std::sqrt(irr.variance(IrregularityChannel::kLateral)), 1e-2);
}

TEST(StochasticIrregularity, grid_interpolation_matches_direct_sum) {
  const StochasticIrregularity irr(small_spec());
  const double sigma = std::sqrt(irr.variance(IrregularityChannel::kVertical));
  const double sigma_slope = [&] {
    double v = 0.0;
    for (std::size_t k = 0; k < irr.component_count(); ++k) {
      const double w = irr.omegas()[k];
      v += one_sided_psd(TrackSpectrum::kErriHigh, IrregularityChannel::kVertical, w) * w * w *
           kTwoPi / irr.period();
    }
    return std::sqrt(v);
  }();
  for (int i = 0; i < 300; ++i) {
    const double s = -200.0 + 9.87654 * i;
    const IrregularitySample a = irr.at(s), b = irr.at_direct(s);
    // Hermite error on a node interval ds = 0.15 m: (Omega_max ds)^4 / 384 relative to each
    // component's amplitude (~4e-5 at Omega_max = 2.09 rad/m), i.e. far below 1e-3 sigma.
    EXPECT_NEAR(a.vertical, b.vertical, 1e-3 * sigma) << s;
    EXPECT_NEAR(a.d_vertical, b.d_vertical, 1e-3 * sigma_slope) << s;
    EXPECT_NEAR(a.cross_level, b.cross_level,
                1e-3 * std::sqrt(irr.variance(IrregularityChannel::kCrossLevel)));
  }
  // Slope of the interpolant against its own central difference (C1 Hermite).
  for (double s = 10.0; s < 100.0; s += 3.3) {
    const double fd = (irr.at(s + 1e-5).lateral - irr.at(s - 1e-5).lateral) / 2e-5;
    EXPECT_NEAR(irr.at(s).d_lateral, fd, 1e-6 * sigma_slope + 1e-10) << s;
  }
}

TEST(StochasticIrregularity, seeded_and_channels_independent) {
  auto spec = small_spec();
  const StochasticIrregularity a(spec), b(spec);
  spec.seed = 43;
  const StochasticIrregularity c(spec);
  spec.seed = 42;
  spec.channels = {IrregularityChannel::kGauge};
  const StochasticIrregularity only_gauge(spec);
  for (double s = 0.0; s < 500.0; s += 17.0) {
    EXPECT_EQ(a.at(s).lateral, b.at(s).lateral);
    EXPECT_NE(a.at(s).lateral, c.at(s).lateral);
    EXPECT_EQ(only_gauge.at(s).lateral, 0.0);
    EXPECT_EQ(only_gauge.at(s).gauge, a.at(s).gauge);  // same phases whatever else is on
  }
  // Periodic beyond the realisation.
  EXPECT_NEAR(a.at(123.4).vertical, a.at(123.4 + a.period()).vertical, 1e-12);
  EXPECT_GE(a.period(), 3000.0);
}

TEST(StochasticIrregularity, fade_in) {
  auto spec = small_spec();
  const StochasticIrregularity plain(spec);
  spec.fade_in_length = 50.0;
  const StochasticIrregularity faded(spec);
  EXPECT_EQ(faded.at(-200.5).lateral, 0.0);  // before start_s
  EXPECT_EQ(faded.at(-200.0).d_lateral, 0.0);
  for (const double x : {60.0, 500.0}) {  // past the fade: unchanged
    EXPECT_EQ(faded.at(-200.0 + x).vertical, plain.at(-200.0 + x).vertical);
  }
  // Halfway the weight is 1/2.
  EXPECT_NEAR(faded.at(-175.0).gauge, 0.5 * plain.at(-175.0).gauge, 1e-15);
  EXPECT_NEAR(faded.at_direct(-175.0).gauge, 0.5 * plain.at_direct(-175.0).gauge, 1e-15);
  // Slope of the faded signal against its central difference (Hermite interpolant is C1; the
  // difference error is ~h^2 |r'''| / 6 < 1e-9 of the slope scale).
  for (double s = -199.0; s < -150.0; s += 3.7) {
    const double fd = (faded.at(s + 1e-5).cross_level - faded.at(s - 1e-5).cross_level) / 2e-5;
    EXPECT_NEAR(faded.at(s).d_cross_level, fd, 1e-8) << s;
  }
}

TEST(StochasticIrregularity, validate_names_the_field) {
  StochasticIrregularitySpec spec;  // length NaN
  try {
    spec.validate("irregularities[0]");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("irregularities[0].length:", 0), 0u) << e.what();
  }
  spec.length = 100.0;
  spec.wavelength_max = 2.0;
  EXPECT_THROW(spec.validate(), std::invalid_argument);
  spec.wavelength_max = 100.0;
  spec.grid_spacing = 1.0;  // > wavelength_min / 4
  EXPECT_THROW(spec.validate(), std::invalid_argument);
  EXPECT_THROW((void)track_spectrum_from_string("fra_7", "spectrum"), std::invalid_argument);
  EXPECT_EQ(track_spectrum_from_string("fra_class_3", "spectrum"), TrackSpectrum::kFraClass3);
}

// Published constants reproduced: GENSYS' ORE B176 high-level table (trc_ipsd manual) lists
// lateral 6.1608e-6 and vertical 1.0863e-5 m^2/(1/m) at 0.1 1/m (10 m waves), 2.3194e-4 and
// 4.0897e-4 at 0.02 1/m (50 m waves). Per (1/m) = 2 pi * per (rad/m).
TEST(TrackSpectra, erri_high_matches_gensys_table) {
  constexpr double kTableDigits = 2e-4;  // the table gives 5 significant digits
  auto per_cycle = [](IrregularityChannel c, double f) {
    return kTwoPi * one_sided_psd(TrackSpectrum::kErriHigh, c, kTwoPi * f);
  };
  EXPECT_NEAR(per_cycle(IrregularityChannel::kLateral, 0.1) / 6.1608e-6, 1.0, kTableDigits);
  EXPECT_NEAR(per_cycle(IrregularityChannel::kVertical, 0.1) / 1.0863e-5, 1.0, kTableDigits);
  EXPECT_NEAR(per_cycle(IrregularityChannel::kLateral, 0.02) / 2.3194e-4, 1.0, kTableDigits);
  EXPECT_NEAR(per_cycle(IrregularityChannel::kVertical, 0.02) / 4.0897e-4, 1.0, kTableDigits);
  // FRA: class 6 is smoother than class 1 everywhere.
  for (const double w : {0.05, 0.5, 2.0}) {
    EXPECT_LT(one_sided_psd(TrackSpectrum::kFraClass6, IrregularityChannel::kVertical, w),
              one_sided_psd(TrackSpectrum::kFraClass1, IrregularityChannel::kVertical, w));
  }
  EXPECT_THROW((void)one_sided_psd(TrackSpectrum::kErriLow, IrregularityChannel::kLateral, 0.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace ferro::track
