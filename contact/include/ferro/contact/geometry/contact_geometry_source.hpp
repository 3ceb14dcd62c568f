#pragma once
// Where the dynamics gets its wheel-rail contact points from, behind one interface: a
// precomputed multi-point table (every contact point per wheel, tread and flange, indexed by
// lateral shift and roll, yaw optional, penetration computed online), the online 3D search, or a
// one-point table imported from another tool. All of them answer in the contact layer's track
// frame (x forward, y right, z down; see wheel_rail_geometry.hpp) for a wheelset pose given
// relative to the two rails.
//
// References: see wheel_rail_geometry.hpp (search), contact_table.hpp (tables).
// Known deviations: see each implementation.

#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::contact {

/// One penetrating contact point as the dynamics needs it. Track frame of the contact layer.
struct WheelRailContact {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Side side = Side::right;
  double x = 0.0, y = 0.0, z = 0.0;  ///< point on the rail surface, track frame [m]
  /// Contact angle [rad], + when the normal leans towards the track centre (flange ~ +70 deg).
  double contact_angle = 0.0;
  double rolling_radius = 0.0;  ///< wheel radius at the point [m]
  double penetration = 0.0;     ///< elastic approach along the normal, > 0 [m]
  double curvature_a = kNaN;    ///< A, longitudinal relative curvature [1/m]
  double curvature_b = kNaN;    ///< B, lateral relative curvature [1/m]
  /// Imported tables give the Hertz state at a reference approach instead of curvatures:
  /// F_n = ref_normal_force (penetration / ref_penetration)^1.5, semi-axes scale as F_n^(1/3).
  double ref_normal_force = kNaN;  ///< [N]
  double ref_penetration = kNaN;   ///< [m]
  double ref_semi_axis_a = kNaN;   ///< [m]
  double ref_semi_axis_b = kNaN;   ///< [m]
  /// Kalker coefficients when the source provides them (imported tables); NaN: from a/b.
  double c11 = kNaN, c22 = kNaN, c23 = kNaN;
  /// Where the point lies on the profiles (sources with profiles; NaN otherwise) [m].
  double wheel_y = kNaN, rail_y = kNaN;
  /// Vertical separation at the pose, < 0 here (penetration = -vertical_gap cos(contact_angle)
  /// for the profile-based sources) [m].
  double vertical_gap = kNaN;
  [[nodiscard]] bool has_reference_state() const { return ref_normal_force == ref_normal_force; }

  /// The place and local geometry of a point (side, position, contact angle, rolling radius,
  /// curvatures, profile coordinates) from any type that names them alike (a search result, a
  /// table candidate); penetration and vertical gap are left to the caller.
  template <class Point>
  [[nodiscard]] static WheelRailContact geometry_of(const Point& q) {
    WheelRailContact c;
    c.side = q.side;
    c.x = q.x;
    c.y = q.y;
    c.z = q.z;
    c.contact_angle = q.contact_angle;
    c.rolling_radius = q.rolling_radius;
    c.curvature_a = q.curvature_a;
    c.curvature_b = q.curvature_b;
    c.wheel_y = q.wheel_y;
    c.rail_y = q.rail_y;
    return c;
  }
};

/// Caller-owned scratch of ContactGeometrySource::contacts(): buffers a source reuses from call
/// to call, so that it keeps no state of its own and allocates nothing once they have grown.
/// Nothing in it carries from one call to the next; one scratch serves one thread of calls (a
/// right-hand side keeps one in its workspace).
struct ContactScratch {
  std::vector<WheelRailContact> candidates;  ///< interpolated candidates (multi-point table)
  std::vector<RunMember> members;            ///< the candidates as the joined-run rule sees them
  std::vector<double> gaps;                  ///< effective vertical gaps of the members [m]
};

class ContactGeometrySource {
 public:
  virtual ~ContactGeometrySource() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// Every penetrating contact point of both wheels at `pose` (relative to the rails), left
  /// wheel first, appended to `out` after clearing it. Must be thread-safe (const, no state of
  /// its own; `scratch` is the caller's) and must not allocate once `out` and `scratch` have
  /// grown to their working size.
  virtual void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out,
                        ContactScratch& scratch) const = 0;
  /// Same with a scratch of its own, allocated for this call (tools and tests; a right-hand side
  /// passes its own scratch).
  void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out) const {
    ContactScratch scratch;
    contacts(pose, out, scratch);
  }
  /// The wheel and rail profiles the points come from, for normal models that need the gap
  /// around a point (semi-Hertz); nullptr when the source has none (imported one-point tables,
  /// the analytic cone).
  [[nodiscard]] virtual const WheelRailPair* profile_pair() const { return nullptr; }
};

}  // namespace ferro::contact
