#include "terminal.hpp"

#include <fmt/format.h>
#include <pthread.h>
#include <semaphore.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

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

}  // namespace

scenarios::ProgressMeter stderr_meter(double t_end) {
  return {t_end, isatty(fileno(stderr)) != 0};
}

void show_progress(const std::string& text) {
  if (text.empty()) return;
  fmt::print(stderr, "{}", text);
  std::fflush(stderr);
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
