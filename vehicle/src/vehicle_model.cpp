// VehicleModel: the model data built once, its workspace, and the OdeSystem interface over the
// evaluation stages (dynamics.cpp, suspension.cpp, wheel_rail.cpp, signals.cpp). The speed
// profile.
//
// References: see vehicle_model.hpp.
// Known deviations: see vehicle_model.hpp.

#include "ferro/vehicle/vehicle_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynamics.hpp"
#include "output_signals.hpp"

namespace ferro::vehicle {

double SpeedProfile::speed(double t) const { return std::max(0.0, initial + acceleration * t); }

double SpeedProfile::rate(double t) const {
  return initial + acceleration * t > 0.0 || (initial == 0.0 && acceleration > 0.0) ? acceleration
                                                                                     : 0.0;
}

double SpeedProfile::distance(double t) const {
  if (acceleration >= 0.0 || initial + acceleration * t > 0.0) {
    return initial * t + 0.5 * acceleration * t * t;
  }
  // Decelerating to a stop at t_stop = -initial / acceleration.
  return -0.5 * initial * initial / acceleration;
}

VehicleModel::VehicleModel(VehicleModelInputs inputs)
    : data_(detail::build_model_data(std::move(inputs))),
      workspace_(std::make_unique<detail::Workspace>()) {}

VehicleModel::~VehicleModel() = default;

std::size_t VehicleModel::size() const { return data_->n_states; }

int VehicleModel::rhs(double t, std::span<const double> x, std::span<double> xdot) const {
  try {
    detail::evaluate(*data_, *workspace_, t, x, xdot);
  } catch (const std::out_of_range&) {
    // The vehicle left the designed track or a contact table's range. A trial state of the
    // integrator's corrector may do so while the solution does not: recoverable (the step is
    // cut); a solution that really leaves it still stops the run after repeated failures. Any
    // other exception reaches the integrator, which stops the run with its message.
    return kRhsRecoverable;
  }
  for (double v : xdot) {
    // A trial state far from the solution (a corrector iterate) may give a non-finite
    // derivative; the step is cut as for a pose outside the table.
    if (!std::isfinite(v)) return kRhsRecoverable;
  }
  return kRhsOk;
}

std::vector<SignalInfo> VehicleModel::state_info() const { return data_->states; }
std::vector<SignalInfo> VehicleModel::signal_info() const { return data_->signal_list; }

void VehicleModel::signals(double t, std::span<const double> x, std::span<double> out) const {
  detail::signals(*data_, *workspace_, t, x, out);
}

std::vector<std::vector<int>> VehicleModel::jacobian_pattern() const {
  return detail::jacobian_pattern(*data_);
}

std::pair<int, int> VehicleModel::jacobian_bandwidth() const {
  return detail::jacobian_bandwidth(*data_);
}

std::vector<std::size_t> VehicleModel::output_states() const {
  return detail::output_state_indices(*data_);
}

std::vector<double> VehicleModel::tolerance_scales() const {
  const detail::ModelData& m = *data_;
  if (!m.track) return {};
  std::vector<double> scale(m.n_states, 1.0);
  const track::CoRunningTrackParams& p = *m.track;
  // Each rate: the natural frequency of its body held by its pads (rails) or by its pads and
  // ballast (sleeper), the others fixed.
  const double rail[3] = {
      std::sqrt(p.pad_stiffness_lateral / p.rail_mass_lateral),
      std::sqrt(p.pad_stiffness_vertical / p.rail_mass_vertical),
      std::sqrt((p.pad_stiffness_roll +
                 p.pad_stiffness_lateral * p.rail_base_depth * p.rail_base_depth) /
                p.rail_roll_inertia)};
  const double s2 = p.rail_seat_half_spacing * p.rail_seat_half_spacing;
  const double sleeper[3] = {
      std::sqrt((p.ballast_stiffness_lateral + 2.0 * p.pad_stiffness_lateral) / p.sleeper_mass_lateral),
      std::sqrt(2.0 * (p.ballast_stiffness_vertical + p.pad_stiffness_vertical) / p.sleeper_mass_vertical),
      std::sqrt(2.0 * (p.ballast_stiffness_vertical + p.pad_stiffness_vertical) * s2 /
                p.sleeper_roll_inertia)};
  for (const detail::BodyData& b : m.bodies) {
    if (b.track < 0) continue;
    for (int j = 0; j < track::kTrackPositions; ++j) {
      scale[static_cast<std::size_t>(b.track + track::kTrackPositions + j)] =
          j < 6 ? rail[j % 3] : sleeper[j % 3];
    }
  }
  return scale;
}

std::vector<double> VehicleModel::rest_state() const {
  return std::vector<double>(data_->n_states, 0.0);
}

std::size_t VehicleModel::wheelset_count() const { return data_->contact_bodies.size(); }

int VehicleModel::state_index(const std::string& body, Dof dof) const {
  for (const detail::BodyData& b : data_->bodies) {
    if (b.name == body) return b.q[static_cast<std::size_t>(dof)];
  }
  return -1;
}

int VehicleModel::rate_index(const std::string& body, Dof dof) const {
  for (const detail::BodyData& b : data_->bodies) {
    if (b.name == body) return b.v[static_cast<std::size_t>(dof)];
  }
  return -1;
}

const VehicleModelInputs& VehicleModel::inputs() const { return data_->in; }

}  // namespace ferro::vehicle
