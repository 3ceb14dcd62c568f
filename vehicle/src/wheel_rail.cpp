// Wheel-rail coupling of one wheelset at every contact point the geometry source returns:
// pose relative to the rails (with track irregularities), normal force from the penetration
// (the contact layer's one Hertz entry point, or with wheel_rail.normal = semi_hertz its
// semi-Hertz patches of the profiles' gap around the point), exact creepages from the body and track-frame kinematics, tangential forces from the
// registered model, forces and moments on the wheelset. Optional Hunt-Crossley damping of the
// normal force: N = N_Hertz (1 + alpha d(delta)/dt), clamped at N >= 0.
//
// References: Toumi (2016) eqs. (5)-(13) (Hertz), (24)-(27) (creepages as rigid slip over the
// rolling speed), (38)-(40), (156) (creep forces, K_ij); Johnson (1985) eq. (4.39); Hunt &
// Crossley, "Coefficient of restitution interpreted as damping in vibroimpact", J. Appl. Mech.
// 42 (1975) 440-445 (F = K delta^n + lambda delta^n d(delta)/dt, here lambda = alpha K;
// alpha = 3 (1 - e) / (2 v) for a restitution coefficient e at impact speed v); Marhefka &
// Orin, IEEE Trans. SMC-A 29 (1999) 566-572 (the force clamped at zero on separation).
// Known deviations: the wheel material point is placed at the rolling radius the source gives,
// along the direction from the axle to the contact point (the axial offset kept), so that the
// rolling radius of a tabulated or analytic profile enters the creepages exactly; the rail is
// at rest in the ground (no rail vibration); gauge irregularity is not passed to the geometry
// (WheelsetPose has no gauge input). The rolling speed is max(|V|, regularisation_speed).
// The penetration rate of the damping is the normal velocity, relative to the rails, of the
// wheel section's point at the contact, from the rates of the rail-relative pose (lateral,
// height, roll; the irregularities passing under the wheelset at V): the exact rate of the
// penetration the geometry gives for that pose (the gap is a minimum, so its rate is the
// relative normal velocity of the closest points); the yaw rate's share (flange lead) is left
// out. The tangential model gets the
// damped normal force (its Coulomb bound follows it) with the semi-axes of the penetration.
// Semi-Hertz: each patch of a point (usually one; strips and equivalent ellipse as the contact
// layer builds them) gets its own tangential-model call at the point's position, normal and
// creepages; the damping scales its load, peak pressure and strip pressures alike.

#include <algorithm>
#include <cmath>

#include "ferro/contact/contact_patch.hpp"
#include "ferro/contact/geometry/contact_sources.hpp"
#include "ferro/vehicle/frames.hpp"
#include "dynamics.hpp"
#include "output_signals.hpp"

namespace ferro::vehicle::detail {
void apply_wheel_rail(const ModelData& model, const BodyData& body, BodyKinematics& k,
                      WheelRailScratch& scratch, WheelResult* left_right) {
  std::vector<contact::WheelRailContact>& points = scratch.points;

  const track::IrregularitySample& irr = k.irregularity;
  const double spacing = k.frame.rail_spacing > 0.0 ? k.frame.rail_spacing
                                                    : model.nominal_rail_spacing;
  const double rail_roll = -std::asin(std::clamp(irr.cross_level / spacing, -1.0, 1.0));
  const double cr = std::cos(rail_roll), sr = std::sin(rail_roll);
  const auto roll_rail = [cr, sr](const Eigen::Vector3d& v) {
    return Eigen::Vector3d(v.x(), cr * v.y() - sr * v.z(), sr * v.y() + cr * v.z());
  };

  // Pose relative to the rails: the axle centre's offset from the rails' origin (centreline at
  // rail level, irregularities included) in the rails' axes, which the cross-level rolls by
  // rail_roll about that origin (the inverse of roll_rail, which places the contact points).
  const Eigen::Vector3d centre = Eigen::Vector3d(0.0, body.rest.y(), body.rest.z()) + k.u;
  RailRelativePose rel;
  const Eigen::Vector3d offset = centre - Eigen::Vector3d(0.0, irr.lateral, irr.vertical);
  rel.lateral = cr * offset.y() + sr * offset.z();
  rel.height = -sr * offset.y() + cr * offset.z() - body.r0;
  rel.roll = k.angles.x() - rail_roll;
  rel.yaw = k.angles.z() - irr.d_lateral;
  model.in.geometry->contacts(to_contact_pose(rel), points);
  if (left_right != nullptr) record_pose(left_right, rel);

  const Eigen::Vector3d axle = k.attitude.col(1);
  const Eigen::Vector3d omega = k.motion.angular_velocity + k.rates + k.spin * axle;
  const Eigen::Vector3d centre_velocity = Eigen::Vector3d(k.motion.speed, 0.0, 0.0) +
                                          k.motion.angular_velocity.cross(centre) + k.u_dot;
  const double rolling_speed =
      std::max(std::abs(k.motion.speed), model.in.config.wheel_rail.regularisation_speed);
  const Eigen::Vector3d rails_origin(0.0, irr.lateral, irr.vertical);

  // Normal damping: rates of the rail-relative pose (the irregularities pass under the wheelset
  // at V) and the axle centre in the rails' axes, where the geometry places it.
  // Computed only when the damping is on (this runs in every right-hand side).
  const double alpha = model.in.config.wheel_rail.hunt_crossley_alpha;
  const Eigen::Vector3d centre_in_rails(0.0, rel.lateral, rel.height + body.r0);
  Eigen::Vector3d pose_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d pose_roll_rate = Eigen::Vector3d::Zero();
  if (alpha > 0.0) {
    const double level_ratio = std::clamp(irr.cross_level / spacing, -1.0, 1.0);
    const double rail_roll_rate =
        -k.motion.speed * irr.d_cross_level /
        (spacing * std::sqrt(std::max(1e-12, 1.0 - level_ratio * level_ratio)));
    // d/dt of (rel.lateral, rel.height): the offset's rate turned into the rails' axes, plus
    // the turning of those axes (d R^T/dt offset = rail_roll_rate (height', -lateral')).
    const double offset_rate_y = k.u_dot.y() - k.motion.speed * irr.d_lateral;
    const double offset_rate_z = k.u_dot.z() - k.motion.speed * irr.d_vertical;
    pose_velocity = {0.0,
                     cr * offset_rate_y + sr * offset_rate_z + rail_roll_rate * centre_in_rails.z(),
                     -sr * offset_rate_y + cr * offset_rate_z - rail_roll_rate * centre_in_rails.y()};
    pose_roll_rate.x() = k.rates.x() - rail_roll_rate;
  }

  const contact::WheelsetPose pose = to_contact_pose(rel);
  for (const contact::WheelRailContact& c : points) {
    // Normal contact: one Hertz patch from the point's curvatures, or the semi-Hertz patches of
    // the profiles' gap around the point (usually one).
    contact::ContactPatch hertz_patch;
    contact::ContactPatch* patches = &hertz_patch;
    std::size_t patch_count = 1;
    double point_normal_force = 0.0;
    if (model.contact.semi_hertz_pair == nullptr) {
      hertz_patch = contact::hertz_patch_from_penetration(c, model.contact.contact_modulus);
      point_normal_force = hertz_patch.normal_force;
    } else {
      contact::NormalSolution& semi = contact::semi_hertz_patches_from_penetration(
          *model.contact.semi_hertz_pair, pose, c, model.contact.material, model.contact.semi_hertz_options,
          scratch.semi_hertz);
      patches = semi.patches.data();
      patch_count = semi.patches.size();
      for (std::size_t i = 0; i < patch_count; ++i) point_normal_force += patches[i].normal_force;
    }
    if (!(point_normal_force > 0.0)) continue;  // wheel lift: no tangential model call

    const Eigen::Vector3d p = rails_origin + roll_rail(from_contact_frame(c.x, c.y, c.z));
    const Eigen::Vector3d n = roll_rail(rail_normal(c.side, c.contact_angle));
    double damping_factor = 1.0;
    if (alpha > 0.0) {
      // Velocity of the wheel section's point at the contact relative to the rails, rails' axes.
      const Eigen::Vector3d arm_in_rails = from_contact_frame(c.x, c.y, c.z) - centre_in_rails;
      const Eigen::Vector3d velocity = pose_velocity + pose_roll_rate.cross(arm_in_rails);
      const double penetration_rate = -velocity.dot(rail_normal(c.side, c.contact_angle));
      damping_factor = std::max(0.0, 1.0 + alpha * penetration_rate);
      if (!(damping_factor > 0.0)) continue;  // separating faster than 1/alpha: no force
    }
    // Wheel material point: axial offset along the axle, radial at the rolling radius.
    const Eigen::Vector3d d = p - centre;
    const Eigen::Vector3d axial = d.dot(axle) * axle;
    Eigen::Vector3d radial = d - axial;
    const double radial_length = radial.norm();
    radial = radial_length > 0.0 ? Eigen::Vector3d(radial / radial_length)
                                 : Eigen::Vector3d(-Eigen::Vector3d::UnitZ());
    const Eigen::Vector3d arm = axial + c.rolling_radius * radial;
    const Eigen::Vector3d slip = centre_velocity + omega.cross(arm);  // rail at rest

    // Contact frame: t1 along the rail, n the rail->wheel normal, t2 = n x t1.
    Eigen::Vector3d t1 = Eigen::Vector3d::UnitX() - n.x() * n;
    t1.normalize();
    const Eigen::Vector3d t2 = n.cross(t1);
    contact::TangentialProblem problem;
    problem.creepage.longitudinal = slip.dot(t1) / rolling_speed;
    problem.creepage.lateral = slip.dot(t2) / rolling_speed;
    problem.creepage.spin = omega.dot(n) / rolling_speed;
    problem.friction = model.in.config.wheel_rail.friction;
    problem.body1 = model.contact.material;
    problem.body2 = model.contact.material;
    problem.rolling_speed = rolling_speed;

    double normal_force = 0.0;
    PointTotals point_totals;  // signals only
    for (std::size_t i = 0; i < patch_count; ++i) {
      contact::ContactPatch& patch = patches[i];
      if (!(patch.normal_force > 0.0)) continue;
      if (alpha > 0.0) {
        patch.normal_force *= damping_factor;
        patch.peak_pressure *= damping_factor;
        for (contact::PatchStrip& strip : patch.strips) strip.peak_pressure *= damping_factor;
      }
      problem.patch = &patch;
      problem.reduction =
          model.contact.reduction_table ? model.contact.reduction_table->at(patch) : model.contact.reduction;
      const contact::TangentialSolution tang = model.contact.tangential->solve(problem);

      const Eigen::Vector3d force =
          patch.normal_force * n + tang.force_x * t1 + tang.force_y * t2;
      k.force += force;
      k.moment += arm.cross(force) + tang.moment_z * n;
      normal_force += patch.normal_force;
      if (left_right != nullptr) {
        WheelResult& w = left_right[c.side == contact::Side::left ? 0 : 1];
        const double towards_centre = c.side == contact::Side::left ? -1.0 : 1.0;
        w.lateral_towards_centre += towards_centre * force.y();
        w.vertical += force.z();
        add_patch(point_totals, patch, problem, tang);
      }
    }

    if (left_right != nullptr) {
      WheelResult& w = left_right[c.side == contact::Side::left ? 0 : 1];
      const double towards_centre = c.side == contact::Side::left ? -1.0 : 1.0;
      w.normal_force += normal_force;
      if (w.points < WheelResult::kPointSignals) {
        w.point_normal_force[static_cast<std::size_t>(w.points)] = normal_force;
      }
      record_point(w, c, point_totals, normal_force);
      ++w.points;
      if (normal_force > w.largest_normal_force) {
        w.largest_normal_force = normal_force;
        w.creepage_x = problem.creepage.longitudinal;
        w.creepage_y = problem.creepage.lateral;
        w.spin = problem.creepage.spin;
        w.contact_angle = c.contact_angle;
        // Outwards from the nominal rail reference point (+-spacing/2).
        w.contact_y = -towards_centre * p.y() - 0.5 * spacing;
      }
    }
  }
}

}  // namespace ferro::vehicle::detail
