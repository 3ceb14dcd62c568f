#pragma once
// What a run of the vehicle model records beyond its states and standard signals: sensors fixed
// to bodies and the in-run anti-alias filters (signals: vehicle_model.hpp). Plain data, SI.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ferro::vehicle {

/// An accelerometer and displacement gauge fixed to a body (signals "<name>.ax", ...; list in
/// vehicle_model.hpp).
struct SensorSpec {
  std::string name;  ///< signal prefix, unique
  std::string body;  ///< a body of the configuration with states in the model
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< from its centre of mass, body axes [m]
  /// Axes whose acceleration goes through the anti-alias filter ("<name>.a<axis>_filtered"):
  /// any of x, y, z.
  std::string filtered_axes = "xyz";
};

/// What a run records beyond the states and the standard signals: sensors, and low-pass
/// filters integrated with the model (extra states after the states of the body they belong
/// to) that remove what a coarse output grid would alias: each wheel's Y and Q and each
/// sensor's accelerations go through a Butterworth low-pass of even order
/// `anti_alias_order` and corner `anti_alias_frequency`, started at their input's steady
/// state by static_equilibrium().
struct OutputSignalsSpec {
  std::vector<SensorSpec> sensors;
  double anti_alias_frequency = 0.0;  ///< [Hz]; 0: no filters (no extra states)
  int anti_alias_order = 4;           ///< 2, 4, 6 or 8
  /// Also every loaded contact point's creep forces, spin moment, wear number, angle, radius,
  /// profile places and peak pressure ("wheelset_i.<side>.point_k.*"; the wheel's sums and
  /// its most loaded point's values are always there).
  bool contact_point_details = false;
};

}  // namespace ferro::vehicle
