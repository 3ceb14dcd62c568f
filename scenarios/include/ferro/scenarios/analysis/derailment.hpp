#pragma once
// Derailment assessment of a time simulation: per wheel Y, Q and Y/Q, their 2 m sliding mean
// along the track, Nadal's flange-climb limit from the flange angle reached and the friction
// coefficient, the sum of Y per axle against Prud'homme's track-shift limit, and the wheel
// unloading dQ/Q0.
//
// References: Toumi 2016, eq. (149) (Nadal), section 4 (Y/Q limits: 2 m mean <= 1.2
//   quasi-static, 0.8 dynamic); EN 14363 (2 m sliding mean sampled every 0.5 m, Prud'homme's
//   sum-Y limit 0.85 (10 kN + P/3), wheel unloading dQ/Q0 <= 0.6).
// Known deviations: the sliding mean integrates the piecewise-linear interpolant of the samples
//   over the position (exact for linear signals); the Nadal limit uses the largest contact
//   angle each wheel reaches in the run (or a given flange angle), not a per-sample angle; Q0 is
//   the wheel load of the first sample unless given.

#include <string>
#include <vector>

namespace ferro::scenarios::analysis {

/// Nadal's limit Y/Q = (tan g - mu) / (1 + mu tan g) for flange angle g [rad] and friction mu.
[[nodiscard]] double nadal_limit(double flange_angle, double mu);

/// Prud'homme's limit on the sum of Y per axle: 0.85 (10 kN + P/3) [N], P = axle load [N].
[[nodiscard]] double prudhomme_limit(double axle_load);

/// A signal averaged over a window sliding along the track.
/// Most means a sliding mean computes (the covered length / step).
inline constexpr double kMaxSlidingMeanPoints = 1e7;

struct SlidingMean {
  std::vector<double> position;  ///< window centres [m]
  std::vector<double> mean;      ///< window averages [signal unit]
};

/// Mean of `values` over windows [s - window/2, s + window/2] of the position, for centres s
/// every `step` from position.front() + window/2 to position.back() - window/2. `position` must
/// be non-decreasing (a vehicle at rest repeats its position: those samples carry no length).
/// Throws std::invalid_argument for mismatched sizes, a decreasing position, non-positive
/// window or step, or a track shorter than the window.
[[nodiscard]] SlidingMean sliding_mean(const std::vector<double>& position,
                                       const std::vector<double>& values, double window = 2.0,
                                       double step = 0.5);

struct DerailmentOptions {
  double mu = 0.36;               ///< wheel-rail friction coefficient in Nadal's formula [-]
  double flange_angle = -1.0;     ///< [rad]; < 0: the largest |contact angle| of each wheel
  double window = 2.0;            ///< sliding-mean window [m]
  double step = 0.5;              ///< sliding-mean sampling step [m]
  double unloading_limit = 0.6;   ///< dQ/Q0 limit [-]
  double wheel_load_static = -1;  ///< Q0 [N]; < 0: each wheel's Q at the first sample
};

struct WheelAssessment {
  std::string name;                 ///< "wheelset_1.left"
  double max_y_over_q = 0.0;        ///< peak of the sliding mean of Y/Q [-]
  double max_y_over_q_position = 0.0;  ///< where [m]
  double max_y_over_q_raw = 0.0;    ///< peak of the unfiltered Y/Q [-]
  double flange_angle = 0.0;        ///< angle used in Nadal's limit [rad]
  double nadal = 0.0;               ///< Nadal's limit [-]; NaN when tan(angle) <= mu (no flange
                                    ///< contact: the wheel cannot climb)
  double q0 = 0.0;                  ///< static wheel load [N]
  double max_unloading = 0.0;       ///< max (Q0 - Q)/Q0 [-]
  double max_unloading_position = 0.0;  ///< [m]
  bool pass_nadal = true;
  bool pass_unloading = true;
  SlidingMean y_over_q_mean;        ///< the 2 m mean along the track
};

struct AxleAssessment {
  std::string name;                 ///< "wheelset_1"
  double axle_load = 0.0;           ///< P = Q0_left + Q0_right [N]
  double limit = 0.0;               ///< Prud'homme [N]
  double max_sum_y = 0.0;           ///< peak |sliding mean of Y_left + Y_right| [N]
  double max_sum_y_position = 0.0;  ///< [m]
  bool pass = true;
  SlidingMean sum_y_mean;
};

struct DerailmentReport {
  std::vector<WheelAssessment> wheels;
  std::vector<AxleAssessment> axles;
  double mu = 0.0;
  bool pass = true;  ///< every wheel and axle passes
};

/// Time series of one wheel, as read from a run.
struct WheelSeries {
  std::string name;
  std::vector<double> lateral;        ///< Y [N]
  std::vector<double> vertical;       ///< Q [N]
  std::vector<double> contact_angle;  ///< [rad]
};

/// Assessment from series sampled at `position`; wheels come in (left, right) pairs per axle,
/// named "wheelset_<i>.left" / ".right".
[[nodiscard]] DerailmentReport assess_derailment(const std::vector<double>& position,
                                                 const std::vector<WheelSeries>& wheels,
                                                 const DerailmentOptions& options);

/// Reads signals `position` and `wheelset_<i>.<left|right>.{Y,Q,contact_angle}` (i = 1, 2, ...
/// while present) from a run's HDF5 file and assesses them. Throws std::invalid_argument naming
/// the file and the missing signal.
[[nodiscard]] DerailmentReport assess_derailment_file(const std::string& h5_path,
                                                      const DerailmentOptions& options);

/// Writes the report under /derailment of a new HDF5 file (kind "derailment_assessment").
void write_derailment_report(const DerailmentReport& report, const std::string& source,
                             const std::string& path);

}  // namespace ferro::scenarios::analysis
