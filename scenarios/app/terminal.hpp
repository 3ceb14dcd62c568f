#pragma once
// Terminal helpers of the command line: progress display and SIGINT/SIGTERM capture.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

namespace ferro::cli {

/// Progress of a run against simulated time. On a TTY: a bar with ETA redrawn in place, shown
/// once the run has lasted a second. Otherwise: a plain log line at each 10 % step.
class Progress {
 public:
  Progress(double t_end, std::FILE* out);
  void update(double t);
  void finish();

 private:
  double t_end_;
  std::FILE* out_;
  bool tty_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  int last_decile_ = 0;
  bool drawn_ = false;
};

/// Installs SIGINT and SIGTERM handlers for its lifetime; the run polls signal_received().
/// run_main installs one before anything else, so a signal that comes while a scene loads is
/// kept for the run to see; a verb that does not poll calls release() to restore the default
/// handlers (re-raising a signal received meanwhile).
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  /// Restores the previous handlers now; re-raises a signal received while installed.
  void release();
  /// Called by a verb that polls signal_received(), before run_main decides to release.
  static void claim();
  [[nodiscard]] static bool claimed();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  /// 0, or the number of the signal received.
  [[nodiscard]] static int signal_received();

 private:
  bool installed_ = true;
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

}  // namespace ferro::cli
