#include "terminal.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

namespace ferro::cli {
namespace {
volatile std::sig_atomic_t g_signal = 0;
bool g_claimed = false;
extern "C" void on_signal(int sig) {
  g_signal = sig;
}

std::string format_seconds(double s) {
  if (s < 60.0) return fmt::format("{:.1f} s", s);
  return fmt::format("{}m{:02d}s", static_cast<int>(s / 60.0), static_cast<int>(s) % 60);
}
}  // namespace

Progress::Progress(double t_end, std::FILE* out)
    : t_end_(t_end),
      out_(out),
      tty_(isatty(fileno(out)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void Progress::update(double t) {
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double frac = std::clamp(t / t_end_, 0.0, 1.0);
  const double eta = frac > 0.0 ? elapsed * (1.0 - frac) / frac : 0.0;
  if (tty_) {
    if (elapsed < 1.0 || std::chrono::duration<double>(now - last_draw_).count() < 0.1) return;
    last_draw_ = now;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(frac * kWidth);
    fmt::print(out_, "\r[{}{}] {:5.1f}%  t = {:.3g} / {:.3g} s  elapsed {}  ETA {}   ",
               std::string(static_cast<std::size_t>(filled), '#'),
               std::string(static_cast<std::size_t>(kWidth - filled), '.'), 100.0 * frac, t, t_end_,
               format_seconds(elapsed), format_seconds(eta));
    std::fflush(out_);
    drawn_ = true;
    return;
  }
  const int decile = static_cast<int>(frac * 10.0 + 1e-9);
  if (elapsed >= 1.0 && decile > last_decile_ && decile < 10) {
    last_decile_ = decile;
    fmt::print(out_, "progress: {}% (t = {:.6g} s of {:.6g} s, elapsed {}, ETA {})\n", decile * 10,
               t, t_end_, format_seconds(elapsed), format_seconds(eta));
    std::fflush(out_);
  }
}

void Progress::finish() {
  if (tty_ && drawn_) fmt::print(out_, "\n");
}

InterruptGuard::InterruptGuard() {
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
  // A parent may start the program with these signals blocked: a signal sent meanwhile is
  // pending, and is delivered to the handler now.
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  sigprocmask(SIG_UNBLOCK, &stop, nullptr);
}

InterruptGuard::~InterruptGuard() {
  if (installed_) {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
}

void InterruptGuard::release() {
  if (!installed_) return;
  installed_ = false;
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
  if (g_signal != 0) std::raise(g_signal);
}

void InterruptGuard::claim() { g_claimed = true; }
bool InterruptGuard::claimed() { return g_claimed; }

int InterruptGuard::signal_received() {
  return g_signal;
}

}  // namespace ferro::cli
