#pragma once
// Filters for the assessment of a run's signals: analog prototypes (cascades of second-order
// sections in s), their digital twins by the bilinear transform with prewarping, causal and
// zero-phase (forward-backward) application, and the application of an analog transfer function
// in the frequency domain.
//
// References: Oppenheim & Schafer, "Discrete-Time Signal Processing" (3rd ed., 2010) §7.2 (the
//   bilinear transform s = K (z - 1)/(z + 1); with K = 2 pi f_w / tan(pi f_w / fs) the digital
//   response at f_w equals the analog one at f_w: prewarping); Butterworth poles on the circle,
//   section damping 1/Q_k = 2 sin((2k - 1) pi / (2 n)); Gustafsson, "Determining the initial
//   states in forward-backward filtering", IEEE Trans. Signal Processing 44(4) 1996 (the edge
//   treatment: odd reflection of the ends, states started at the steady state of the first
//   padded sample).
// Known deviations: only even orders (whole second-order sections). The forward-backward filter
//   has the squared gain of the one-pass filter; a zero-phase low- or high-pass is designed with
//   its corner moved so that the squared gain is 1/sqrt(2) (-3 dB) at the nominal corner
//   (zero_phase_corner). Frequency-domain application (apply_analog) zero-pads the record so
//   that the response to its end does not wrap onto its start: it is the analog filter's
//   response to the record (started from rest at its first value) up to the response of the
//   analog filter to content above the Nyquist frequency, which the record does not hold.

#include <complex>
#include <span>
#include <vector>

namespace ferro::scenarios::analysis {

/// (n2 s^2 + n1 s + n0) / (d2 s^2 + d1 s + d0), s in rad/s.
struct AnalogSection {
  double n2 = 0.0, n1 = 0.0, n0 = 1.0;
  double d2 = 0.0, d1 = 0.0, d0 = 1.0;
  /// Frequency the bilinear transform is prewarped at for this section [Hz] (its natural
  /// frequency).
  double warp_frequency = 1.0;
};

/// Product of second-order sections times a gain.
struct AnalogFilter {
  std::vector<AnalogSection> sections;
  double gain = 1.0;
  /// H(j 2 pi f).
  [[nodiscard]] std::complex<double> response(double f) const;
};

/// y[n] = b0 x[n] + b1 x[n-1] + b2 x[n-2] - a1 y[n-1] - a2 y[n-2].
struct Biquad {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0, a1 = 0.0, a2 = 0.0;
};

/// A cascade of biquads for one sampling rate.
struct DigitalFilter {
  std::vector<Biquad> sections;
  double sample_rate = 0.0;  ///< [Hz]
  /// H(exp(j 2 pi f / sample_rate)).
  [[nodiscard]] std::complex<double> response(double f) const;
};

/// Butterworth low-pass of even order n with corner fc [Hz] (gain 1/sqrt(2) there).
[[nodiscard]] AnalogFilter butterworth_lowpass_analog(int order, double fc);
/// Butterworth high-pass of even order n with corner fc [Hz].
[[nodiscard]] AnalogFilter butterworth_highpass_analog(int order, double fc);
/// High-pass at f_low times low-pass at f_high, each Butterworth of even order n.
[[nodiscard]] AnalogFilter butterworth_bandpass_analog(int order, double f_low, double f_high);

/// Bilinear transform of every section, each prewarped at its warp_frequency (the digital gain
/// and phase equal the analog ones there). Throws std::invalid_argument when a warp frequency
/// is not below the Nyquist frequency.
[[nodiscard]] DigitalFilter bilinear(const AnalogFilter& analog, double sample_rate);

/// Corner of an order-n Butterworth low-pass whose forward-backward application has its
/// -3 dB point at fc: fc (sqrt(2) - 1)^(-1/(2n)) [Hz]. For a high-pass, the inverse factor.
[[nodiscard]] double zero_phase_lowpass_corner(int order, double fc);
[[nodiscard]] double zero_phase_highpass_corner(int order, double fc);

/// The one-pass Butterworth low-pass for zero-phase filtering at fc: corner
/// zero_phase_lowpass_corner(order, fc), prewarped at fc itself, so that after the bilinear
/// transform the forward-backward gain at fc is 1/sqrt(2) exactly at any sampling rate.
[[nodiscard]] AnalogFilter zero_phase_lowpass(int order, double fc);
/// Band-pass likewise: high-pass for f_low and low-pass for f_high, prewarped at f_low, f_high.
[[nodiscard]] AnalogFilter zero_phase_bandpass(int order, double f_low, double f_high);

/// Causal filtering, every section started at rest at the steady state of x[0].
[[nodiscard]] std::vector<double> filter(const DigitalFilter& f, std::span<const double> x);

/// Zero-phase filtering: forward, then backward over the reversed result; gain |H|^2, phase 0.
/// The record is extended at both ends by its odd reflection (2 x[0] - x[k]) over `padding`
/// samples (at most size - 1) so the ends start and stop smoothly.
[[nodiscard]] std::vector<double> filtfilt(const DigitalFilter& f, std::span<const double> x,
                                           std::size_t padding);

/// Samples of the slowest section's impulse response worth padding with: three time constants
/// of the lowest section frequency (3 fs / (2 pi f_min Q ... )), at least 16.
[[nodiscard]] std::size_t edge_padding(const AnalogFilter& analog, double sample_rate);

/// The analog filter applied in the frequency domain to a record sampled at `sample_rate`:
/// y = IFFT(H(j 2 pi f_k) FFT(x - x[0])) (+ H(0) x[0]), zero-padded to at least
/// x.size() + `settle_seconds` * sample_rate samples.
[[nodiscard]] std::vector<double> apply_analog(const AnalogFilter& analog,
                                               std::span<const double> x, double sample_rate,
                                               double settle_seconds);

}  // namespace ferro::scenarios::analysis
