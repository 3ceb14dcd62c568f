#pragma once
// What the assessment of a run needs besides its signals, written by `ferrodyn run` into the
// run's HDF5 file (groups /vehicle and /track, attributes of /assessment; docs/OUTPUT.md) and
// read back by `ferrodyn assess`: the vehicle's category, bodies (kind, mass, rest position),
// static axle loads, the design track's sections, and the scene's assessment settings.

#include <string>
#include <vector>

#include "ferro/io/hdf5.hpp"
#include "ferro/scenarios/analysis/track_statistics.hpp"
#include "ferro/vehicle/vehicle_config.hpp"

namespace ferro::scenarios {
struct Scene;
}

namespace ferro::scenarios::analysis {

struct RunBody {
  std::string name;  ///< "car_body", "bogie_1", "wheelset_2", ...
  std::string kind;  ///< car_body | bogie_frame | wheelset
  double mass = 0.0;                        ///< [kg]
  double rest_x = 0.0, rest_y = 0.0, rest_z = 0.0;  ///< rest position of the centre of mass [m]
  double static_load = 0.0;  ///< wheelsets: static axle load P0 [N] (0 for other bodies)
};

struct RunContext {
  std::string vehicle;    ///< vehicle name
  std::string category;   ///< coach | locomotive | power_car | wagon; "" when not given
  double gravity = 9.81;  ///< [m/s^2]
  double friction = 0.0;  ///< wheel-rail mu of the run [-]
  std::vector<RunBody> bodies;
  /// The designed track's sections (empty: straight track without sections).
  std::vector<TrackSection> sections;
  double rail_spacing = 1.5;  ///< distance the cant is measured over [m]
  bool twist_test = false;  ///< the scene says the run is the twist test
  /// The run's in-run anti-alias low-pass (Butterworth): corner [Hz] (0: none) and order.
  double anti_alias_frequency = 0.0;
  int anti_alias_order = 0;
  /// Delay of that low-pass at low frequencies, sum 1/(Q_k w_c) [s] (0 without it): its
  /// outputs at t are its input around t - delay.
  [[nodiscard]] double anti_alias_delay() const;
  [[nodiscard]] const RunBody* body(const std::string& name) const;
};

/// Static axle load of every wheelset of the vehicle [N], by body index (0 for other bodies):
/// each body's weight and the load it receives from the bodies above it (the upper bodies of
/// its suspension elements) go to the bodies below it, shared by the lever rule about the
/// body's centre of mass along x for one or two supports, equally for more.
[[nodiscard]] std::vector<double> static_axle_loads(const vehicle::VehicleConfig& config);

/// The context of a vehicle scene (the whole vehicle's bodies, whatever the model scope).
[[nodiscard]] RunContext run_context(const Scene& scene);

/// Writes /vehicle, /track and /assessment of a run file.
void write_run_context(io::H5File& file, const RunContext& context);

/// Reads them back; a file without /vehicle gives an empty context (bodies empty).
[[nodiscard]] RunContext read_run_context(const io::H5File& file);

/// alpha of the track-shift limit for a category: 0.85 for wagons, 1 otherwise (EN 14363).
[[nodiscard]] double track_shift_alpha(const std::string& category);

}  // namespace ferro::scenarios::analysis
