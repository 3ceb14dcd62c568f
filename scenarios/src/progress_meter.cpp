#include "ferro/scenarios/progress_meter.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace ferro::scenarios {

std::string format_seconds(double s) {
  if (s < 60.0) return fmt::format("{:.1f} s", s);
  return fmt::format("{}m{:02d}s", static_cast<int>(s / 60.0), static_cast<int>(s) % 60);
}

ProgressMeter::ProgressMeter(double t_end, bool redraw) : t_end_(t_end), redraw_(redraw) {}

std::string ProgressMeter::update(double t) {
  return update(t, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
}

std::string ProgressMeter::update(double t, double elapsed) {
  const double frac = std::clamp(t / t_end_, 0.0, 1.0);
  const double eta = frac > 0.0 ? elapsed * (1.0 - frac) / frac : 0.0;
  if (redraw_) {
    if (elapsed < 1.0 || elapsed - last_draw_ < 0.1) return {};
    last_draw_ = elapsed;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(frac * kWidth);
    drawn_ = true;
    return fmt::format("\r[{}{}] {:5.1f}%  t = {:.3g} / {:.3g} s  elapsed {}  ETA {}   ",
                       std::string(static_cast<std::size_t>(filled), '#'),
                       std::string(static_cast<std::size_t>(kWidth - filled), '.'), 100.0 * frac,
                       t, t_end_, format_seconds(elapsed), format_seconds(eta));
  }
  const int decile = static_cast<int>(frac * 10.0 + 1e-9);
  if (elapsed >= 1.0 && decile > last_decile_ && decile < 10) {
    last_decile_ = decile;
    return fmt::format("progress: {}% (t = {:.6g} s of {:.6g} s, elapsed {}, ETA {})\n",
                       decile * 10, t, t_end_, format_seconds(elapsed), format_seconds(eta));
  }
  return {};
}

std::string ProgressMeter::finish() const { return redraw_ && drawn_ ? "\n" : ""; }

}  // namespace ferro::scenarios
