#pragma once
// Assessment of a vehicle run as EN 14363 / UIC 518 and EN 12299 define it: running safety (Y/Q
// per wheel, track-shift force sum Y per axle), track loading (Q_max, Q_qst, Y_qst, sum Y_max),
// stability (sum Y rms in the band f0 +- 2 Hz, bogie-frame lateral acceleration), ride
// (car-body floor accelerations, N_MV, Sperling's Wz), and, for the twist test only, the wheel
// unloading dQ/Q0. Each quantity is processed as the standard prescribes (20 Hz low-pass, 2 m
// sliding mean, 100 m sliding rms, percentiles per track section) and compared with its limit.
//
// References: EN 14363:2016 and UIC 518 (4th ed., 2009): processing as tabulated on
//   gensys.se/course/UIC518_tests.html (sum Y and Y/Q: low-pass >= 20 Hz, 2 m sliding mean
//   sampled every 0.5 m, 0.15 % / 99.85 % percentiles; Q: 20 Hz, 99.85 %; Y_qst, Q_qst: 50 %;
//   car body: 0.4-10 Hz, percentiles and rms; instability: sum Y in f0 +- 2 Hz, sliding rms);
//   limits: (Y/Q)_lim = 0.8 over 2 m (UIC 518 summary, railwaynews.net); Prud'homme
//   (sum Y)_lim = alpha (10 kN + P0/3), alpha = 1 for locomotives, power cars and coaches, 0.85
//   for wagons; (sum Y_rms)_lim = (sum Y)_lim / 2 over 100 m; bogie frame (12 - m+/5)/2 m/s^2 rms,
//   m+ the bogie mass in t; Q_lim = min(90 kN + Q0, 200 / 190 / 180 / 170 / 160 kN for
//   V <= 160 / 200 / 250 / 300 / > 300 km/h); Q_qst,lim = 145 kN; Y_qst,lim = 60 kN; twist test
//   dQ/Q0 <= 0.6. Nadal's limit (Toumi 2016 eq. 149) as information.
// Known deviations: the limit values other than Y/Q 0.8 and the processing were not checked
//   against the standard's text (not at hand): docs/ANALYSES.md lists which figure comes from
//   where. Filters are Butterworth, order 4, zero phase (forward-backward, corner moved so the
//   combined gain is -3 dB at the nominal corner); Y/Q is the 2 m mean of the ratio of the
//   filtered Y and Q (Q below 1 % of Q0 counts as 1 % of Q0). Positions are those of the body
//   concerned (wheelset, bogie, floor point), not of the vehicle centre. Without acceleration
//   sensors in the run, floor and bogie-frame accelerations are derived from the bodies' rigid
//   motion (rate states differentiated by central differences, plus the measured car_body.ay
//   and the track frame's yaw acceleration).

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ferro/scenarios/analysis/run_context.hpp"
#include "ferro/scenarios/analysis/track_statistics.hpp"

namespace ferro::scenarios::analysis {

/// Nadal's limit Y/Q = (tan g - mu) / (1 + mu tan g) for flange angle g [rad] and friction mu.
[[nodiscard]] double nadal_limit(double flange_angle, double mu);

/// Prud'homme's limit on the track-shift force per axle: alpha (10 kN + P0/3) [N], P0 the static
/// axle load [N].
[[nodiscard]] double prudhomme_limit(double axle_load, double alpha);

/// Limit on the 99.85 % wheel force Q (20 Hz): min(90 kN + Q0, cap(V)) [N], cap 200 kN up to
/// 160 km/h, 190 to 200, 180 to 250, 170 to 300, 160 above; speed [m/s], Q0 [N].
[[nodiscard]] double q_max_limit(double speed, double static_wheel_load);

/// Quasi-static limits in curves [N].
inline constexpr double kQqstLimit = 145.0e3;
inline constexpr double kYqstLimit = 60.0e3;

/// Bogie-frame lateral acceleration limit (12 - m/5)/2 [m/s^2 rms], m the bogie mass [kg].
[[nodiscard]] double bogie_acceleration_limit(double bogie_mass);

struct AssessmentOptions {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double mu = kNaN;                ///< Nadal's friction coefficient; NaN: the run's wheel-rail mu
  double flange_angle = -1.0;      ///< [rad]; < 0: the largest |contact angle| of each wheel
  double lowpass = 20.0;           ///< low-pass corner of forces and quasi-static values [Hz]
  int filter_order = 4;            ///< Butterworth order of every filter (even)
  double window = 2.0;             ///< sliding-mean window [m]
  double step = 0.5;               ///< sliding-mean sampling step [m]
  double stability_window = 100.0; ///< sliding-rms window [m]
  double stability_step = 10.0;    ///< [m]
  double stability_half_band = 2.0;  ///< f0 +- this [Hz]
  double f0 = kNaN;                ///< instability frequency [Hz]; NaN: from the run's spectrum
  double f0_min = 2.0, f0_max = 12.0;  ///< band searched for f0 (bogie hunting) [Hz]
  /// Nadal's limit is shown for wheels whose largest contact angle reaches this (flange
  /// contact) [rad].
  double nadal_min_angle = 45.0 * M_PI / 180.0;
  double ride_low = 0.4, ride_high = 10.0;  ///< car-body band [Hz]
  double floor_offset = 1.0;       ///< lateral offset of the vertical floor points [m]
  double section_length = 0.0;     ///< > 0: windows of this length replace the scene's sections
  double y_over_q_limit = 0.8;     ///< (Y/Q)_lim [-]
  double unloading_limit = 0.6;    ///< twist test (dQ/Q0)_lim [-]
  std::string category;            ///< overrides the run's vehicle category when not empty
  std::optional<bool> twist_test;  ///< overrides the scene's assessment.twist_test
};

enum class Verdict { pass, fail, info };

/// One line of the result table: a statistic of one quantity, for one wheel / axle / body, in
/// one track section.
struct AssessmentRow {
  std::string group;     ///< running safety | track loading | stability | ride | twist test
  std::string quantity;  ///< e.g. "Y/Q 2 m", "sum Y 2 m", "Q max"
  std::string item;      ///< wheel, axle, bogie or floor point, e.g. "wheelset_1.right"
  std::string section;   ///< track section name, or "run"
  std::string unit;      ///< of value, limit, statistics ("-", "N", "m/s^2")
  double value = 0.0;    ///< the statistic compared with the limit
  double limit = std::numeric_limits<double>::quiet_NaN();  ///< NaN: none
  /// Largest |processed value| in the section (the largest value for one-sided statistics:
  /// Q max, dQ/Q0).
  double max_abs = 0.0;
  double position = 0.0;  ///< where that is, at the item concerned [m]
  SectionStatistics stats;  ///< 0.15 / 50 / 99.85 % of the processed signal
  Verdict verdict = Verdict::info;
};

/// A processed signal along the track, written for plots.
struct AssessedSignal {
  std::string quantity;  ///< as in the rows
  std::string item;
  std::string unit;
  std::string description;
  std::vector<double> position;  ///< at the item [m]
  std::vector<double> value;
  double limit = std::numeric_limits<double>::quiet_NaN();  ///< symmetric +- limit line
};

struct Assessment {
  std::string vehicle, category;
  double alpha = 1.0;         ///< track-shift factor [-]
  double mu = 0.0;            ///< in Nadal's limit
  double sample_rate = 0.0;   ///< of the run's output [Hz]
  double f0 = std::numeric_limits<double>::quiet_NaN();  ///< instability frequency [Hz]; NaN:
                                                         ///< stability not assessed
  bool f0_from_spectrum = true;
  bool twist_test = false;
  bool accelerations_derived = false;  ///< some floor/bogie accelerations derived from the
                                       ///< bodies' rigid motion (no sensor in the run)
  bool forces_filtered_in_run = false;  ///< wheel forces through the run's anti-alias filter
  std::vector<TrackSection> sections;
  std::vector<AssessmentRow> rows;
  std::vector<AssessedSignal> signals;
  std::vector<std::string> notes;  ///< what could not be assessed and why
  bool pass = true;                ///< no row fails
};

/// Assesses a run's HDF5 file (kind time_simulation of a vehicle scene). Throws
/// std::invalid_argument naming the file and what is missing or wrong.
[[nodiscard]] Assessment assess_run(const std::string& h5_path, const AssessmentOptions& options);

/// Writes the assessment into a new HDF5 file (kind "assessment"; layout docs/OUTPUT.md).
void write_assessment(const Assessment& a, const std::string& source, const std::string& path);

[[nodiscard]] const char* to_string(Verdict v);

}  // namespace ferro::scenarios::analysis
