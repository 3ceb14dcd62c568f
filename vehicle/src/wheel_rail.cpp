// Wheel-rail coupling of one wheelset at every contact point the geometry source returns: each
// wheel against its own rail, placed by the design frame, the irregularities (alignment, level,
// cross-level, gauge) and, on a flexible track, the rail's elastic lateral, vertical and roll
// displacement; normal force from the penetration (the contact layer's one Hertz entry point, or
// with wheel_rail.normal = semi_hertz its semi-Hertz patches of the profiles' gap around the
// point); exact creepages from the wheel's material velocity relative to the rail's; tangential
// forces from the registered model; forces and moments on the wheelset and, reversed, on the
// rail. Optional Hunt-Crossley damping of the normal force: N = N_Hertz (1 + alpha d(delta)/dt),
// clamped at N >= 0.
//
// Each rail is the image of its nominal position in the contact geometry's rail pair under a
// rigid motion: a roll theta (the cross-level's roll of the pair plus the rail's elastic roll)
// and a translation. The wheelset's pose relative to the "virtual pair" whose rail on that side
// is the displaced rail is what the geometry source answers for; its points on that side are
// kept and moved back. When both rails undergo the same motion (a rigid track without gauge
// irregularity) one query serves both wheels.
//
// References: Toumi (2016) eqs. (5)-(13) (Hertz), (24)-(27) (creepages as rigid slip over the
// rolling speed), (38)-(40), (156) (creep forces, K_ij); Johnson (1985) eq. (4.39); Hunt &
// Crossley, "Coefficient of restitution interpreted as damping in vibroimpact", J. Appl. Mech.
// 42 (1975) 440-445 (F = K delta^n + lambda delta^n d(delta)/dt, here lambda = alpha K;
// alpha = 3 (1 - e) / (2 v) for a restitution coefficient e at impact speed v); Marhefka &
// Orin, IEEE Trans. SMC-A 29 (1999) 566-572 (the force clamped at zero on separation); Zhai,
// Wang & Cai, Veh. Syst. Dyn. 47 (2009) 1349-1376 (wheel-rail coupling with the rails' lateral,
// vertical and torsional motion).
// Known deviations: the wheel material point is placed at the rolling radius the source gives,
// along the direction from the axle to the contact point (the axial offset kept), so that the
// rolling radius of a tabulated or analytic profile enters the creepages exactly; a rail has no
// elastic yaw (its direction is the design's plus the irregularities' slope). The rolling speed
// is max(|V|, regularisation_speed). The penetration rate of the damping is the normal velocity
// of the wheel section's point at the contact relative to the rail: from the rates of the
// rail-relative pose (lateral, height, roll; the irregularities passing under the wheelset at V)
// less the rail's elastic velocity at the point; the yaw rate's share (flange lead) is left out.
// The tangential model gets the damped normal force (its Coulomb bound follows it) with the
// semi-axes of the penetration. Semi-Hertz: each patch of a point (usually one; strips and
// equivalent ellipse as the contact layer builds them) gets its own tangential-model call at the
// point's position, normal and creepages; the damping scales its load, peak pressure and strip
// pressures alike.

#include <algorithm>
#include <cmath>

#include "dynamics.hpp"
#include "ferro/contact/geometry/point_normal_contact.hpp"
#include "ferro/contact/normal/contact_patch.hpp"
#include "ferro/contact/tangential/creepage.hpp"
#include "ferro/vehicle/frames.hpp"
#include "output_signals.hpp"

namespace ferro::vehicle::detail {
namespace {

/// One rail, displaced: the virtual rail pair (origin and roll) whose rail on this side it is,
/// its yaw, and its elastic motion (for the velocity of its material points).
struct RailPlacement {
  contact::Side side = contact::Side::left;
  double roll = 0.0, cos_roll = 1.0, sin_roll = 0.0;  ///< theta of the virtual pair [rad]
  double roll_rate = 0.0;                   ///< the irregular cross-level's roll rate [rad/s]
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< virtual pair's centreline point [m]
  double yaw = 0.0;                                  ///< [rad]
  double yaw_irregular_rate_y = 0.0;  ///< d(lateral)/ds of this rail (its yaw) [m/m]
  double d_vertical = 0.0;            ///< d(vertical)/ds of this rail [m/m]
  // Elastic motion (zero on a rigid track).
  Eigen::Vector3d com = Eigen::Vector3d::Zero();           ///< rail's centre of mass [m]
  Eigen::Vector3d com_velocity = Eigen::Vector3d::Zero();  ///< [m/s]
  double elastic_roll_rate = 0.0;                          ///< [rad/s]

  [[nodiscard]] Eigen::Vector3d to_track(const Eigen::Vector3d& v) const {
    return {v.x(), cos_roll * v.y() - sin_roll * v.z(), sin_roll * v.y() + cos_roll * v.z()};
  }
  /// Elastic velocity of the rail's material point at p [m/s].
  [[nodiscard]] Eigen::Vector3d velocity_at(const Eigen::Vector3d& p) const {
    return com_velocity + Eigen::Vector3d(elastic_roll_rate, 0.0, 0.0).cross(p - com);
  }
};

/// Where the two rails of a wheelset are: design frame, irregularities, elastic displacement.
std::array<RailPlacement, 2> place_rails(const ModelData& m, const BodyData& body,
                                         const BodyKinematics& k, std::span<const double> x) {
  const track::IrregularitySample& irr = k.irregularity;
  const double spacing = k.frame.rail_spacing > 0.0 ? k.frame.rail_spacing : m.nominal_rail_spacing;
  const double level_ratio = std::clamp(irr.cross_level / spacing, -1.0, 1.0);
  const double pair_roll = -std::asin(level_ratio);
  // The rails' section under the wheelset: at its own longitudinal position (a wheelset free
  // to move lengthwise carries its contact points with it).
  const Eigen::Vector3d rails_origin(k.u.x(), irr.lateral, irr.vertical);
  std::array<RailPlacement, 2> rails;
  for (int side = 0; side < 2; ++side) {
    RailPlacement& r = rails[static_cast<std::size_t>(side)];
    const double sigma = side == 0 ? 1.0 : -1.0;  // left rail at +y
    r.side = side == 0 ? contact::Side::left : contact::Side::right;
    r.roll_rate = -k.motion.speed * irr.d_cross_level /
                  (spacing * std::sqrt(std::max(1e-12, 1.0 - level_ratio * level_ratio)));
    r.yaw = irr.d_lateral + sigma * 0.5 * irr.d_gauge;
    r.yaw_irregular_rate_y = r.yaw;
    r.d_vertical = irr.d_vertical;
    // Beyond the pair's rigid motion: half the gauge deviation outwards and the elastic
    // displacement of the rail head's reference point.
    Eigen::Vector3d shift(0.0, sigma * 0.5 * irr.gauge, 0.0);
    double elastic_roll = 0.0;
    if (body.track >= 0) {
      const auto q = x.subspan(static_cast<std::size_t>(body.track) + 3 * side, 3);
      const auto v = x.subspan(
          static_cast<std::size_t>(body.track) + track::kTrackPositions + 3 * side, 3);
      const double h = m.track->rail_head_height;
      elastic_roll = q[2];
      shift += Eigen::Vector3d(0.0, q[0] - h * q[2], q[1]);
      r.com_velocity = Eigen::Vector3d(0.0, v[0], v[1]);
      r.elastic_roll_rate = v[2];
    }
    r.roll = pair_roll + elastic_roll;
    r.cos_roll = std::cos(r.roll);
    r.sin_roll = std::sin(r.roll);
    // origin = reference point - R(theta) P0; the difference of the pair's and the rail's
    // rotations of P0 is exactly zero on a rigid track, so the origin is then the rails' own.
    const Eigen::Vector3d p0(0.0, sigma * 0.5 * spacing, 0.0);
    const Eigen::Vector3d pair_p0(0.0, std::cos(pair_roll) * p0.y(), std::sin(pair_roll) * p0.y());
    r.origin = rails_origin + (pair_p0 - r.to_track(p0)) + shift;
    if (body.track >= 0) {
      // Centre of mass: rail_head_height below the reference point, in the rail's axes.
      r.com = r.origin + r.to_track(p0 - Eigen::Vector3d(0.0, 0.0, m.track->rail_head_height));
    }
  }
  return rails;
}

/// The wheelset's pose relative to the virtual pair of `rail`.
RailRelativePose pose_relative_to(const RailPlacement& rail, const Eigen::Vector3d& centre,
                                  const BodyKinematics& k, double r0) {
  const Eigen::Vector3d offset = centre - rail.origin;
  RailRelativePose rel;
  rel.lateral = rail.cos_roll * offset.y() + rail.sin_roll * offset.z();
  rel.height = -rail.sin_roll * offset.y() + rail.cos_roll * offset.z() - r0;
  rel.roll = k.angles.x() - rail.roll;
  rel.yaw = k.angles.z() - rail.yaw;
  return rel;
}

/// Velocity (virtual pair axes) of the wheel section's point at the axle centre relative to the
/// irregular rails, and the section's roll rate relative to them: the rates of the pose the
/// geometry sees (normal damping only).
struct PoseRates {
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d roll_rate = Eigen::Vector3d::Zero();
  Eigen::Vector3d centre_in_rails = Eigen::Vector3d::Zero();
};

PoseRates pose_rates(const RailPlacement& rail, const RailRelativePose& rel,
                     const BodyKinematics& k, double r0) {
  PoseRates out;
  out.centre_in_rails = Eigen::Vector3d(0.0, rel.lateral, rel.height + r0);
  // d/dt of (rel.lateral, rel.height): the offset's rate turned into the rails' axes, plus the
  // turning of those axes (d R^T/dt offset = roll_rate (height', -lateral')).
  const double offset_rate_y = k.u_dot.y() - k.motion.speed * rail.yaw_irregular_rate_y;
  const double offset_rate_z = k.u_dot.z() - k.motion.speed * rail.d_vertical;
  const double cr = rail.cos_roll, sr = rail.sin_roll;
  out.velocity = {0.0,
                  cr * offset_rate_y + sr * offset_rate_z + rail.roll_rate * out.centre_in_rails.z(),
                  -sr * offset_rate_y + cr * offset_rate_z -
                      rail.roll_rate * out.centre_in_rails.y()};
  out.roll_rate.x() = k.rates.x() - rail.roll_rate;
  return out;
}

/// What every point of one wheelset shares.
struct WheelsetMotion {
  Eigen::Vector3d centre, centre_velocity, omega, axle;
  double rolling_speed = 0.0;
};

/// Forces of one contact point on the wheelset (accumulators of k) and its rail (load),
/// and the wheel's results.
void apply_point(const ModelData& m, const contact::WheelRailContact& c,
                 const RailPlacement& rail, const contact::WheelsetPose& pose,
                 const PoseRates* rates, const WheelsetMotion& w, BodyKinematics& k,
                 WheelRailScratch& scratch, track::RailLoad& load, WheelResult* result) {
  // Normal contact: one Hertz patch from the point's curvatures, or the semi-Hertz patches of the
  // profiles' gap around the point (usually one).
  contact::ContactPatch hertz_patch;
  contact::ContactPatch* patches = &hertz_patch;
  std::size_t patch_count = 1;
  double point_normal_force = 0.0;
  if (m.contact.semi_hertz_pair == nullptr) {
    hertz_patch = contact::hertz_patch_from_penetration(c, m.contact.contact_modulus);
    point_normal_force = hertz_patch.normal_force;
  } else {
    contact::NormalSolution& semi = contact::semi_hertz_patches_from_penetration(
        *m.contact.semi_hertz_pair, pose, c, m.contact.material, m.contact.semi_hertz_options,
        scratch.semi_hertz);
    patches = semi.patches.data();
    patch_count = semi.patches.size();
    for (std::size_t i = 0; i < patch_count; ++i) point_normal_force += patches[i].normal_force;
  }
  if (!(point_normal_force > 0.0)) return;  // wheel lift: no tangential model call

  const Eigen::Vector3d p = rail.origin + rail.to_track(from_contact_frame(c.x, c.y, c.z));
  const Eigen::Vector3d n = rail.to_track(rail_normal(c.side, c.contact_angle));
  const Eigen::Vector3d rail_velocity = rail.velocity_at(p);
  double damping_factor = 1.0;
  if (rates != nullptr) {
    // Velocity of the wheel section's point at the contact relative to the rail, rails' axes.
    const Eigen::Vector3d arm_in_rails = from_contact_frame(c.x, c.y, c.z) - rates->centre_in_rails;
    const Eigen::Vector3d rail_elastic(
        0.0, rail.cos_roll * rail_velocity.y() + rail.sin_roll * rail_velocity.z(),
        -rail.sin_roll * rail_velocity.y() + rail.cos_roll * rail_velocity.z());
    const Eigen::Vector3d velocity =
        rates->velocity + rates->roll_rate.cross(arm_in_rails) - rail_elastic;
    const double penetration_rate = -velocity.dot(rail_normal(c.side, c.contact_angle));
    damping_factor = std::max(0.0, 1.0 + m.in.config.wheel_rail.hunt_crossley_alpha * penetration_rate);
    if (!(damping_factor > 0.0)) return;  // separating faster than 1/alpha: no force
  }
  // Wheel material point at the rolling radius, contact frame (t1 along the rail, n the
  // rail->wheel normal, t2 = n x t1) and creepages: the contact layer's one definition. The
  // rail's material point moves with the track; its rotation is not in the spin.
  const Eigen::Vector3d arm = contact::wheel_point_arm(p - w.centre, w.axle, c.rolling_radius,
                                                       -Eigen::Vector3d::UnitZ());
  const contact::ContactFrame frame = contact::ContactFrame::from_normal(n);
  const Eigen::Vector3d& t1 = frame.t1;
  const Eigen::Vector3d& t2 = frame.t2;
  contact::TangentialProblem problem;
  problem.creepage =
      contact::creepage(w.centre_velocity + w.omega.cross(arm), w.omega, rail_velocity,
                        Eigen::Vector3d::Zero(), frame, w.rolling_speed);
  problem.friction = m.in.config.wheel_rail.friction;
  problem.body1 = m.contact.material;
  problem.body2 = m.contact.material;
  problem.rolling_speed = w.rolling_speed;

  const double towards_centre = c.side == contact::Side::left ? -1.0 : 1.0;
  double normal_force = 0.0;
  PointTotals point_totals;  // signals only
  for (std::size_t i = 0; i < patch_count; ++i) {
    contact::ContactPatch& patch = patches[i];
    if (!(patch.normal_force > 0.0)) continue;
    if (rates != nullptr) {
      patch.normal_force *= damping_factor;
      patch.peak_pressure *= damping_factor;
      for (contact::PatchStrip& strip : patch.strips) strip.peak_pressure *= damping_factor;
    }
    problem.patch = &patch;
    problem.reduction =
        m.contact.reduction_table ? m.contact.reduction_table->at(patch) : m.contact.reduction;
    const contact::TangentialSolution tang = m.contact.tangential->solve(problem);

    const Eigen::Vector3d force = patch.normal_force * n + tang.force_x * t1 + tang.force_y * t2;
    k.force += force;
    k.moment += arm.cross(force) + tang.moment_z * n;
    // The reaction on the rail at p, about its centre of mass.
    const Eigen::Vector3d r = p - rail.com;
    load.force_y -= force.y();
    load.force_z -= force.z();
    load.moment_x -= r.y() * force.z() - r.z() * force.y() + tang.moment_z * n.x();
    normal_force += patch.normal_force;
    if (result != nullptr) {
      result->lateral_towards_centre += towards_centre * force.y();
      result->vertical += force.z();
      add_patch(point_totals, patch, problem, tang);
    }
  }
  if (result == nullptr) return;
  result->normal_force += normal_force;
  if (result->points < WheelResult::kPointSignals) {
    result->point_normal_force[static_cast<std::size_t>(result->points)] = normal_force;
  }
  record_point(*result, c, point_totals, normal_force);
  ++result->points;
  if (normal_force > result->largest_normal_force) {
    result->largest_normal_force = normal_force;
    result->creepage_x = problem.creepage.longitudinal;
    result->creepage_y = problem.creepage.lateral;
    result->spin = problem.creepage.spin;
    result->contact_angle = c.contact_angle;
    // Outwards from the nominal rail reference point (+-spacing/2).
    const double spacing =
        k.frame.rail_spacing > 0.0 ? k.frame.rail_spacing : m.nominal_rail_spacing;
    result->contact_y = -towards_centre * p.y() - 0.5 * spacing;
  }
}

bool same_placement(const RailPlacement& a, const RailPlacement& b) {
  return a.roll == b.roll && a.origin == b.origin && a.yaw == b.yaw;
}

}  // namespace

void apply_wheel_rail(const ModelData& m, const BodyData& body, BodyKinematics& k,
                      std::span<const double> x, WheelRailScratch& scratch,
                      track::RailLoad* rail_loads, WheelResult* left_right) {
  const std::array<RailPlacement, 2> rails = place_rails(m, body, k, x);
  WheelsetMotion w;
  w.centre = Eigen::Vector3d(0.0, body.rest.y(), body.rest.z()) + k.u;
  w.axle = k.attitude.col(1);
  w.omega = k.motion.angular_velocity + k.rates + k.spin * w.axle;
  w.centre_velocity = Eigen::Vector3d(k.motion.speed, 0.0, 0.0) +
                      k.motion.angular_velocity.cross(w.centre) + k.u_dot;
  w.rolling_speed =
      std::max(std::abs(k.motion.speed), m.in.config.wheel_rail.regularisation_speed);
  const bool damped = m.in.config.wheel_rail.hunt_crossley_alpha > 0.0;
  // One query of the geometry when both rails moved alike, else one per rail.
  const bool one_query = same_placement(rails[0], rails[1]);
  for (int side = 0; side < 2; ++side) {
    if (one_query && side == 1) break;
    const RailPlacement& rail = rails[static_cast<std::size_t>(side)];
    const RailRelativePose rel = pose_relative_to(rail, w.centre, k, body.r0);
    const contact::WheelsetPose pose = to_contact_pose(rel);
    if (left_right != nullptr) record_pose(left_right, rel, one_query ? -1 : side);
    m.in.geometry->contacts(pose, scratch.points, scratch.geometry);
    PoseRates rates;
    if (damped) rates = pose_rates(rail, rel, k, body.r0);
    for (const contact::WheelRailContact& c : scratch.points) {
      if (!one_query && c.side != rail.side) continue;
      const auto s = static_cast<std::size_t>(c.side == contact::Side::left ? 0 : 1);
      track::RailLoad scrap;
      apply_point(m, c, rails[s], pose, damped ? &rates : nullptr, w, k, scratch,
                  rail_loads != nullptr ? rail_loads[s] : scrap,
                  left_right != nullptr ? left_right + s : nullptr);
    }
  }
}

}  // namespace ferro::vehicle::detail
