#pragma once
// Implementations of ContactGeometrySource, their factory, and the normal contact the dynamics
// computes from their points:
// - MultiPointContactTable: precomputed, every candidate point per wheel over lateral shift and
//   roll (yaw optional), penetration online from the vertical position (default source);
// - SearchContactSource: the online 3D contact search of wheel_rail_geometry.hpp at every call;
// - ImportedContactTable: a one-point table of another tool (CSV, reference Hertz state);
// - ConicalContactSource: analytic conical wheels on knife-edge rail crowns (linear studies);
// - make_contact_source(): builds one of them from a ContactSourceSpec;
// - hertz_patch_from_penetration(): normal force, semi-axes and peak pressure of one point from
//   its penetration, through the one Hertz implementation of hertz.hpp or, for imported tables,
//   from the point's reference Hertz state;
// - semi_hertz_patches_from_penetration(): the semi-Hertz patches of one point of a source with
//   profiles (table, search), from the gap of the profiles around it.
//
// Conical geometry (contact-layer frame: y right, z down; side sign s = +1 right, -1 left).
// Each wheel is a cone of conicity gamma whose radius is r0 at the nominal contact point, lateral
// distance e from the axle centre, decreasing outwards: r(y_w) = r0 + gamma e - s gamma y_w
// (y_w along the axle, wheelset frame). The rail is reduced to its crown line at track
// y = s e, z = 0 (top of rail). The lowest point of each wheel circle lies straight below the
// axle in the wheelset frame, so at roll phi the section y_w touching the crown line solves
// y_c + y_w cos(phi) - r(y_w) sin(phi) = s e (linear in y_w); the vertical gap is
// -(z_c + y_w sin(phi) + r(y_w) cos(phi)) with z_c = -r0 + vertical. At zero roll this gives the
// rolling radii r0 +- gamma y of linear theory. The normal is the cone's generator normal rolled
// with the wheelset: contact angle atan(gamma) - s phi (+ towards the track centre).
//
// References: Wickens, "Fundamentals of Rail Vehicle Dynamics" (2003) ch. 2 (conical wheelset,
// rolling radii r0 +- gamma y, roll coefficient); Toumi (2016) eqs. (5)-(13) (Hertz), eq. (151)
// (Klingel); Johnson, "Contact Mechanics" (1985) eqs. (3.64)-(3.72).
// Known deviations: conical source: the contact point on the rail is fixed at the crown line
// (knife-edge rail, the given curvatures A, B only set the Hertz ellipse), yaw does not move the
// points (x = 0; first-order exact for small yaw), no flange. Search source: allocates (the
// search builds its candidate lists), about 0.1 ms per call; use the tables in long runs.

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ferro/contact/contact_patch.hpp"
#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/contact/normal_model.hpp"
#include "ferro/contact/semi_hertz.hpp"

namespace ferro::contact {

/// Normal contact of one point from its penetration (WheelRailContact::penetration [m]):
/// - with a reference state (imported tables): F_n = F0 (d/d0)^1.5, a = a0 (F_n/F0)^(1/3),
///   b = b0 (F_n/F0)^(1/3), p0 = 3 F_n / (2 pi a b); contact_modulus is not used;
/// - otherwise from the curvatures A, B through hertz_solve_from_approach() (exact Hertz,
///   conformal/negative curvature treated as hertz_curvatures() documents), E* = contact_modulus
///   [Pa].
/// penetration <= 0 (wheel lift): F_n = 0, a = b = p0 = 0 (no tangential model must be called).
/// The patch carries approach = penetration and the curvatures used (NaN for reference states).
/// No allocation; about 0.1 us. Throws std::invalid_argument on NaN input (field named).
[[nodiscard]] ContactPatch hertz_patch_from_penetration(const WheelRailContact& contact,
                                                        double contact_modulus);

/// Buffers of semi_hertz_patches_from_penetration(), reused from call to call (one per thread).
struct SemiHertzScratch {
  NormalProblem problem;
  SemiHertzWorkspace work;
  NormalSolution solution;
  std::vector<double> left, right;  ///< gap samples either side of the point [m]
};

/// Semi-Hertz normal contact of one point of a profile-based source (pair, pose: the ones the
/// source answered for). The undeformed gap along the normal of the point's contact plane
/// (inclined by its contact angle; ContactPlaneGap, in the wheel section through the point) is
/// sampled outwards from the point every b/16 (b: the point's Hertz semi-axis, step kept in
/// [2 um, 0.25 mm]) until, on each side, the gap exceeds its lowest value by 1.1 penetrations,
/// a profile ends, or the gap rises and falls again by more than 1 um (a barrier: the next local
/// minimum is another point of the source, so each point keeps its own basin and a joined run is
/// split at its barrier). semi_hertz_solve_from_approach() then gives the patches (usually one;
/// strips, equivalent ellipse, load) at the point's penetration, with A = the point's
/// curvature_a and its curvature_b as the first estimate of B_ref; each patch carries
/// approach = penetration. Returns scratch.solution (no patch
/// when penetration <= 0). No allocation once the scratch buffers have grown. Throws
/// std::invalid_argument on NaN penetration and where semi_hertz_solve() does (e.g. the basin's
/// minimum on a profile end), std::runtime_error where a profile ends at the point.
/// Known deviations: the gap is that of the wheel section through the point (x = 0; the
/// longitudinal curvature is the point's A, eq. 17); the point keeps the position, normal and
/// creepages the source gives (the patch centre's offset from the point, y_center, is not
/// applied).
[[nodiscard]] NormalSolution& semi_hertz_patches_from_penetration(
    const WheelRailPair& pair, const WheelsetPose& pose, const WheelRailContact& contact,
    const Material& material, const SemiHertzOptions& options, SemiHertzScratch& scratch);

/// WheelRailContact of a search point (profile coordinates and gap carried over).
[[nodiscard]] WheelRailContact to_wheel_rail_contact(const ContactPoint& point);

/// Online 3D search: every penetrating point of both wheels (one per connected run of
/// interpenetration, tread and flange), exactly as search_contacts(). Allocates per call.
class SearchContactSource final : public ContactGeometrySource {
 public:
  explicit SearchContactSource(std::shared_ptr<const WheelRailPair> pair);
  [[nodiscard]] std::string_view name() const override { return "search"; }
  void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out) const override;
  [[nodiscard]] const WheelRailPair& pair() const { return *pair_; }
  [[nodiscard]] const WheelRailPair* profile_pair() const override { return pair_.get(); }

 private:
  std::shared_ptr<const WheelRailPair> pair_;
};

/// Parameters of the analytic conical wheelset. SI units.
struct ConicalContactParams {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double conicity = kNaN;               ///< gamma = tan(cone half-angle) [-], in [0, 1)
  double contact_half_distance = kNaN;  ///< e: lateral distance of each contact point [m]
  double nominal_radius = kNaN;         ///< r0: rolling radius at the centred position [m]
  double curvature_a = kNaN;            ///< A, longitudinal relative curvature [1/m] (> 0)
  double curvature_b = kNaN;            ///< B, lateral relative curvature [1/m] (> 0)
  /// Throws std::invalid_argument naming the field and the allowed range.
  void validate() const;
};

/// Analytic conical wheels (see the file comment). Two points at most, no allocation.
class ConicalContactSource final : public ContactGeometrySource {
 public:
  explicit ConicalContactSource(const ConicalContactParams& params);
  [[nodiscard]] std::string_view name() const override { return "conical"; }
  void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out) const override;
  /// The point of one wheel whether or not it penetrates (vertical_gap > 0: separated).
  [[nodiscard]] WheelRailContact wheel_point(const WheelsetPose& pose, Side side) const;
  [[nodiscard]] const ConicalContactParams& params() const { return params_; }

 private:
  ConicalContactParams params_;
};

/// Grid of a MultiPointContactTable. Each axis is uniform; an axis with min == max (step
/// ignored) is absent. SI units.
struct MultiPointTableParams {
  /// [m]; the pose's lateral shift is measured in the axes of the rail as it lies, so a rail
  /// rolled by theta adds theta times the axle's height above it (0.46 m): +-15 mm holds the flange
  /// contact of S1002 (from ~-7 mm) with the rails rolled by up to ~7 mrad under flange forces.
  double lateral_min = -0.015;
  double lateral_max = 0.015;    ///< [m]
  double lateral_step = 0.1e-3;  ///< [m]
  double roll_min = -0.012;      ///< [rad]
  double roll_max = 0.012;       ///< [rad]
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
/// apart than 2 kBranchMatch are never one branch); the links are closed transitively over the
/// cell. A branch present at every corner is multilinearly interpolated; a branch present at
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
    double gap = 0.0;      ///< vertical gap at vertical = 0 [m]
    double barrier = 0.0;  ///< largest gap to the previous candidate of the wheel, at vertical = 0 [m]
    double x = 0.0, y = 0.0, z = 0.0;  ///< point on the rail, track frame [m]
    double wheel_y = 0.0, rail_y = 0.0;  ///< profile coordinates [m]
    double contact_angle = 0.0;          ///< [rad]
    double rolling_radius = 0.0;         ///< [m]
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
  void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out) const override;
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

/// One-point contact table imported from another tool, in the CSV layout of
/// data/cooperrider_wagon/ (README.md there): one row per wheelset lateral displacement, the
/// columns lateral_displacement_m, normal_force_N, contact_angle_rad, semi_axis_a_longitudinal_m,
/// semi_axis_b_lateral_m, wheel_contact_lateral_position_m, rolling_radius_m, kalker_c11,
/// kalker_c22, kalker_c23, rail_contact_vertical_position_m, penetration_m,
/// rail_contact_lateral_position_m (the last one is read and ignored).
///
/// The file's frame is the source tool's: y LEFT, z UP, and the table describes the LEFT wheel
/// as a function of the displacement y towards it; the right wheel reads the table at -y. The
/// conversion to the contact layer's frame (y right, z down) happens here and only here:
/// y_file = -pose.lateral, z_file = -pose.vertical; roll is the same rotation in both frames
/// (+ lowers the right wheel). So the left wheel reads the table at -pose.lateral and the right
/// wheel at +pose.lateral.
///
/// Each column is a natural cubic spline in y through all rows. pose.vertical and pose.roll are
/// deviations from the table's quasi-static state at that y (the state in which each wheel
/// carries the table's N0 at approach q0), as the source tool defines them. The extra approach
/// along the normal (file frame, a, r, delta the table's lever arm, rolling radius and contact
/// angle of that wheel, phi the roll, z = -pose.vertical):
///   left:  e = (r - a tan phi) sin phi + a / cos phi - a - r phi,
///          dq = -e sin(delta + phi) - (z + a phi) cos(delta + phi);
///   right: e = (r + a tan phi) sin phi - a / cos phi + a - r phi,
///          dq = +e sin(delta - phi) - (z - a phi) cos(delta - phi).
/// The point carries penetration = q0 + dq and the reference state (N0, q0, a0, b0), so that
/// hertz_patch_from_penetration() gives N = N0 (1 + dq/q0)^1.5 and a, b scaled by (N/N0)^(1/3);
/// C11, C22, C23 are passed through. Contact angle in the track frame: delta + phi (left),
/// delta - phi (right), + towards the track centre. Point: x = 0, y = pose.lateral -+ a (left,
/// right), z = -(rail contact vertical position) (below top of rail).
///
/// References: DYTSI (D. Bigoni, DTU, 2011-2014) as restated in data/cooperrider_wagon/
/// wagon.yaml (normal law, penetration change, lookup and mirror convention); de Boor, "A
/// Practical Guide to Splines" (natural cubic spline).
/// Known deviations: the source tool drops a point whose table or dynamic force is below 1 N;
/// here every point with q0 + dq > 0 is reported (the force goes continuously to zero).
class ImportedContactTable final : public ContactGeometrySource {
 public:
  /// Reads and checks the CSV file (std::invalid_argument with file:line: column on bad input).
  explicit ImportedContactTable(const std::string& csv_path);
  [[nodiscard]] std::string_view name() const override { return "imported"; }
  /// Both wheels (left first, at most one point each). Throws std::out_of_range naming the file
  /// and the limit when |pose.lateral| exceeds lateral_limit() (the source tool stops such a run
  /// as a derailment). No allocation once `out` holds 2 entries.
  void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out) const override;
  /// The point of one wheel whether or not it penetrates (penetration may be <= 0).
  [[nodiscard]] WheelRailContact wheel_point(const WheelsetPose& pose, Side side) const;
  /// |y| limit of the table: the magnitude of its first lateral value [m].
  [[nodiscard]] double lateral_limit() const { return limit_; }
  [[nodiscard]] bool in_range(const WheelsetPose& pose) const {
    return std::abs(pose.lateral) <= limit_;
  }
  /// Knots (file rows) and the spline of column `column` (1 .. 11: normal_force_N ..
  /// penetration_m, in file order) at file-frame displacement y [m].
  [[nodiscard]] const std::vector<double>& lateral() const;
  [[nodiscard]] double column(int column, double y_file) const;
  [[nodiscard]] const std::vector<double>& column_values(int column) const;
  static constexpr int kColumns = 13;

 private:
  struct Data;  // knots and one natural cubic spline per column
  std::shared_ptr<const Data> data_;
  std::string path_;
  double limit_ = 0.0;
};

/// What make_contact_source() builds. SI units; files as paths (relative to the working
/// directory; callers resolve them against their own base directory first).
struct ContactSourceSpec {
  /// "table" (multi-point table, default), "search" (online 3D search), "imported" (one-point
  /// CSV table), "conical" (analytic cone).
  std::string kind = "table";
  std::string wheel_profile;   ///< table, search: wheel profile file (read_profile)
  /// table, search: when finite, the wheel's tread is replaced by a cone of this conicity from
  /// wheel_tread_join_y on (splice_conical_tread(); the thesis' 1/10 variant) [-, m].
  double wheel_tread_conicity = std::numeric_limits<double>::quiet_NaN();
  double wheel_tread_join_y = std::numeric_limits<double>::quiet_NaN();
  std::string rail_profile;    ///< table, search: rail profile file (read_profile)
  WheelRailPairParams pair;    ///< table, search
  MultiPointTableParams table; ///< table: grid
  /// table: HDF5 cache. Read when it exists and was built from the same profiles, pair and grid
  /// (fingerprint attribute); otherwise built and written there. Empty: built in memory only.
  std::string table_file;
  std::string imported_table;     ///< imported: CSV file
  ConicalContactParams conical;   ///< conical
};

/// The allowed values of ContactSourceSpec::kind.
inline constexpr std::array<std::string_view, 4> kContactSourceKinds{"table", "search",
                                                                     "imported", "conical"};

/// Builds the source `spec` asks for. Throws std::invalid_argument naming the field (e.g.
/// "ContactSourceSpec.kind: 'x' is not one of table, search, imported, conical") or the file.
[[nodiscard]] std::shared_ptr<const ContactGeometrySource> make_contact_source(
    const ContactSourceSpec& spec);

}  // namespace ferro::contact
