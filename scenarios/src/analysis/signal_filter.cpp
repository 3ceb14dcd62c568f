// Filters of the assessment (see the header for references and known deviations).
#include "ferro/scenarios/analysis/signal_filter.hpp"

#include <fftw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>

namespace ferro::scenarios::analysis {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;

void check_order(int order, double fc, const char* what) {
  if (order < 2 || order % 2 != 0)
    throw std::invalid_argument(fmt::format("{}: order must be even and >= 2, got {}", what, order));
  if (!(fc > 0.0) || !std::isfinite(fc))
    throw std::invalid_argument(fmt::format("{}: corner must be > 0 Hz, got {}", what, fc));
}

// Quality factors of the sections of an order-n Butterworth filter, Q_k = 1/(2 sin((2k-1) pi/2n)).
std::vector<double> butterworth_q(int order) {
  std::vector<double> q;
  for (int k = 1; k <= order / 2; ++k)
    q.push_back(1.0 / (2.0 * std::sin((2.0 * k - 1.0) * M_PI / (2.0 * order))));
  return q;
}

}  // namespace

std::complex<double> AnalogFilter::response(double f) const {
  const std::complex<double> s(0.0, kTwoPi * f);
  std::complex<double> h(gain, 0.0);
  for (const auto& c : sections)
    h *= (c.n2 * s * s + c.n1 * s + c.n0) / (c.d2 * s * s + c.d1 * s + c.d0);
  return h;
}

std::complex<double> DigitalFilter::response(double f) const {
  const std::complex<double> zi = std::exp(std::complex<double>(0.0, -kTwoPi * f / sample_rate));
  std::complex<double> h(1.0, 0.0);
  for (const auto& b : sections)
    h *= (b.b0 + b.b1 * zi + b.b2 * zi * zi) / (1.0 + b.a1 * zi + b.a2 * zi * zi);
  return h;
}

AnalogFilter butterworth_lowpass_analog(int order, double fc) {
  check_order(order, fc, "Butterworth low-pass");
  const double w = kTwoPi * fc;
  AnalogFilter f;
  for (double q : butterworth_q(order))
    f.sections.push_back({0.0, 0.0, 1.0, 1.0 / (w * w), 1.0 / (q * w), 1.0, fc});
  return f;
}

AnalogFilter butterworth_highpass_analog(int order, double fc) {
  check_order(order, fc, "Butterworth high-pass");
  const double w = kTwoPi * fc;
  AnalogFilter f;
  for (double q : butterworth_q(order))
    f.sections.push_back({1.0 / (w * w), 0.0, 0.0, 1.0 / (w * w), 1.0 / (q * w), 1.0, fc});
  return f;
}

AnalogFilter butterworth_bandpass_analog(int order, double f_low, double f_high) {
  if (!(f_high > f_low))
    throw std::invalid_argument(fmt::format(
        "Butterworth band-pass: upper corner {} Hz must exceed the lower {} Hz", f_high, f_low));
  AnalogFilter f = butterworth_highpass_analog(order, f_low);
  const AnalogFilter lp = butterworth_lowpass_analog(order, f_high);
  f.sections.insert(f.sections.end(), lp.sections.begin(), lp.sections.end());
  return f;
}

DigitalFilter bilinear(const AnalogFilter& analog, double sample_rate) {
  if (!(sample_rate > 0.0) || !std::isfinite(sample_rate))
    throw std::invalid_argument(fmt::format("bilinear: sample rate must be > 0 Hz, got {}",
                                            sample_rate));
  DigitalFilter d;
  d.sample_rate = sample_rate;
  for (const auto& c : analog.sections) {
    const double fw = c.warp_frequency;
    if (!(fw > 0.0 && fw < 0.5 * sample_rate))
      throw std::invalid_argument(fmt::format(
          "bilinear: section frequency {} Hz must lie below the Nyquist frequency {} Hz (sample "
          "the signal faster)",
          fw, 0.5 * sample_rate));
    // s = K (z - 1)/(z + 1); multiply numerator and denominator by (z + 1)^2.
    const double k = kTwoPi * fw / std::tan(M_PI * fw / sample_rate), k2 = k * k;
    const double a0 = c.d2 * k2 + c.d1 * k + c.d0;
    Biquad b;
    b.b0 = (c.n2 * k2 + c.n1 * k + c.n0) / a0;
    b.b1 = 2.0 * (c.n0 - c.n2 * k2) / a0;
    b.b2 = (c.n2 * k2 - c.n1 * k + c.n0) / a0;
    b.a1 = 2.0 * (c.d0 - c.d2 * k2) / a0;
    b.a2 = (c.d2 * k2 - c.d1 * k + c.d0) / a0;
    d.sections.push_back(b);
  }
  if (!d.sections.empty()) {
    d.sections.front().b0 *= analog.gain;
    d.sections.front().b1 *= analog.gain;
    d.sections.front().b2 *= analog.gain;
  }
  return d;
}

double zero_phase_lowpass_corner(int order, double fc) {
  check_order(order, fc, "zero-phase low-pass");
  return fc * std::pow(std::sqrt(2.0) - 1.0, -1.0 / (2.0 * order));
}

double zero_phase_highpass_corner(int order, double fc) {
  check_order(order, fc, "zero-phase high-pass");
  return fc * std::pow(std::sqrt(2.0) - 1.0, 1.0 / (2.0 * order));
}

AnalogFilter zero_phase_lowpass(int order, double fc) {
  AnalogFilter f = butterworth_lowpass_analog(order, zero_phase_lowpass_corner(order, fc));
  for (auto& c : f.sections) c.warp_frequency = fc;
  return f;
}

AnalogFilter zero_phase_bandpass(int order, double f_low, double f_high) {
  if (!(f_high > f_low))
    throw std::invalid_argument(fmt::format(
        "zero-phase band-pass: upper corner {} Hz must exceed the lower {} Hz", f_high, f_low));
  AnalogFilter f = butterworth_highpass_analog(order, zero_phase_highpass_corner(order, f_low));
  for (auto& c : f.sections) c.warp_frequency = f_low;
  for (auto c : zero_phase_lowpass(order, f_high).sections) f.sections.push_back(c);
  return f;
}

namespace {

// One pass of the cascade in place (transposed direct form II), each section started at the
// steady state of the constant input x[0] at its entry.
void run_cascade(const DigitalFilter& f, std::vector<double>& x) {
  if (x.empty()) return;
  for (const auto& b : f.sections) {
    const double u = x.front();
    const double dc = (b.b0 + b.b1 + b.b2) / (1.0 + b.a1 + b.a2);
    const double y0 = dc * u;
    double z2 = b.b2 * u - b.a2 * y0;
    double z1 = b.b1 * u - b.a1 * y0 + z2;
    for (double& v : x) {
      const double in = v;
      const double out = b.b0 * in + z1;
      z1 = b.b1 * in - b.a1 * out + z2;
      z2 = b.b2 * in - b.a2 * out;
      v = out;
    }
  }
}

}  // namespace

std::vector<double> filter(const DigitalFilter& f, std::span<const double> x) {
  std::vector<double> y(x.begin(), x.end());
  run_cascade(f, y);
  return y;
}

std::vector<double> filtfilt(const DigitalFilter& f, std::span<const double> x,
                             std::size_t padding) {
  const std::size_t n = x.size();
  if (n == 0) return {};
  const std::size_t p = std::min(padding, n - 1);
  std::vector<double> y;
  y.reserve(n + 2 * p);
  for (std::size_t k = p; k >= 1; --k) y.push_back(2.0 * x[0] - x[k]);
  y.insert(y.end(), x.begin(), x.end());
  for (std::size_t k = 1; k <= p; ++k) y.push_back(2.0 * x[n - 1] - x[n - 1 - k]);
  run_cascade(f, y);
  std::reverse(y.begin(), y.end());
  run_cascade(f, y);
  std::reverse(y.begin(), y.end());
  return {y.begin() + static_cast<long>(p), y.begin() + static_cast<long>(p + n)};
}

std::size_t edge_padding(const AnalogFilter& analog, double sample_rate) {
  // Decay time of a section with natural frequency w and quality Q: 2 Q / w; six of them.
  double longest = 0.0;
  for (const auto& c : analog.sections) {
    const double w = std::sqrt(c.d0 / (c.d2 > 0.0 ? c.d2 : 1.0));
    const double q = c.d2 > 0.0 && c.d1 > 0.0 ? std::sqrt(c.d0 * c.d2) / c.d1 : 1.0;
    longest = std::max(longest, c.d2 > 0.0 ? 2.0 * q / w : c.d1 / c.d0);
  }
  return std::max<std::size_t>(16, static_cast<std::size_t>(std::ceil(6.0 * longest * sample_rate)));
}

namespace {
std::mutex& fftw_planner_mutex() {  // FFTW's planner is not thread-safe
  static std::mutex m;
  return m;
}
}  // namespace

std::vector<double> apply_analog(const AnalogFilter& analog, std::span<const double> x,
                                 double sample_rate, double settle_seconds) {
  const std::size_t n = x.size();
  if (n == 0) return {};
  std::size_t m = 1;
  const auto need = n + static_cast<std::size_t>(std::ceil(std::max(0.0, settle_seconds) *
                                                           sample_rate));
  while (m < need) m <<= 1;
  std::vector<double> buf(m, 0.0);
  const double x0 = x[0];
  for (std::size_t i = 0; i < n; ++i) buf[i] = x[i] - x0;
  std::vector<std::complex<double>> spec(m / 2 + 1);
  auto* cspec = reinterpret_cast<fftw_complex*>(spec.data());
  fftw_plan fwd, inv;
  {
    std::lock_guard lock(fftw_planner_mutex());
    fwd = fftw_plan_dft_r2c_1d(static_cast<int>(m), buf.data(), cspec, FFTW_ESTIMATE);
    inv = fftw_plan_dft_c2r_1d(static_cast<int>(m), cspec, buf.data(), FFTW_ESTIMATE);
  }
  fftw_execute(fwd);
  for (std::size_t k = 0; k < spec.size(); ++k) {
    const double f = sample_rate * static_cast<double>(k) / static_cast<double>(m);
    std::complex<double> h = analog.response(f);
    // The Nyquist bin of a real record is real: keep the real part of the response there.
    if (2 * k == m) h = std::complex<double>(h.real(), 0.0);
    spec[k] *= h;
  }
  fftw_execute(inv);
  {
    std::lock_guard lock(fftw_planner_mutex());
    fftw_destroy_plan(fwd);
    fftw_destroy_plan(inv);
  }
  const double dc = analog.response(0.0).real() * x0;
  std::vector<double> y(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = buf[i] / static_cast<double>(m) + dc;
  return y;
}

}  // namespace ferro::scenarios::analysis
