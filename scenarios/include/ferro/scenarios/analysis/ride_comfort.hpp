#pragma once
// Ride comfort of car-body accelerations: EN 12299's mean comfort index N_MV (standard
// simplified method) with the frequency weightings Wb (vertical) and Wd (horizontal), Sperling's
// ride index Wz, and the one-sided power spectral density they and the stability analysis read.
//
// References: EN 12299:2009 (N_MV = 6 sqrt(a_XP95(Wd)^2 + a_YP95(Wd)^2 + a_ZP95(Wb)^2), a_P95 the
//   95th percentile of consecutive 5 s rms values of the weighted floor accelerations [m/s^2]);
//   ISO 8041 table of the weightings (as reproduced in the Larson Davis HVM200 manual, table 3.1):
//   W = H_h H_l H_t H_s, band limits H_h = s^2/(s^2 + w1 s/Q1 + w1^2), H_l = w2^2/(s^2 + w2 s/Q2 +
//   w2^2), a-v transition H_t = (1 + s/w3)/(1 + s/(Q4 w4) + s^2/w4^2), upward step H_s =
//   K (s^2 + w5 s/Q5 + w5^2)/(s^2 + w6 s/Q6 + w6^2); Wb: f1 0.4, f2 100, Q1 = Q2 = 1/sqrt(2),
//   f3 = f4 = 16 Hz, Q4 0.55, f5 2.5, Q5 0.9, f6 4, Q6 0.95, K 1.024; Wd: f3 = f4 = 2 Hz, Q4 0.63,
//   no step. Sperling's weighting B_z(f) = 0.588 sqrt((1.911 f^2 + (0.25 f^2)^2) /
//   ((1 - 0.2777 f^2)^2 + (1.563 f - 0.0368 f^3)^2)), B_y = 1.25 B_z (Forstberg 2000, eq. 3.1),
//   Wz = (2 int (100 B)^2 G df)^0.15 over 0.5-30 Hz, G the one-sided PSD [(m/s^2)^2/Hz]
//   (a sinusoid of rms a gives Wz = (100 sqrt(2) B a)^0.3, Sperling's (A^3 F(f)/f)^0.1 form
//   with A the peak in cm/s^2); Welch (1967) for the PSD.
// Known deviations: EN 12299 takes N_MV over 5 min (60 blocks of 5 s); a run shorter than that
//   gives it over the whole 5 s blocks it holds (a record shorter than 5 s is one block). That
//   EN 12299's Wb is ISO 2631-4's (the constants above) is taken from the ISO 8041 table; the
//   EN text itself was not at hand. The weightings are applied in the frequency domain
//   (apply_analog): the 100 Hz band limit lies at the Nyquist frequency of a 5 ms output, where no
//   bilinear map can place it.

#include <span>
#include <string>
#include <vector>

#include "ferro/scenarios/analysis/signal_filter.hpp"

namespace ferro::scenarios::analysis {

/// EN 12299 / ISO 8041 weighting Wb (vertical, seated/standing comfort) as an analog filter.
[[nodiscard]] AnalogFilter weighting_wb();
/// EN 12299 / ISO 8041 weighting Wd (horizontal).
[[nodiscard]] AnalogFilter weighting_wd();

/// Sperling's frequency weighting for a direction: "vertical" B_z, "lateral" B_y = 1.25 B_z.
[[nodiscard]] double sperling_weighting(double f, bool lateral);

/// One-sided power spectral density by Welch's method: Hann segments of `segment` samples (the
/// record's length when shorter), half overlapping, each with its mean removed; the density
/// integrates (sum G df) to the record's mean square of the segments' fluctuation.
struct Spectrum {
  std::vector<double> frequency;  ///< [Hz], 0 to Nyquist in steps of df
  std::vector<double> density;    ///< [unit^2 / Hz]
  double df = 0.0;                ///< [Hz]
};
[[nodiscard]] Spectrum welch_psd(std::span<const double> x, double sample_rate,
                                 std::size_t segment);

/// Frequency of the largest density in [f_min, f_max] [Hz] (NaN when the band holds no bin).
[[nodiscard]] double dominant_frequency(const Spectrum& s, double f_min, double f_max);

/// The comfort of one floor position.
struct ComfortIndex {
  std::vector<double> block_rms_x, block_rms_y, block_rms_z;  ///< 5 s rms of the weighted
                                                              ///< accelerations [m/s^2]
  double a_x95 = 0.0, a_y95 = 0.0, a_z95 = 0.0;  ///< their 95th percentiles [m/s^2]
  double n_mv = 0.0;                             ///< 6 sqrt(a_x95^2 + a_y95^2 + a_z95^2) [-]
  bool short_record = false;  ///< fewer than 60 blocks (less than the standard's 5 min)
};

/// N_MV from the floor accelerations (x along the car, y lateral, z vertical; gravity removed)
/// sampled at `sample_rate`; blocks of `block_seconds` (5 s).
[[nodiscard]] ComfortIndex comfort_index(std::span<const double> ax, std::span<const double> ay,
                                         std::span<const double> az, double sample_rate,
                                         double block_seconds = 5.0);

/// Sperling's Wz of one direction from the acceleration record [m/s^2] sampled at
/// `sample_rate` (Welch segments of 5 s, band 0.5-30 Hz).
[[nodiscard]] double sperling_index(std::span<const double> a, double sample_rate, bool lateral);

/// EN 12299's scale for N_MV ("very comfortable" < 1, "comfortable" < 2, "medium" < 4,
/// "uncomfortable" < 5, else "very uncomfortable").
[[nodiscard]] std::string comfort_class(double n_mv);

}  // namespace ferro::scenarios::analysis
