#pragma once
// Stochastic track irregularities synthesised from a one-sided PSD (spectra.hpp) as a sum of
// cosines with seeded random phases:
//   r(s) = sum_k sqrt(2 S(Omega_k) dOmega) cos(Omega_k (s - start_s) + phase_k),
// Omega_k = k dOmega on the grid of an inverse FFT of period P = N ds >= length, restricted to
// the band [2 pi / wavelength_max, 2 pi / wavelength_min]. The inverse FFT (FFTW) gives r and
// dr/ds at the N grid nodes; at() interpolates them by cubic Hermite (value and slope
// continuous). at_direct() sums the cosines exactly (slow; for checks).
//
// References: Shinozuka & Jan, J. Sound Vib. 25 (1972) 111-128 (spectral representation by a
// sum of cosines with random phases); Cooley & Tukey / FFTW (Frigo & Johnson, Proc. IEEE 93
// (2005)) for the inverse transform; spectra as in spectra.hpp.
// Known deviations: the four channels are independent realisations (no coherence between
// lateral, vertical, cross-level and gauge, which real track shows); the amplitudes are
// deterministic (only phases are random), so every realisation has exactly the band variance;
// the realisation is periodic with period P (P >= length). Hermite interpolation between
// nodes adds a relative error of about (Omega ds)^4 / 384 in value: 4e-5 at the default
// ds = wavelength_min / 20. Phases use the top 53 bits of std::mt19937_64 so a seed gives the
// same track on every standard library.

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "ferro/track/irregularity.hpp"
#include "ferro/track/spectra.hpp"

namespace ferro::track {

/// Most nodes of the inverse-FFT grid of a realisation (2^27: 1 GiB per channel of doubles).
inline constexpr std::size_t kMaxGridNodes = std::size_t{1} << 27;

struct StochasticIrregularitySpec {
  TrackSpectrum spectrum = TrackSpectrum::kErriLow;
  /// Channels to synthesise; the others stay zero. Each channel gets its own phases, drawn in
  /// the fixed order lateral, vertical, cross_level, gauge whatever this list holds, so
  /// switching a channel off does not change the others.
  std::vector<IrregularityChannel> channels = {
      IrregularityChannel::kLateral, IrregularityChannel::kVertical,
      IrregularityChannel::kCrossLevel, IrregularityChannel::kGauge};
  double wavelength_min = 3.0;    ///< shortest wavelength of the band [m] (EN 13848 D1: 3 m)
  double wavelength_max = 150.0;  ///< longest wavelength of the band [m] (EN 13848 D3: 150 m)
  double start_s = 0.0;           ///< arc length where the realisation starts [m]
  double length = std::numeric_limits<double>::quiet_NaN();  ///< non-repeating extent [m], > 0
  std::uint64_t seed = 1;  ///< seed of std::mt19937_64 for the phases
  /// Grid spacing of the inverse FFT [m]; NaN = wavelength_min / 20. At most wavelength_min / 4.
  double grid_spacing = std::numeric_limits<double>::quiet_NaN();
  double amplitude_scale = 1.0;  ///< multiplies every amplitude (1 = the spectrum as published)
  /// Length over which the irregularities fade in from zero after start_s [m], with the smooth
  /// weight (1 - cos(pi x / fade_in_length)) / 2; 0 = no fade. With a fade, the irregularities
  /// are zero before start_s (instead of periodic), so a vehicle can start on perfect track.
  double fade_in_length = 0.0;

  /// Throws std::invalid_argument naming `where` + field.
  void validate(const std::string& where = "stochastic") const;
};

class StochasticIrregularity final : public Irregularity {
 public:
  /// Validates the spec and synthesises the realisation (one inverse FFT per channel).
  explicit StochasticIrregularity(const StochasticIrregularitySpec& spec);

  [[nodiscard]] std::string name() const override;
  /// Hermite interpolation of the FFT grid; periodic beyond [start_s, start_s + period)
  /// (before start_s: zero if fade_in_length > 0).
  [[nodiscard]] IrregularitySample at(double s) const override;
  /// Exact sum of the cosines (cost proportional to the number of components), same fade-in.
  [[nodiscard]] IrregularitySample at_direct(double s) const;

  [[nodiscard]] double period() const { return period_; }
  [[nodiscard]] double grid_spacing() const { return spacing_; }
  [[nodiscard]] std::size_t component_count() const { return omegas_.size(); }
  [[nodiscard]] const std::vector<double>& omegas() const { return omegas_; }
  /// Variance of the realisation of one channel, sum_k a_k^2 / 2 (= integral of the PSD over the
  /// band, discretised) [m^2]; zero for a channel not synthesised.
  [[nodiscard]] double variance(IrregularityChannel channel) const;
  [[nodiscard]] const StochasticIrregularitySpec& spec() const { return spec_; }

 private:
  static constexpr std::size_t kChannels = 4;
  StochasticIrregularitySpec spec_;
  double period_ = 0.0, spacing_ = 0.0;
  std::vector<double> omegas_;
  std::array<std::vector<double>, kChannels> amplitudes_;  // empty for channels not synthesised
  std::array<std::vector<double>, kChannels> phases_;
  // Grid node n: values of the 4 channels, then their s-derivatives.
  std::vector<std::array<double, 2 * kChannels>> nodes_;

  // Applies the fade-in weight at s to an unfaded sample.
  [[nodiscard]] IrregularitySample faded(double s, IrregularitySample raw) const;
};

}  // namespace ferro::track
