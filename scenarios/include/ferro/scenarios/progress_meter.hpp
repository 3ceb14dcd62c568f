#pragma once
// The progress text of a run against simulated time, for a program to print: on a terminal a
// bar with the ETA, redrawn in place (it starts with '\r'), shown once the run has lasted a
// second and at most every 0.1 s; otherwise a plain line at each 10 % step after the first
// second.

#include <chrono>
#include <string>

namespace ferro::scenarios {

class ProgressMeter {
 public:
  /// `t_end` [s] the simulated time of the whole run; `redraw` true for a terminal. The run
  /// starts now.
  ProgressMeter(double t_end, bool redraw);
  /// The text to print at simulated time `t` [s], `elapsed` [s] wall time since the start; empty
  /// when nothing is to be printed now.
  [[nodiscard]] std::string update(double t, double elapsed);
  /// update(t, the wall time since the meter was made).
  [[nodiscard]] std::string update(double t);
  /// The text that ends the display: a newline after a drawn bar, else empty.
  [[nodiscard]] std::string finish() const;

 private:
  double t_end_;
  bool redraw_;
  double last_draw_ = 0.0;  ///< elapsed time of the last bar [s]
  int last_decile_ = 0;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// "12.3 s" under a minute, else "4m05s".
[[nodiscard]] std::string format_seconds(double seconds);

}  // namespace ferro::scenarios
