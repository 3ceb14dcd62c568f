#include "terminal.hpp"

#include <fmt/format.h>
#include <pthread.h>
#include <semaphore.h>
#include <unistd.h>

#include <atomic>
#include <thread>

#include <algorithm>
#include <filesystem>

#include "ferro/scenarios/output_file.hpp"

namespace ferro::cli {
namespace {
volatile std::sig_atomic_t g_signal = 0;
std::atomic<bool> g_acknowledged{false};
std::atomic<bool> g_guard_done{false};
sem_t g_wake;  // posted by the handler (async-signal-safe) for the watchdog
std::thread g_watchdog;

// Ends the program on signal `sig`: unfinished outputs removed, a line on stderr, 128 + sig.
// Async-signal-safe (unlink, write, _exit).
[[noreturn]] void end_now(int sig) {
  scenarios::remove_pending_outputs();
  const char* text = sig == SIGINT ? "ferrodyn: interrupted by SIGINT; unfinished outputs removed\n"
                                   : "ferrodyn: interrupted by SIGTERM; unfinished outputs removed\n";
  std::size_t n = 0;
  while (text[n] != '\0') ++n;
  [[maybe_unused]] const auto written = write(STDERR_FILENO, text, n);
  _exit(128 + sig);
}

extern "C" void on_signal(int sig) {
  if (g_signal != 0) end_now(sig);  // the second request: at once
  g_signal = sig;
  sem_post(&g_wake);
}

// Waits for a signal; unless the program acknowledges it within the grace, ends the program.
void watchdog() {
  while (sem_wait(&g_wake) != 0) {
  }
  if (g_guard_done.load()) return;
  const int sig = g_signal;
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::duration<double>(InterruptGuard::kStopGrace);
  while (std::chrono::steady_clock::now() < until) {
    if (g_acknowledged.load() || g_guard_done.load()) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (g_acknowledged.load() || g_guard_done.load()) return;
  end_now(sig);
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
  sem_init(&g_wake, 0, 0);
  g_watchdog = std::thread(watchdog);
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
  // A parent (or the launcher) may start the program with these signals blocked: a signal sent
  // meanwhile is pending, and is delivered to the handler now.
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  pthread_sigmask(SIG_UNBLOCK, &stop, nullptr);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
  g_guard_done.store(true);
  sem_post(&g_wake);
  if (g_watchdog.joinable()) g_watchdog.join();
}

void InterruptGuard::acknowledge() { g_acknowledged.store(true); }

int InterruptGuard::signal_received() {
  return g_signal;
}

bool InterruptGuard::stop_now() {
  if (g_signal == 0) return false;
  acknowledge();
  return true;
}

}  // namespace ferro::cli
