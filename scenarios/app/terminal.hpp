#pragma once
// Terminal helpers of the command line: progress display and SIGINT/SIGTERM capture.
#include <csignal>
#include <string>

#include "ferro/scenarios/progress_meter.hpp"

namespace ferro::cli {

/// A progress meter for stderr (a bar redrawn in place on a terminal, else a plain line at each
/// 10 % step), starting now; its text goes to show_progress().
[[nodiscard]] scenarios::ProgressMeter stderr_meter(double t_end);
/// Prints a meter's text on stderr at once (nothing for an empty text).
void show_progress(const std::string& text);

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
