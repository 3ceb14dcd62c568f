#pragma once
// Output signals a run records beyond the states and the standard signals
// (OutputSignalsSpec): sensors fixed to bodies (accelerometer readings and displacements), and
// the anti-alias low-pass filters integrated with the model, whose states sit in the state
// block of the body they belong to (a wheelset's wheel forces, a sensor's body).

#include <span>

#include "ferro/contact/normal/contact_patch.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/vehicle/frames.hpp"
#include "model_data.hpp"
#include "workspace.hpp"

namespace ferro::vehicle::detail {

/// Adds one patch of a contact point to the point's totals (its tangential forces and spin
/// moment, the wear number of its creepages, its largest patch's semi-axes and peak pressure).
void add_patch(PointTotals& totals, const contact::ContactPatch& patch,
               const contact::TangentialProblem& problem, const contact::TangentialSolution& tang);

/// Records a loaded point into its wheel's result, as point w.points (call before counting it)
/// and as the most loaded point when it carries more than the wheel's largest so far.
void record_point(WheelResult& w, const contact::WheelRailContact& c, const PointTotals& totals,
                  double normal_force);

/// Records the wheelset's yaw relative to a rail (side 0 left, 1 right) into that wheel's
/// result, or relative to both (side -1, the rails displaced alike) into both.
void record_pose(WheelResult* left_right, const RailRelativePose& rel, int side);

/// Validates m.in.outputs and resolves the sensors' bodies (after the bodies are ordered).
/// Throws std::invalid_argument naming the field ("outputs.sensors[1].body: ...").
void resolve_output_signals(ModelData& m);

/// Places the output filters body `i` hosts from state index `next` on; returns the next free
/// index. Called while the states are laid out, after the body's own states.
[[nodiscard]] int lay_out_output_filters(ModelData& m, std::size_t i, int next);

/// Names of the filter states (m.states already sized) and of the output signals (appended to
/// m.signal_list).
void name_output_states(ModelData& m);
void name_output_signals(ModelData& m);

/// The filters' rates into xdot, from the wheel results of this evaluation (2 per contact body)
/// and the bodies' accumulated forces (the evaluation's kinematics and forces in `ws`).
void output_filter_rates(const ModelData& m, const Workspace& ws, const WheelResult* wheels,
                         std::span<const double> x, std::span<double> xdot);

/// The output signals (name_output_signals order) into `out`, after an evaluation at (t, x).
/// Returns the number written.
std::size_t output_signal_values(const ModelData& m, const Workspace& ws,
                                 std::span<const double> x, std::span<double> out);

/// Indices of every filter state, increasing.
[[nodiscard]] std::vector<std::size_t> output_state_indices(const ModelData& m);

/// Sets every filter's states to the steady state of its input at (t, x): outputs equal to the
/// input, rates zero.
void set_output_filters_steady(const ModelData& m, Workspace& ws, double t,
                               std::span<double> x);

}  // namespace ferro::vehicle::detail
