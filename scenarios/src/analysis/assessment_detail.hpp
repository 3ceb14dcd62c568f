#pragma once
// Internals shared by the assessment's source files: the run's signals on a uniform time grid,
// the designed filters, and the rows-per-section bookkeeping.

#include <functional>
#include <string>
#include <vector>

#include "ferro/io/hdf5.hpp"
#include "ferro/scenarios/analysis/assessment.hpp"
#include "ferro/scenarios/analysis/signal_filter.hpp"

namespace ferro::scenarios::analysis::detail {

/// The run's samples on its uniform output grid (a last sample off the grid is dropped).
class RunSignals {
 public:
  explicit RunSignals(const std::string& path);
  [[nodiscard]] bool has(const std::string& name) const;
  /// The signal, n() samples; throws std::invalid_argument naming the file and signal.
  [[nodiscard]] std::vector<double> get(const std::string& name) const;
  /// The signal, or zeros when the run does not have it (a frozen degree of freedom).
  [[nodiscard]] std::vector<double> get_or_zero(const std::string& name) const;
  [[nodiscard]] std::size_t n() const { return time.size(); }
  [[nodiscard]] const io::H5File& file() const { return file_; }

  /// The reference point's position at t - delay (the place a signal delayed by `delay` [s]
  /// belongs to); before the run's start extrapolated at the initial speed.
  [[nodiscard]] std::vector<double> position_before(double delay) const;
  /// A force or acceleration signal and its place: `<name>_filtered` (the run's anti-alias
  /// low-pass) at the positions `delay` earlier when the run has it, else `<name>` at the
  /// reference positions. `filtered` tells which.
  struct Located {
    std::vector<double> value, position;
    bool filtered = false;
  };
  [[nodiscard]] Located located(const std::string& name, double delay) const;

  std::string path;
  std::vector<double> time, position, speed;
  double sample_rate = 0.0;

 private:
  io::H5File file_;
};

/// A zero-phase filter designed for the run's sampling rate.
struct ZeroPhase {
  DigitalFilter digital;
  std::size_t padding = 0;
  [[nodiscard]] std::vector<double> operator()(const std::vector<double>& x) const;
};
[[nodiscard]] ZeroPhase zero_phase_lowpass(int order, double fc, double sample_rate);
[[nodiscard]] ZeroPhase zero_phase_bandpass(int order, double f_low, double f_high,
                                            double sample_rate);

/// Time derivative by central differences (one-sided at the ends).
[[nodiscard]] std::vector<double> derivative(const std::vector<double>& t,
                                             const std::vector<double>& x);

/// Positions of a point at `offset` [m] from the vehicle reference point.
[[nodiscard]] std::vector<double> shifted(const std::vector<double>& position, double offset);

/// Which statistic of a section is compared with the limit.
enum class Statistic { extreme, high, median_abs, max_abs, rms };

/// A row for the whole run (not per section), information only.
void add_run_row(Assessment& a, const std::string& group, const std::string& quantity,
                 const std::string& item, const std::string& unit, double value);

/// Adds one row per section holding samples of (position, value) to `a`. `limit` gives the
/// limit of a section (NaN: information only); `only_curves` skips sections that are not curves;
/// with `judged` false the limit is shown for information and gives no verdict.
void add_rows(Assessment& a, const std::string& group, const std::string& quantity,
              const std::string& item, const std::string& unit,
              const std::vector<double>& position, const std::vector<double>& value,
              Statistic statistic, const std::function<double(const TrackSection&)>& limit,
              bool only_curves = false, bool judged = true);

/// Ride: floor accelerations and comfort of the car body (assessment_ride.cpp).
void assess_ride(Assessment& a, const RunSignals& run, const RunContext& context,
                 const AssessmentOptions& options);

/// The design track at arc length s: curvature [1/m], cant angle [rad] and its slope [rad/m]
/// (linear curvature and cant in transitions, EN 13803).
struct DesignPoint {
  double curvature = 0.0, cant_angle = 0.0, d_cant_angle = 0.0;
};
[[nodiscard]] DesignPoint design_point(const std::vector<TrackSection>& sections,
                                       double rail_spacing, double s);

}  // namespace ferro::scenarios::analysis::detail
