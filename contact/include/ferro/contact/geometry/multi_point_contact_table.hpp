#pragma once
// The precomputed multi-point contact table (the default contact geometry source): every
// candidate point per wheel over lateral shift and roll (yaw optional), penetration online from
// the vertical position.
//
// References: see wheel_rail_geometry.hpp (search) and MultiPointContactTable below.
// Known deviations: see MultiPointContactTable below.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::contact {

/// Grid of a MultiPointContactTable. Each axis is uniform; an axis with min == max (step
/// ignored) is absent. SI units.
struct MultiPointTableParams {
  /// [m]; the pose's lateral shift is measured in the axes of the rail as it lies, so a rail
  /// rolled by theta adds theta times the axle's height above it (0.46 m): +-20 mm holds the flange
  /// contact of S1002 (from ~7 mm) with the rails rolled by up to ~20 mrad under flange forces
  /// (the 10 mm alignment defect at 400 km/h rolls them by 11 mrad).
  double lateral_min = -0.020;
  double lateral_max = 0.020;    ///< [m]
  double lateral_step = 0.1e-3;  ///< [m]
  /// [rad]; the wheelset's roll relative to the rail as it lies: the rails' own roll under flange
  /// forces (11 mrad under the 10 mm alignment defect at 400 km/h) adds to the wheelset's.
  double roll_min = -0.020;
  double roll_max = 0.020;       ///< [rad]
  /// [rad]; 0.25 mrad: on S1002 / UIC60 1:40 the two tread lobes 11 mm apart change their gap
  /// difference by 11 um per mrad of relative roll, a fifth of the Hertz approach, so a branch
  /// born inside a 1 mrad cell fades in over a quarter of the approach; on a flexible track,
  /// whose rails roll by up to ~2 mrad under the wheels, 1 mrad cells put wheel loads up to
  /// 33 kN off the search's along a run, 0.25 mrad cells 4.6 kN (mean 1 kN against 74 N).
  double roll_step = 0.25e-3;
  double yaw_min = 0.0;          ///< [rad]
  double yaw_max = 0.0;          ///< [rad]
  double yaw_step = 0.005;       ///< [rad]
  /// Candidates kept per wheel and node, the deepest first (<= kMaxPointsPerWheel).
  int max_points_per_wheel = 4;
  /// Candidates whose reference gap exceeds the wheel's deepest by more than this are dropped:
  /// they would touch only after the deepest point penetrated this far [m].
  double capture_depth = 2.0e-3;
  /// Throws std::invalid_argument naming the field.
  void validate() const;
};

/// Precomputed multi-point contact geometry over lateral shift, roll (and yaw, optional).
///
/// Build: at every grid node the wheelset is placed at vertical = 0 and every candidate point of
/// each wheel (local minimum of the section gap, tread and flange; candidate_points()) is stored
/// with its vertical gap at that reference, its barrier to the previous candidate, and its
/// geometry (point, profile coordinates, contact angle, rolling radius, curvatures A, B).
/// Look-up: vertical gaps are affine in the vertical position, so the gap at the actual pose is
/// the interpolated reference gap minus pose.vertical; penetration = -gap cos(contact angle).
/// Penetrating candidates joined by a submerged barrier share their depth as search_contacts()
/// does (share_joined_runs(): continuous in the pose).
///
/// Branches. Interpolation is per candidate branch, never across branches, so a jump of the
/// contact (tread to flange) gives two points near the jump, each with its own geometry, and
/// never a fake point between them. Matching across the corners of a grid cell: for each pair of
/// corners that differ along one axis, the candidates of one wheel (ordered by wheel-profile
/// coordinate) are aligned order-preservingly at minimum cost, a match costing the distance in
/// wheel-profile coordinate and an unmatched candidate kBranchMatch (so two candidates further
/// apart than 2 kBranchMatch are never one branch); the links are closed over the cell, the
/// closest first, leaving out a link that would give a branch two candidates at one corner (the
/// edges of a cell may disagree where the contact races along the profile, more so across a yaw
/// axis), so each branch keeps the links it agrees with. A branch present at every corner is multilinearly interpolated; a branch present at
/// only some corners (born or dying inside the cell) is interpolated from those corners alone
/// (weights renormalised) and fades in or out with W, the interpolation weight those corners
/// carry: it gets the load share S(W) = 3 t^2 - 2 t^3, t = (W - 1/4) / (1/2) clamped to [0, 1]
/// (C1 smoothstep over the middle half of the weight: 0 below W = 1/4, 1 above W = 3/4 and for a
/// branch present at every corner, so the branch is used at most 3/4 of a cell from its
/// corners and cells without such a branch are answered as before). Its penetration is the
/// Hertz approach at which it carries S times the force of its full approach (approach
/// S^(2/3), F ~ approach^1.5 at fixed curvatures), so its normal force, ellipse and the
/// tangential forces that follow them fade with it, and in a joined run its excess counts S
/// times (RunMember::share). S(W) + S(1 - W) = 1: where the contact races along the flange root
/// (the root branch dies over the corners where the flange branch is born), the two hand the
/// load over with shares summing to one, and the wheel's force is continuous in the pose.
/// The gap (and the barrier) also uses the gap's exact gradient over lateral shift, roll and yaw
/// stored per candidate (the gap is a minimum, so its derivative is the partial derivative at the
/// minimising wheel point): a full branch takes sum_c w_c (g_c + grad g_c . (q - q_c) / 2) with
/// the multilinear weights w_c, exact for quadratic gaps (error third order in the step); a
/// partial branch takes the full first-order Taylor value from its corners, so it is
/// extrapolated, not held constant.
///
/// References: see wheel_rail_geometry.hpp (search).
/// Known deviations: (multi)linear interpolation of the point's geometry along each branch
/// (error ~ step^2 times its second derivative);
/// a branch born or dying inside a cell fades over the cell instead of appearing where it is
/// born, and its gap is extrapolated to first order from its corners: where the point races
/// along the flange root the load is spread over the root and flange points, each with its
/// own geometry, and the wheel's normal force is continuous but not exact inside the cell
/// (S1002 / UIC60, 0.1 mm x 1 mrad cells: median 12 % off the search's across one such cell,
/// whose own Hertz force steps there); in a joined run
/// of three or more members a fading inner member still steps its neighbours' depths when it
/// vanishes (share_joined_runs());
/// the barrier of a candidate that follows candidates dropped by max_points_per_wheel or
/// capture_depth takes the gradient of the barrier or gap it was folded from;
/// where the point races along the flange root (several mm per cell) its position is that of
/// the nearer node's branch (up to ~2 mm off); an absent axis (min == max) is not looked at (a
/// table without a yaw axis answers at any yaw as at yaw_min); poses outside the grid throw (no
/// extrapolation).
class MultiPointContactTable final : public ContactGeometrySource {
 public:
  static constexpr int kMaxPointsPerWheel = 6;
  static constexpr double kBranchMatch = 1.0e-3;  ///< [m] on the wheel profile

  /// Stored per candidate and node.
  struct Candidate {
    Side side = Side::right;
    double gap = 0.0;  ///< vertical gap at vertical = 0 [m]
    double barrier =
        0.0;  ///< largest gap to the previous candidate of the wheel, at vertical = 0 [m]
    double x = 0.0, y = 0.0, z = 0.0;             ///< point on the rail, track frame [m]
    double wheel_y = 0.0, rail_y = 0.0;           ///< profile coordinates [m]
    double contact_angle = 0.0;                   ///< [rad]
    double rolling_radius = 0.0;                  ///< [m]
    double curvature_a = 0.0, curvature_b = 0.0;  ///< [1/m]
    /// Gradient of `gap` over the grid axes at the node (exact, envelope theorem) [m, m/rad].
    double dgap_dlateral = 0.0, dgap_droll = 0.0, dgap_dyaw = 0.0;
    /// Gradient of `barrier` over the grid axes, at the barrier's own section (same theorem:
    /// the barrier is a maximum over sections of per-section minima) [m, m/rad].
    double dbarrier_dlateral = 0.0, dbarrier_droll = 0.0, dbarrier_dyaw = 0.0;
  };

  /// Tabulates `pair` on the grid (about 0.1 ms per node).
  static MultiPointContactTable build(const WheelRailPair& pair,
                                      const MultiPointTableParams& params);
  /// True when `path` is an HDF5 multi-point table written by another format version (a cache
  /// to rebuild); false for the current version and for any other file.
  static bool is_table_of_another_version(const std::string& path);
  /// Reads a table written by save_hdf5; throws std::invalid_argument naming the file/dataset.
  static MultiPointContactTable load_hdf5(const std::string& path);
  /// Writes the grid as attributes, /node_offset [n_nodes + 1] and /candidates [n x 18]
  /// (columns: side (0 left, 1 right), then the Candidate fields in order; SI).
  void save_hdf5(const std::string& path) const;

  [[nodiscard]] std::string_view name() const override { return "table"; }
  /// The pair the table was built from, when attached (make_contact_source() attaches it; a
  /// table read alone from its file has none).
  [[nodiscard]] const WheelRailPair* profile_pair() const override { return pair_.get(); }
  void attach_pair(std::shared_ptr<const WheelRailPair> pair) { pair_ = std::move(pair); }
  /// Every penetrating point of both wheels (left first, each in increasing wheel_y). Throws
  /// std::out_of_range naming the axis when the pose lies outside the grid. No allocation once
  /// `out` holds 2 kMaxPointsPerWheel entries; well under 1 us.
  using ContactGeometrySource::contacts;
  void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out,
                ContactScratch& scratch) const override;
  /// Every interpolated candidate (penetrating or not, before the runs are merged), for tests
  /// and plots.
  void candidates(const WheelsetPose& pose, std::vector<WheelRailContact>& out) const;
  [[nodiscard]] bool in_range(const WheelsetPose& pose) const;
  [[nodiscard]] const MultiPointTableParams& params() const { return params_; }
  /// FNV-1a hash of what a table is built from (both profiles as read, the pair parameters and
  /// the grid): tells whether a cached file still belongs to its inputs.
  [[nodiscard]] static std::uint64_t fingerprint(const WheelRailPair& pair,
                                                 const MultiPointTableParams& params);
  [[nodiscard]] std::uint64_t fingerprint() const { return fingerprint_; }
  [[nodiscard]] std::size_t node_count() const { return node_offset_.size() - 1; }
  [[nodiscard]] std::size_t candidate_count() const { return nodes_.size(); }
  /// Candidates of node (lateral index i, roll index j, yaw index k).
  [[nodiscard]] std::pair<const Candidate*, const Candidate*> node(int i, int j, int k) const;

 private:
  struct Axis {
    double min = 0.0, step = 1.0;
    int n = 1;
  };
  struct Group {
    Side side = Side::right;
    std::array<int, 8> corner{-1, -1, -1, -1, -1, -1, -1, -1};  ///< candidate index or -1
  };
  MultiPointTableParams params_;
  std::shared_ptr<const WheelRailPair> pair_;
  std::uint64_t fingerprint_ = 0;
  std::array<Axis, 3> axes_{};  // lateral, roll, yaw
  std::vector<std::size_t> node_offset_;
  std::vector<Candidate> nodes_;
  std::vector<std::size_t> cell_offset_;
  std::vector<Group> groups_;
  void finish();
  [[nodiscard]] std::size_t node_index(int i, int j, int k) const;
  template <class Emit>
  void interpolate(const WheelsetPose& pose, Emit&& emit) const;
};

}  // namespace ferro::contact
