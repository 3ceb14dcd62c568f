// The bounds no physical state of a model leaves (OdeSystem::state_bounds), from the model's
// geometry: the integrators stop a run whose state crosses one as diverged. They are generous
// on purpose: a run that crosses one has left the track or the model's meaning, whatever the
// tolerance or step that took it there.
//
// Whole vehicle (frames: y left, z up, angles relative to each body's track frame):
//  - wheelset y and z: within twice the flangeway w = (track_gauge - flange_back_distance) / 2,
//    the lateral travel from the centred position at which a flange back reaches the rail's
//    gauge face. At w the whole flange (28-33 mm thick on standard profiles, less than
//    w = 37.5 mm on standard gauge) already stands over the rail head; at 2 w the wheel has
//    crossed it. Lifted by 2 w (more than twice any standard flange height) a wheel is off the
//    rail.
//  - other bodies' x, y, z: within half the track gauge (a centre of mass beyond the rail);
//  - every body angle: within 0.5 rad (29 deg), far beyond any overturning or yaw a body on
//    the track reaches.
// Suspended wheelset (linear model): |y| within the half gauge e (a contact point beyond the
// rail), |psi| within 0.5 rad.
#include <fmt/format.h>

#include "ferro/vehicle/suspended_wheelset.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::vehicle {
namespace {
constexpr double kMaxAngle = 0.5;  // [rad]
}  // namespace

std::vector<StateBound> VehicleModel::state_bounds() const {
  const VehicleConfig& cfg = inputs().config;
  const double gauge = cfg.wheel_rail.track_gauge;
  const double flangeway = 0.5 * (gauge - cfg.wheel_rail.flange_back_distance);
  std::vector<StateBound> out;
  for (const RigidBodySpec& b : cfg.bodies) {
    const bool wheelset = b.kind == BodyKind::wheelset;
    for (int d = 0; d < 6; ++d) {
      const int index = state_index(b.name, static_cast<Dof>(d));
      if (index < 0) continue;
      StateBound bound;
      bound.index = static_cast<std::size_t>(index);
      if (d >= 3) {
        bound.limit = kMaxAngle;
        bound.reason = "a body turned this far has overturned or left the track";
      } else if (wheelset && d > 0 && flangeway > 0.0) {
        bound.limit = 2.0 * flangeway;
        bound.reason = fmt::format(
            "twice the flangeway (track_gauge - flange_back_distance) / 2 = {:.4g} m: the wheel "
            "has crossed the rail head",
            flangeway);
      } else {
        bound.limit = 0.5 * gauge;
        bound.reason = "half the track gauge: the body has left the track";
      }
      out.push_back(std::move(bound));
    }
  }
  return out;
}

std::vector<StateBound> SuspendedWheelset::state_bounds() const {
  return {{0, params().half_gauge, "the half gauge e: the contact point has left the rail"},
          {1, kMaxAngle, "a wheelset turned this far has left the track"}};
}

}  // namespace ferro::vehicle
