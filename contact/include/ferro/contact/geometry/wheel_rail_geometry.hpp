#pragma once
// Wheelset-on-track contact geometry: the read-only wheel/rail pair model, the wheelset pose,
// the 3D contact search (every contact point on both wheels, tread and flange), the vertical
// load solve with a Hertzian stiffness, the rigid (both wheels touching) solve, and the
// undeformed gap sampled around a contact point for semi-Hertzian and MIM solvers.
//
// Frames. Track frame: x forward, y lateral to the RIGHT, z DOWN (SIMPACK / Manchester benchmark
// convention). The right rail and right wheel use their profiles as read; the left ones are
// mirrored (y -> -y). Wheelset frame and pose: wheelset_pose.hpp (R = Rz(yaw) Rx(roll), axle
// centre at y = lateral, z = -r0 + vertical).
//
// Search method: each wheel is cut into lateral sections (circles of radius r(y_w)); on each
// circle the point of smallest vertical distance to the (prismatic) rail is found by Newton's
// method on the circle angle, which places the contact ahead of or behind the axle under yaw
// (the flange contact leads). Local minima of this section gap over y_w are the candidate
// points (refined by parabolic interpolation), so tread + flange contact give two points; where
// a submerged barrier joins two candidates into one penetrating run, they share its depth
// continuously (share_joined_runs()).
//
// References: Shabana, Zaazaa & Sugiyama, "Railroad Vehicle Dynamics" (2008) ch. 4 (wheel and
// rail surface geometry, contact angle, rolling radius); Toumi (2016) eqs. (1), (5)-(16)
// (gap, Hertz, curvatures A = cos(gamma)/(2 r) and B from the transverse radii); Johnson,
// "Contact Mechanics" (1985) eq. (4.39) (Hertz approach with complete elliptic integrals);
// Shackleton & Iwnicki, VSD 46 (2008) (Manchester benchmark conventions).
// Hertz's solution (normal load from the approach, ellipse) is hertz.hpp's, with its one treatment
// of conformal/negative curvature (hertz_curvatures()).
// Known deviations: penetration is measured vertically per section and converted to the normal
// by cos(gamma) (the usual "vertical interpenetration" approximation, good while the penetration
// is small against the profile radii); the wheel's longitudinal curvature ignores yaw (A uses
// cos(gamma)/r); rails are prismatic (no rail roll or lateral bending).

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "ferro/contact/geometry/profile.hpp"
#include "ferro/contact/geometry/profile_curve.hpp"
#include "ferro/contact/geometry/wheelset_pose.hpp"

namespace ferro::contact {

/// Track / wheelset data of a wheel-rail pair. SI units.
struct WheelRailPairParams {
  double track_gauge = std::numeric_limits<double>::quiet_NaN();  ///< [m]
  double gauge_depth = 0.014;  ///< depth of the gauge measurement below top of rail [m]
  double flange_back_distance = std::numeric_limits<double>::quiet_NaN();  ///< [m]
  /// Lateral position of the flange back in wheel-profile coordinates [m]; NaN: the profile's
  /// smallest y. EN 13715 profiles: -0.070.
  double flange_back_y = std::numeric_limits<double>::quiet_NaN();
  double nominal_radius = std::numeric_limits<double>::quiet_NaN();  ///< r0 at y_w = 0 [m]
  double rail_inclination = 0.0;  ///< applied to the rail profile as read [rad] (0: as read)
  double grid_step = 0.05e-3;     ///< resampling step of the profile tables [m]
  double section_step = 0.5e-3;   ///< lateral spacing of wheel sections in the search [m]
  /// Throws std::invalid_argument naming the offending field.
  void validate() const;
};

/// Read-only model of one wheel profile on one rail profile, used on both sides (mirrored).
class WheelRailPair {
 public:
  WheelRailPair(const Profile& wheel, const Profile& rail, const WheelRailPairParams& params);

  [[nodiscard]] const WheelRailPairParams& params() const { return params_; }
  [[nodiscard]] const Profile& wheel_profile() const { return wheel_profile_; }
  [[nodiscard]] const Profile& rail_profile() const { return rail_profile_; }  ///< inclined
  [[nodiscard]] const ProfileCurve& wheel() const { return wheel_; }
  [[nodiscard]] const ProfileCurve& rail() const { return rail_; }
  [[nodiscard]] const RailReference& rail_reference() const { return rail_ref_; }
  /// Wheelset-frame lateral position of the right wheel's profile origin [m].
  [[nodiscard]] double wheel_offset() const { return wheel_offset_; }
  /// Track-frame lateral position of the right rail's profile origin [m].
  [[nodiscard]] double rail_offset() const { return rail_offset_; }
  /// Wheel radius at wheel-profile coordinate y_w [m].
  [[nodiscard]] double wheel_radius(double y_w) const {
    return params_.nominal_radius + wheel_.z(y_w) - wheel_z0_;
  }
  /// Rail surface height (track z, down) at rail-profile coordinate y_r: top of rail at 0 [m].
  [[nodiscard]] double rail_height(double y_r) const { return rail_.z(y_r) - rail_ref_.top_z; }

 private:
  WheelRailPairParams params_;
  Profile wheel_profile_, rail_profile_;
  ProfileCurve wheel_, rail_;
  RailReference rail_ref_;
  double wheel_offset_ = 0.0, rail_offset_ = 0.0, wheel_z0_ = 0.0;
};

/// One contact point (or candidate point when its vertical_gap is positive).
struct ContactPoint {
  Side side = Side::right;
  double x = 0.0, y = 0.0, z = 0.0;  ///< point on the rail surface, track frame [m]
  double wheel_y = 0.0;              ///< lateral coordinate on the wheel profile [m]
  double rail_y = 0.0;               ///< lateral coordinate on the rail profile [m]
  double wheel_angle = 0.0;  ///< angle of the point on the wheel circle from straight down [rad]
  /// Contact angle [rad]: inclination of the rail surface at the point, positive when the
  /// contact normal leans towards the track centre (flange contact ~ +70 deg). The Manchester
  /// benchmark's results use the opposite sign on the gauge face.
  double contact_angle = 0.0;
  double rolling_radius = 0.0;  ///< wheel radius at the point [m]
  double curvature_a = 0.0;     ///< A, longitudinal: gap ~ A x^2 + B s^2 [1/m]
  double curvature_b = 0.0;     ///< B, lateral (in the contact plane) [1/m]; <= 0: conformal
  double vertical_gap = 0.0;    ///< vertical separation, negative = interpenetration [m]
  double penetration = 0.0;     ///< normal interpenetration max(0, -gap cos(gamma)) [m]
  double barrier = std::numeric_limits<double>::infinity();  ///< largest section gap between
                                                             ///< this and the previous candidate on
                                                             ///< the same wheel [m]
  /// Where the barrier is (a finite barrier only): the nearest point of the barrier's section on
  /// the rail surface, track frame [m], and the rail's contact angle there [rad].
  double barrier_x = 0.0, barrier_y = 0.0, barrier_z = 0.0, barrier_angle = 0.0;
  double normal_force = 0.0;                                 ///< set by solve_vertical_load [N]
  [[nodiscard]] bool on_flange() const { return contact_angle > kFlangeAngle; }
  static constexpr double kFlangeAngle = 0.5236;  ///< 30 deg: above it the point is "flange"
};

/// All candidate points (local minima of the section gap) of one wheel, in increasing wheel_y;
/// minima whose gap exceeds `max_gap` [m] are skipped (not refined). A skipped candidate's
/// barrier is folded into the next one's.
[[nodiscard]] std::vector<ContactPoint> candidate_points(
    const WheelRailPair& pair, const WheelsetPose& pose, Side side,
    double max_gap = std::numeric_limits<double>::infinity());

/// The candidate with the smallest vertical gap (the first touching point of a wheel). Throws
/// std::invalid_argument when `candidates` is empty.
[[nodiscard]] const ContactPoint& deepest_candidate(const std::vector<ContactPoint>& candidates);

/// One candidate as the joined-run rule sees it: its wheel, its vertical gap and its barrier to
/// the previous candidate of the same wheel (a wheel's first candidate: +infinity), at the
/// reference vertical position [m].
struct RunMember {
  Side side = Side::right;
  double gap = 0.0;
  double barrier = std::numeric_limits<double>::infinity();
  /// Load share of a member that fades in or out (a table's branch born or dying inside a grid
  /// cell), in (0, 1]; its excess counts this much in the run's weights.
  double share = 1.0;
};

/// Effective vertical gaps of candidates joined into runs, at a drop `drop` [m] below the
/// reference. `members` holds the candidates of both wheels, left first, each wheel in increasing
/// wheel_y; `effective_gap` receives one value per member (negative: the member carries load).
///
/// A barrier below the rail (depth D = drop - barrier > 0) joins its two neighbours into one run:
/// the penetrating stretch between them is one patch. Member i of a run, at depth d_i = drop -
/// gap_i, with D_i the deeper of its two adjacent submerged barriers, excess e_i = d_i - D_i >= 0
/// and weight w_i = e_i / sum_run e, penetrates by d_i - (1 - w_i) D_i^2 / d_i. (D_i is taken
/// deeper by the search's 1 um prominence, min(D_i, 1 um), so that a minimum which the search
/// starts to report once it is 1 um below its barrier enters with no depth.) So:
/// - a barrier just submerging (D -> 0) leaves every member's depth and its rate unchanged (the
///   correction is second order in D), so the run's stiffness does not step as it joins;
/// - a member merging with its barrier (e_i -> 0, a minimum that vanishes) carries nothing and
///   the others get their full depth back;
/// - two members whose depths cross swap nothing (the rule is symmetric);
/// - deeper in, the depths grow at a rate between w_i and 1 each: from two contacts' stiffness
///   when the barrier just submerges towards one contact's when the run is one flat patch
///   (D -> d, members sharing d by their weights).
/// A member with share s < 1 (fading in or out) counts s e_i in place of e_i in the weights, so
/// its partners get their full depth back as it fades out.
/// Every effective gap is therefore continuous in the pose, where keeping only the deepest member
/// jumps by the members' distance when their depths cross. An unjoined member keeps gap - drop.
/// Known deviation: a run is one non-Hertzian patch in reality; sharing its depth among Hertzian
/// members is a regularisation of the multi-Hertzian kind (as virtual-penetration methods reduce
/// the penetration), not a patch solution. In a run of three or more members the rule stays
/// continuous except where an inner member vanishes (its two barriers fold into one).
void share_joined_runs(const RunMember* members, int count, double drop, double* effective_gap);

/// Contact points at `pose`: every penetrating candidate of each wheel, both wheels (left
/// first, then right, each in increasing wheel_y); candidates joined by a submerged barrier share
/// their depth as share_joined_runs() says.
[[nodiscard]] std::vector<ContactPoint> search_contacts(const WheelRailPair& pair,
                                                        const WheelsetPose& pose);

/// Same from precomputed candidates of both wheels at `pose` shifted down by `extra_drop` [m]
/// (vertical gaps are exactly affine in the vertical position).
[[nodiscard]] std::vector<ContactPoint> contacts_from_candidates(
    const std::vector<ContactPoint>& candidates, double extra_drop);

/// Smallest vertical gap of one wheel at `pose` [m] (negative: interpenetration).
[[nodiscard]] double min_vertical_gap(const WheelRailPair& pair, const WheelsetPose& pose,
                                      Side side);

/// Result of a vertical-load solve.
struct LoadedWheelset {
  WheelsetPose pose;                              ///< with the solved vertical position
  std::vector<ContactPoint> points;               ///< with normal_force set
  std::array<double, 2> vertical_load{0.0, 0.0};  ///< carried by left/right wheel [N]
};

/// Finds the vertical position at which the contact points (Hertzian springs) carry
/// `total_vertical_load` [N] (sum of the vertical components of the normal forces, both
/// wheels), with lateral, roll and yaw from `pose`. Throws std::runtime_error if no contact.
[[nodiscard]] LoadedWheelset solve_vertical_load(const WheelRailPair& pair,
                                                 const WheelsetPose& pose,
                                                 double total_vertical_load,
                                                 double contact_modulus);

/// Rigid contact: roll and vertical position so that both wheels touch (smallest gap zero on
/// each side), for the given lateral shift and yaw. The points are the touching ones.
struct RigidContact {
  WheelsetPose pose;
  std::vector<ContactPoint> points;  ///< the deepest (touching) candidate on each wheel
  std::array<ContactPoint, 2> main;  ///< left, right touching point
};
[[nodiscard]] RigidContact solve_rigid_contact(const WheelRailPair& pair, double lateral,
                                               double yaw = 0.0);

/// Undeformed separation between wheel and rail along the contact normal, sampled on a grid in
/// the contact plane of `point`: x along the track, s across (towards the field side of that
/// wheel), the grid centred at (x_centre, s_centre) relative to the point:
/// gap[iy * nx + ix] at x = x_centre + (ix - (nx-1)/2) dx, s = s_centre + (iy - (ny-1)/2) ds
/// [m]; negative inside the interpenetration, NaN where a profile ends. For semi-Hertz / MIM
/// use gap - min(gap) as the undeformed distance z(x, y) of Toumi eq. (1).
/// Example (Toumi ch. 2 non-Hertzian case, S1002 / UIC60 1:40 centred): pose =
/// touching_pose(pair, {}); point = deepest of candidate_points(pair, pose, Side::right);
/// sample_gap(pair, pose, point, 46, 100, 0.223e-3, 0.223e-3, 0.0, -3.233e-3) covers the
/// thesis' s in [-14.374, 7.908] mm (both lobes).
struct GapGrid {
  int nx = 0, ny = 0;
  double dx = 0.0, ds = 0.0;              ///< [m]
  double x_centre = 0.0, s_centre = 0.0;  ///< grid centre relative to the point [m]
  std::vector<double> gap;                ///< [m]
  [[nodiscard]] double at(int ix, int iy) const {
    return gap[static_cast<std::size_t>(iy * nx + ix)];
  }
  [[nodiscard]] double x(int ix) const { return x_centre + (ix - 0.5 * (nx - 1)) * dx; }
  [[nodiscard]] double s(int iy) const { return s_centre + (iy - 0.5 * (ny - 1)) * ds; }
};
/// `plane_angle` [rad], when finite, inclines the sampling plane by this contact angle (sign as
/// ContactPoint::contact_angle) instead of the rail's slope at the point: the plane of a patch
/// whose reference angle is an average over the patch.
[[nodiscard]] GapGrid sample_gap(const WheelRailPair& pair, const WheelsetPose& pose,
                                 const ContactPoint& point, int nx, int ny, double dx, double ds,
                                 double x_centre = 0.0, double s_centre = 0.0,
                                 double plane_angle = std::numeric_limits<double>::quiet_NaN());

/// The undeformed separation of sample_gap(), one sample at a time: at(x, s) is the gap along
/// the normal of `point`'s contact plane at x along the track and s across (towards the field
/// side of that wheel), both relative to the point [m]; NaN where a profile ends. Keeps a
/// reference to `pair`. Construction and each sample (two Newton solves on the resampled
/// profiles) allocate nothing: the semi-Hertz normal contact of the dynamics samples it at every
/// right-hand side.
class ContactPlaneGap {
 public:
  ContactPlaneGap(const WheelRailPair& pair, const WheelsetPose& pose, const ContactPoint& point,
                  double plane_angle = std::numeric_limits<double>::quiet_NaN());
  [[nodiscard]] double at(double x, double s) const;

 private:
  const WheelRailPair* pair_;
  double sgn_, px_, py_, pz_;
  WheelsetFrame frame_;
  double ny_ = 0.0, nz_ = 0.0, ty_ = 0.0, tz_ = 0.0;  // plane normal and lateral tangent
  double mx_ = 0.0, my_ = 0.0, mz_ = 0.0;             // the normal in the wheelset frame
};

/// `pose` moved vertically so that its deepest point just touches (smallest gap zero).
[[nodiscard]] WheelsetPose touching_pose(const WheelRailPair& pair, const WheelsetPose& pose);

}  // namespace ferro::contact
