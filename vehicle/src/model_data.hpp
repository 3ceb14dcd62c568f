#pragma once
// The read-only data of a VehicleModel, built once from its inputs (model_build.cpp) and shared
// by every evaluation: bodies with their place in the state, suspension elements, the contact
// mechanics (tangential model, K_ij, material, semi-Hertz pair), state and signal names. Nothing
// here changes after construction; the per-evaluation scratch is the Workspace (workspace.hpp).
// Equations and conventions: vehicle_model.hpp.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/contact/normal/semi_hertz.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/track/track_structure.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::vehicle::detail {

/// One body of the configuration with its place in the state.
struct BodyData {
  std::string name;
  BodyKind kind = BodyKind::car_body;
  double mass = 0.0;
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();  ///< roll, pitch, yaw [kg m^2]
  Eigen::Vector3d rest = Eigen::Vector3d::Zero();     ///< rest position; x is the frame offset
  double r0 = 0.0;                                    ///< wheelsets: nominal rolling radius [m]
  bool dynamic = false;      ///< has at least one state
  bool has_contact = false;  ///< wheelset in the selection: wheel-rail forces are computed
  std::array<int, 6> q{-1, -1, -1, -1, -1, -1};  ///< position state per DOF
  std::array<int, 6> v{-1, -1, -1, -1, -1, -1};  ///< rate state per DOF
  int spin = -1;                                 ///< spin perturbation state
  /// Wheelsets on a flexible track: first state of the co-running track under it
  /// (track::kTrackPositions positions, then their rates); -1 on a rigid track.
  int track = -1;
  int block_begin = 0, block_end = 0;            ///< state range incl. series-damper states
  /// First state of the output filters this body hosts (output_signals.cpp), -1: none.
  int output_filters = -1;
};

struct ElementData {
  SuspensionElementSpec spec;
  int a = -1, b = -1;  ///< indices into ModelData::bodies (-1: track frame)
  int state = -1;      ///< series damper internal deflection
  /// Relative position point_b - point_a on straight track at rest, track axes [m].
  Eigen::Vector3d rest_vector = Eigen::Vector3d::Zero();
};

/// Everything the wheel-rail stage reads besides the geometry source.
struct ContactMechanics {
  std::unique_ptr<contact::TangentialModel> tangential;
  contact::Material material;
  double contact_modulus = 0.0;
  contact::ReductionFactors reduction;
  /// K_ij from a table (wheel_rail.reduction_table), looked up per contact patch; empty: the
  /// constants `reduction`.
  std::optional<contact::KijPatchLookup> reduction_table;
  /// wheel_rail.normal = semi_hertz: the geometry source's profiles, whose gap around each
  /// contact point the semi-Hertz model reads; nullptr: Hertz from the point's curvatures.
  const contact::WheelRailPair* semi_hertz_pair = nullptr;
  contact::SemiHertzOptions semi_hertz_options;
};

/// A sensor with its body's model index; `filter[a]` is the first state of the anti-alias
/// filter of its acceleration along axis a (-1: not filtered).
struct SensorData {
  SensorSpec spec;
  int body = -1;
  std::array<int, 3> filter{-1, -1, -1};
};

/// The anti-alias low-pass: a cascade of order/2 sections y'' + (w/Q_k) y' + w^2 y = w^2 u, each
/// with two states (y_k, y_k'); a channel's states are contiguous.
struct OutputFilterData {
  int order = 0;  ///< 0: no filters
  double omega = 0.0;          ///< corner [rad/s]
  std::vector<double> inv_q;   ///< 1/Q_k of the sections
  [[nodiscard]] int states_per_channel() const { return order; }
};

struct ModelData {
  VehicleModelInputs in;
  std::vector<BodyData> bodies;  ///< in state order (decreasing rest x)
  std::vector<ElementData> elements;
  std::vector<int> contact_bodies;  ///< bodies with wheel-rail contact, front first
  int car_body = -1;
  std::size_t n_states = 0;
  std::vector<SignalInfo> states, signal_list;
  ContactMechanics contact;
  double nominal_rail_spacing = 1.5;
  /// The co-running track under every contact wheelset (track structure `discrete`); empty on a
  /// rigid track.
  std::optional<track::CoRunningTrackParams> track;
  std::vector<SensorData> sensors;
  OutputFilterData output_filter;
};

/// Builds and validates the model data (std::invalid_argument naming the field).
[[nodiscard]] std::shared_ptr<const ModelData> build_model_data(VehicleModelInputs inputs);

/// Attitude R = Rz(yaw) Ry(pitch) Rx(roll) of the angles (roll, pitch, yaw).
[[nodiscard]] Eigen::Matrix3d attitude_matrix(const Eigen::Vector3d& angles);

}  // namespace ferro::vehicle::detail
