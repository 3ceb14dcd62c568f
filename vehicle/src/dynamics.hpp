#pragma once
// The stages of one evaluation of the vehicle model (equations: vehicle_model.hpp): the body
// kinematics in their track frames, the suspension elements (suspension.cpp), the wheel-rail
// coupling (wheel_rail.cpp) and the equations of motion. Each stage reads the model data and
// writes into the workspace.

#include <limits>
#include <span>

#include "model_data.hpp"
#include "workspace.hpp"

namespace ferro::vehicle::detail {

/// What an evaluation returns besides xdot: the per-wheel results (2 per contact body, left
/// first) and the car body's lateral acceleration.
struct EvaluationOutputs {
  WheelResult* wheels = nullptr;  ///< null: not wanted
  double* car_body_ay = nullptr;  ///< null: not wanted
  /// Fill the workspace's pad forces of the flexible track (also done whenever xdot is asked).
  bool pad_forces = false;
};

/// Evaluates the model at (t, x): xdot (may be empty) and the outputs asked for.
/// `speed_override` (finite) replaces the speed profile's V(t) (the static equilibrium's
/// continuation in speed); the track position and dV/dt stay those of t.
void evaluate(const ModelData& m, Workspace& ws, double t, std::span<const double> x,
              std::span<double> xdot, const EvaluationOutputs& outputs = {},
              double speed_override = std::numeric_limits<double>::quiet_NaN());

/// Frame, frame motion and (when `irregular`) irregularities at arc length s.
void frame_at(const ModelData& m, double s, double speed, double rate, BodyKinematics& k,
              bool irregular);

/// Suspension element forces and moments added to the bodies' accumulators; series-damper
/// internal rates written into xdot (when not empty).
void apply_element(const ModelData& m, const ElementData& element,
                   std::vector<BodyKinematics>& kin, const BodyKinematics& track_frame_a,
                   std::span<const double> x, std::span<double> xdot);

/// Wheel-rail forces on one wheelset (added to its accumulators), their reactions on its two
/// rails (`rail_loads`, left and right, added to; may be null on a rigid track) and the
/// per-wheel results (`left_right`, may be null).
void apply_wheel_rail(const ModelData& m, const BodyData& body, BodyKinematics& k,
                      std::span<const double> x, WheelRailScratch& scratch,
                      track::RailLoad* rail_loads, WheelResult* left_right);

/// Position and velocity (ground frame) of a point p given in body axes, and its arm from the
/// body's centre in the axes of the body's track frame (the rotated p; (0, p_y, p_z) for the
/// track frame itself, body == nullptr).
void point_state(const BodyData* body, const BodyKinematics& k, const Eigen::Vector3d& p,
                 Eigen::Vector3d& position, Eigen::Vector3d& velocity, Eigen::Vector3d& arm);

/// Half-bandwidths of the Jacobian from the coupling structure (layout.cpp).
[[nodiscard]] std::pair<int, int> jacobian_bandwidth(const ModelData& m);
/// Structural sparsity of the Jacobian, per column its rows (layout.cpp).
[[nodiscard]] std::vector<std::vector<int>> jacobian_pattern(const ModelData& m);

}  // namespace ferro::vehicle::detail

namespace ferro::vehicle::detail {
/// The signals of signal_info() at (t, x) into `out` (signals.cpp).
void signals(const ModelData& m, Workspace& ws, double t, std::span<const double> x,
             std::span<double> out);
}  // namespace ferro::vehicle::detail
