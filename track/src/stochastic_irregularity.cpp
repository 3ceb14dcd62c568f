// Stochastic irregularities: random-phase sum of cosines evaluated by inverse FFT on a grid,
// cubic Hermite interpolation between nodes.
//
// References: Shinozuka & Jan (1972); Frigo & Johnson (2005) (FFTW c2r conventions:
// unnormalised, x_j = sum_k X_k exp(+2 pi i j k / N) over the Hermitian-completed spectrum).
// Known deviations: see stochastic_irregularity.hpp.

#include "ferro/track/stochastic_irregularity.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <mutex>
#include <numbers>
#include <random>
#include <stdexcept>

#include "ferro/numerics/interpolation.hpp"

namespace ferro::track {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr std::array<IrregularityChannel, 4> kChannelOrder = {
    IrregularityChannel::kLateral, IrregularityChannel::kVertical, IrregularityChannel::kCrossLevel,
    IrregularityChannel::kGauge};

int channel_index(IrregularityChannel c) {
  return static_cast<int>(c);
}

// FFTW's planner is not thread-safe; execution is.
std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

void StochasticIrregularitySpec::validate(const std::string& where) const {
  if (!(std::isfinite(wavelength_min) && wavelength_min > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "{}.wavelength_min: must be positive and finite [m] (got {})", where, wavelength_min));
  }
  if (!(std::isfinite(wavelength_max) && wavelength_max > wavelength_min)) {
    throw std::invalid_argument(
        fmt::format("{}.wavelength_max: must be finite and > wavelength_min = {} m (got {})", where,
                    wavelength_min, wavelength_max));
  }
  if (!std::isfinite(start_s)) {
    throw std::invalid_argument(
        fmt::format("{}.start_s: must be finite [m] (got {})", where, start_s));
  }
  if (!(std::isfinite(length) && length > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{}.length: must be positive and finite [m] (got {})", where, length));
  }
  if (!std::isnan(grid_spacing) && !(grid_spacing > 0.0 && grid_spacing <= 0.25 * wavelength_min)) {
    throw std::invalid_argument(
        fmt::format("{}.grid_spacing: must be in (0, wavelength_min / 4 = {}] m, or unset (got {})",
                    where, 0.25 * wavelength_min, grid_spacing));
  }
  if (!(std::isfinite(fade_in_length) && fade_in_length >= 0.0)) {
    throw std::invalid_argument(fmt::format(
        "{}.fade_in_length: must be finite and >= 0 [m] (got {})", where, fade_in_length));
  }
  if (!(std::isfinite(amplitude_scale) && amplitude_scale >= 0.0)) {
    throw std::invalid_argument(fmt::format("{}.amplitude_scale: must be finite and >= 0 (got {})",
                                            where, amplitude_scale));
  }
  if (channels.empty()) {
    throw std::invalid_argument(
        fmt::format("{}.channels: at least one of lateral, vertical, cross_level, gauge", where));
  }
}

StochasticIrregularity::StochasticIrregularity(const StochasticIrregularitySpec& spec)
    : spec_(spec) {
  spec_.validate();
  const double wanted =
      std::isnan(spec_.grid_spacing) ? spec_.wavelength_min / 20.0 : spec_.grid_spacing;
  // Period covers the length and the longest wavelength; node count a power of two.
  const double min_period = std::max(spec_.length, spec_.wavelength_max);
  std::size_t n = 16;
  while (static_cast<double>(n) * wanted < min_period) n *= 2;
  if (n > (std::size_t{1} << 27)) {
    throw std::invalid_argument(
        fmt::format("stochastic.length: {} m at a grid spacing of {} m needs more than 2^27 nodes",
                    spec_.length, wanted));
  }
  spacing_ = wanted;
  period_ = static_cast<double>(n) * spacing_;
  const double d_omega = kTwoPi / period_;
  const double omega_lo = kTwoPi / spec_.wavelength_max, omega_hi = kTwoPi / spec_.wavelength_min;
  const auto k_lo = static_cast<std::size_t>(std::ceil(omega_lo / d_omega - 1e-9));
  const auto k_hi = static_cast<std::size_t>(std::floor(omega_hi / d_omega + 1e-9));
  std::vector<std::size_t> ks;
  for (std::size_t k = std::max<std::size_t>(k_lo, 1); k <= k_hi && k < n / 2; ++k) ks.push_back(k);
  if (ks.empty()) {
    throw std::invalid_argument(
        fmt::format("stochastic: no frequency of the {} m period falls in the band [{}, {}] m",
                    period_, spec_.wavelength_min, spec_.wavelength_max));
  }
  omegas_.reserve(ks.size());
  for (const auto k : ks) omegas_.push_back(static_cast<double>(k) * d_omega);

  // Phases: every channel draws its set in fixed order, synthesised or not.
  std::mt19937_64 rng(spec_.seed);
  std::array<bool, kChannels> on{};
  for (const auto c : spec_.channels) on[channel_index(c)] = true;
  for (const auto c : kChannelOrder) {
    const std::size_t ci = channel_index(c);
    std::vector<double> phase(ks.size());
    for (auto& p : phase) p = kTwoPi * static_cast<double>(rng() >> 11) * 0x1.0p-53;
    if (!on[ci]) continue;
    std::vector<double> amp(ks.size());
    for (std::size_t i = 0; i < ks.size(); ++i) {
      amp[i] = spec_.amplitude_scale *
               std::sqrt(2.0 * one_sided_psd(spec_.spectrum, c, omegas_[i]) * d_omega);
    }
    amplitudes_[ci] = std::move(amp);
    phases_[ci] = std::move(phase);
  }

  // Inverse FFT per channel, for r and dr/ds: X_k = (a_k / 2) e^{i phase_k}, X'_k = i Omega_k X_k.
  nodes_.assign(n, {});
  std::vector<std::complex<double>> spectrum(n / 2 + 1);
  std::vector<double> signal(n);
  fftw_plan plan = nullptr;
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    plan =
        fftw_plan_dft_c2r_1d(static_cast<int>(n), reinterpret_cast<fftw_complex*>(spectrum.data()),
                             signal.data(), FFTW_ESTIMATE);
  }
  for (const auto c : kChannelOrder) {
    const std::size_t ci = channel_index(c);
    if (amplitudes_[ci].empty()) continue;
    for (std::size_t deriv = 0; deriv < 2; ++deriv) {
      std::fill(spectrum.begin(), spectrum.end(), std::complex<double>(0.0, 0.0));
      for (std::size_t i = 0; i < ks.size(); ++i) {
        std::complex<double> x = std::polar(0.5 * amplitudes_[ci][i], phases_[ci][i]);
        if (deriv == 1) x *= std::complex<double>(0.0, omegas_[i]);
        spectrum[ks[i]] = x;
      }
      fftw_execute(plan);  // c2r overwrites its input; it is refilled each pass
      for (std::size_t j = 0; j < n; ++j) nodes_[j][ci + deriv * kChannels] = signal[j];
    }
  }
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(plan);
  }
}

std::string StochasticIrregularity::name() const {
  return fmt::format("stochastic {} ({}-{} m, seed {})", to_string(spec_.spectrum),
                     spec_.wavelength_min, spec_.wavelength_max, spec_.seed);
}

IrregularitySample StochasticIrregularity::at(double s) const {
  double t = std::fmod(s - spec_.start_s, period_);
  if (t < 0.0) t += period_;
  const std::size_t n = nodes_.size();
  auto j = static_cast<std::size_t>(t / spacing_);
  if (j >= n) j = n - 1;
  const double tau = t / spacing_ - static_cast<double>(j);
  const auto& p0 = nodes_[j];
  const auto& p1 = nodes_[j + 1 == n ? 0 : j + 1];
  const numerics::HermiteBasis b(tau);
  double v[kChannels], dv[kChannels];
  for (std::size_t c = 0; c < kChannels; ++c) {
    const double y0 = p0[c], y1 = p1[c], m0 = p0[c + kChannels], m1 = p1[c + kChannels];
    v[c] = b.h00 * y0 + b.h10 * spacing_ * m0 + b.h01 * y1 + b.h11 * spacing_ * m1;
    dv[c] = (b.g00 * y0 + b.g01 * y1) / spacing_ + b.g10 * m0 + b.g11 * m1;
  }
  IrregularitySample out;
  out.lateral = v[0];
  out.vertical = v[1];
  out.cross_level = v[2];
  out.gauge = v[3];
  out.d_lateral = dv[0];
  out.d_vertical = dv[1];
  out.d_cross_level = dv[2];
  out.d_gauge = dv[3];
  return faded(s, out);
}

IrregularitySample StochasticIrregularity::at_direct(double s) const {
  IrregularitySample out;
  const double x = s - spec_.start_s;
  for (const auto c : kChannelOrder) {
    const std::size_t ci = channel_index(c);
    if (amplitudes_[ci].empty()) continue;
    double v = 0.0, dv = 0.0;
    for (std::size_t i = 0; i < omegas_.size(); ++i) {
      const double arg = omegas_[i] * x + phases_[ci][i];
      v += amplitudes_[ci][i] * std::cos(arg);
      dv -= amplitudes_[ci][i] * omegas_[i] * std::sin(arg);
    }
    out.add(c, v, dv);
  }
  return faded(s, out);
}

IrregularitySample StochasticIrregularity::faded(double s, IrregularitySample raw) const {
  const double fade = spec_.fade_in_length;
  if (fade <= 0.0) return raw;
  const double x = s - spec_.start_s;
  if (x >= fade) return raw;
  if (!(x > 0.0)) return {};
  // w = (1 - cos(pi x / L)) / 2, w' = pi / (2 L) sin(pi x / L); (w r)' = w r' + w' r.
  const double arg = std::numbers::pi * x / fade;
  const double w = 0.5 * (1.0 - std::cos(arg));
  const double dw = 0.5 * std::numbers::pi / fade * std::sin(arg);
  IrregularitySample out;
  for (const auto c : kChannelOrder) {
    out.add(c, w * raw.value(c), w * raw.derivative(c) + dw * raw.value(c));
  }
  return out;
}

double StochasticIrregularity::variance(IrregularityChannel channel) const {
  double sum = 0.0;
  for (const double a : amplitudes_[channel_index(channel)]) sum += 0.5 * a * a;
  return sum;
}

}  // namespace ferro::track
