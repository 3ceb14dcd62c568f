// One-sided PSDs of track irregularities: ERRI / ORE B176 low and high, FRA classes 1-6.
//
// References and Known deviations: see spectra.hpp (formulas and constants are listed there
// with their sources).

#include "ferro/track/spectra.hpp"

#include <fmt/format.h>

#include <array>
#include <stdexcept>

namespace ferro::track {
namespace {

struct ErriLevel {
  double a_lateral, a_vertical, a_gauge;  // [m rad]
};
constexpr ErriLevel kErriLow{2.119e-7, 4.032e-7, 5.32e-8};
constexpr ErriLevel kErriHigh{6.125e-7, 1.080e-6, 1.032e-7};
constexpr double kErriOmegaC = 0.8246;  // [rad/m]
constexpr double kErriOmegaR = 0.0206;
constexpr double kErriOmegaS = 0.4380;

struct FraClass {
  double a_vertical, a_lateral, omega_s;  // [cm^2 rad/m], [cm^2 rad/m], [rad/m]
};
constexpr std::array<FraClass, 6> kFraClasses = {{{1.2107, 3.3634, 0.6046},
                                                  {1.0181, 1.2107, 0.9308},
                                                  {0.6816, 0.4128, 0.8520},
                                                  {0.5376, 0.3027, 1.1312},
                                                  {0.2095, 0.0762, 0.8209},
                                                  {0.0339, 0.0339, 0.4380}}};
constexpr double kFraOmegaC = 0.8245;  // [rad/m]
constexpr double kFraK = 0.25;
constexpr double kCm2ToM2 = 1e-4;

double erri_psd(const ErriLevel& lvl, IrregularityChannel channel, double omega) {
  const double w2 = omega * omega;
  const double wc2 = kErriOmegaC * kErriOmegaC;
  const double base = wc2 / ((w2 + kErriOmegaR * kErriOmegaR) * (w2 + wc2));
  const double roll_off = w2 / (w2 + kErriOmegaS * kErriOmegaS);
  switch (channel) {
    case IrregularityChannel::kLateral:
      return lvl.a_lateral * base;
    case IrregularityChannel::kVertical:
      return lvl.a_vertical * base;
    // Angle spectrum (A_v / b^2) * base * roll_off, times (2b)^2 for the height difference.
    case IrregularityChannel::kCrossLevel:
      return 4.0 * lvl.a_vertical * base * roll_off;
    case IrregularityChannel::kGauge:
      return lvl.a_gauge * base * roll_off;
  }
  return 0.0;
}

double fra_psd(const FraClass& cls, IrregularityChannel channel, double omega) {
  const double w2 = omega * omega;
  const double wc2 = kFraOmegaC * kFraOmegaC;
  switch (channel) {
    case IrregularityChannel::kLateral:
      return kCm2ToM2 * kFraK * cls.a_lateral * wc2 / (w2 * (w2 + wc2));
    case IrregularityChannel::kVertical:
      return kCm2ToM2 * kFraK * cls.a_vertical * wc2 / (w2 * (w2 + wc2));
    case IrregularityChannel::kCrossLevel:
    case IrregularityChannel::kGauge:
      return kCm2ToM2 * 4.0 * kFraK * cls.a_vertical * wc2 /
             ((w2 + wc2) * (w2 + cls.omega_s * cls.omega_s));
  }
  return 0.0;
}

}  // namespace

TrackSpectrum track_spectrum_from_string(std::string_view name, const std::string& where) {
  if (name == "erri_low" || name == "ore_b176_low") return TrackSpectrum::kErriLow;
  if (name == "erri_high" || name == "ore_b176_high") return TrackSpectrum::kErriHigh;
  for (int c = 1; c <= 6; ++c) {
    if (name == fmt::format("fra_{}", c) || name == fmt::format("fra_class_{}", c)) {
      return static_cast<TrackSpectrum>(static_cast<int>(TrackSpectrum::kFraClass1) + c - 1);
    }
  }
  throw std::invalid_argument(
      fmt::format("{}: unknown track spectrum '{}' (allowed: erri_low, erri_high, fra_1 ... fra_6)",
                  where, name));
}

std::string_view to_string(TrackSpectrum spectrum) {
  switch (spectrum) {
    case TrackSpectrum::kErriLow:
      return "erri_low";
    case TrackSpectrum::kErriHigh:
      return "erri_high";
    case TrackSpectrum::kFraClass1:
      return "fra_1";
    case TrackSpectrum::kFraClass2:
      return "fra_2";
    case TrackSpectrum::kFraClass3:
      return "fra_3";
    case TrackSpectrum::kFraClass4:
      return "fra_4";
    case TrackSpectrum::kFraClass5:
      return "fra_5";
    case TrackSpectrum::kFraClass6:
      return "fra_6";
  }
  return "?";
}

double one_sided_psd(TrackSpectrum spectrum, IrregularityChannel channel, double omega) {
  if (!(omega > 0.0)) {
    throw std::invalid_argument(
        fmt::format("one_sided_psd: omega must be positive [rad/m] (got {})", omega));
  }
  switch (spectrum) {
    case TrackSpectrum::kErriLow:
      return erri_psd(kErriLow, channel, omega);
    case TrackSpectrum::kErriHigh:
      return erri_psd(kErriHigh, channel, omega);
    default: {
      const int cls = static_cast<int>(spectrum) - static_cast<int>(TrackSpectrum::kFraClass1);
      return fra_psd(kFraClasses.at(cls), channel, omega);
    }
  }
}

}  // namespace ferro::track
