#pragma once
// Terminal helpers of the command line: progress display and SIGINT/SIGTERM capture.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include "ferro/scenarios/progress_meter.hpp"

namespace ferro::cli {

/// Progress of a run against simulated time, printed on `out` (scenarios::ProgressMeter: a bar
/// redrawn in place on a TTY, else a plain line at each 10 % step).
class Progress {
 public:
  Progress(double t_end, std::FILE* out);
  void update(double t);
  void finish();

 private:
  std::FILE* out_;
  scenarios::ProgressMeter meter_;
  std::chrono::steady_clock::time_point start_;
};

/// SIGINT and SIGTERM for the whole program, installed first thing in run_main. A stop request is
/// honoured within kStopGrace seconds wherever the program is:
///  - code that polls signal_received() and stops at once (a run between two integrator steps,
///    plotting) calls acknowledge() (or polls stop_now()) and the verb ends in order;
///  - otherwise (a computation that does not poll) a watchdog thread ends the program when the
///    grace has passed: it removes the temporary files of unfinished outputs (output_file.hpp),
///    says so on stderr and exits with 128 + signal. A second signal ends it so at once.
class InterruptGuard {
 public:
  static constexpr double kStopGrace = 0.4;  ///< [s]
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  /// The stop was seen and the program is stopping in order (no forced exit).
  static void acknowledge();
  /// 0, or the number of the signal received.
  [[nodiscard]] static int signal_received();
  /// signal_received() != 0, acknowledging it: for code that stops at once when it sees it.
  [[nodiscard]] static bool stop_now();

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

}  // namespace ferro::cli
