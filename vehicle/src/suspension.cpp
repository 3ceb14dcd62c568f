// Suspension elements between attachment points of two bodies (or a body and the track frame):
// linear spring + damper per axis with preload, damper with series stiffness (internal
// deflection as a first-order state), bump stop (free play then a force table), torsion spring
// + damper about x or z.
//
// References: Iwnicki (1998) Manchester benchmarks (element set: per-axlebox primary springs
// and dampers, secondary springs, yaw dampers, lateral bump stop, anti-roll bar, bogie yaw
// stiffness); Wickens (2003) ch. 2 (series damper: c q' = k (delta - q)).
// Known deviations: deflections are taken along the axes of body_a's track frame (not of the
// body's rotated axes): element axes stay aligned with the track, a small-angle approximation.
// Torsion elements act on the difference of the bodies' absolute angles about the axis (body
// angle plus frame heading or cant angle), which equals the relative rotation to first order.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dynamics.hpp"

namespace ferro::vehicle::detail {

void point_state(const BodyData* body, const BodyKinematics& k, const Eigen::Vector3d& p,
                 Eigen::Vector3d& position, Eigen::Vector3d& velocity, Eigen::Vector3d& arm) {
  Eigen::Vector3d local;
  if (body == nullptr) {
    arm = Eigen::Vector3d(0.0, p.y(), p.z());
    local = arm;
    velocity = Eigen::Vector3d(k.motion.speed, 0.0, 0.0) + k.motion.angular_velocity.cross(local);
  } else {
    arm = k.attitude * p;
    local = Eigen::Vector3d(0.0, body->rest.y(), body->rest.z()) + k.u + arm;
    velocity = Eigen::Vector3d(k.motion.speed, 0.0, 0.0) + k.motion.angular_velocity.cross(local) +
               k.u_dot + k.rates.cross(arm);
  }
  position = k.frame.position + k.frame.rotation * local;
  velocity = k.frame.rotation * velocity;
}

namespace {

/// Bump-stop force magnitude at |deflection| d: zero inside the free play, linear from the
/// clearance to the first table point, table interpolation, last slope beyond.
double bump_stop_force(const SuspensionElementSpec& s, double d) {
  if (d <= s.clearance) return 0.0;
  const auto& xs = s.table_displacement;
  const auto& fs = s.table_force;
  if (d <= xs.front()) {
    const double span = xs.front() - s.clearance;
    return span > 0.0 ? fs.front() * (d - s.clearance) / span : fs.front();
  }
  const auto it = std::upper_bound(xs.begin(), xs.end(), d);
  std::size_t i = static_cast<std::size_t>(it - xs.begin());
  if (i >= xs.size()) i = xs.size() - 1;
  const double x0 = xs[i - 1], x1 = xs[i];
  return fs[i - 1] + (fs[i] - fs[i - 1]) * (d - x0) / (x1 - x0);
}

/// Absolute angle of a body (or the frame) about x (roll) or z (yaw) and its rate.
void absolute_angle(const BodyKinematics& k, bool dynamic_body, int axis, double& angle,
                    double& rate) {
  const double body_angle = dynamic_body ? k.angles[axis] : 0.0;
  const double body_rate = dynamic_body ? k.rates[axis] : 0.0;
  if (axis == 0) {  // frame roll is -cant_angle (R = Rz(heading) Rx(-cant_angle))
    angle = body_angle - k.frame.cant_angle;
  } else {
    angle = body_angle + k.frame.heading;
  }
  rate = body_rate + k.motion.angular_velocity[axis];
}

}  // namespace

void apply_element(const ModelData& model, const ElementData& e,
                   std::vector<BodyKinematics>& kin, const BodyKinematics& track_frame_a,
                   std::span<const double> x, std::span<double> xdot) {
  const SuspensionElementSpec& s = e.spec;
  const BodyData* body_a = e.a >= 0 ? &model.bodies[static_cast<std::size_t>(e.a)] : nullptr;
  const BodyData& body_b = model.bodies[static_cast<std::size_t>(e.b)];
  const BodyKinematics& ka = e.a >= 0 ? kin[static_cast<std::size_t>(e.a)] : track_frame_a;
  BodyKinematics& kb = kin[static_cast<std::size_t>(e.b)];

  if (s.type == ElementType::torsion) {
    const int axis = static_cast<int>(s.axis) - 3;
    double angle_a = 0.0, rate_a = 0.0, angle_b = 0.0, rate_b = 0.0;
    absolute_angle(ka, body_a != nullptr, axis, angle_a, rate_a);
    absolute_angle(kb, true, axis, angle_b, rate_b);
    double diff = angle_b - angle_a;
    diff = std::remainder(diff, 2.0 * std::numbers::pi);
    const double torque_b = -(s.k * diff + s.c * (rate_b - rate_a));
    kb.moment[axis] += torque_b;
    if (e.a >= 0) kin[static_cast<std::size_t>(e.a)].moment[axis] -= torque_b;
    return;
  }

  // Attachment points in the ground frame, their relative position and velocity in the axes of
  // body_a's track frame.
  Eigen::Vector3d pa, va, arm_a, pb, vb, arm_b;
  point_state(body_a, ka, s.point_a, pa, va, arm_a);
  point_state(&body_b, kb, s.point_b, pb, vb, arm_b);
  const Eigen::Matrix3d& Ra = ka.frame.rotation;
  const Eigen::Vector3d d = Ra.transpose() * (pb - pa);
  const Eigen::Vector3d deflection = d - e.rest_vector;
  const Eigen::Vector3d deflection_rate =
      Ra.transpose() * (vb - va) - ka.motion.angular_velocity.cross(d);

  Eigen::Vector3d f = Eigen::Vector3d::Zero();  // on body_b, body_a frame axes
  switch (s.type) {
    case ElementType::spring_damper:
      f = -(s.stiffness.cwiseProduct(deflection) + s.damping.cwiseProduct(deflection_rate)) +
          s.preload;
      break;
    case ElementType::series_damper: {
      const int axis = static_cast<int>(s.axis);
      const double q = x[static_cast<std::size_t>(e.state)];
      const double force = s.k * (deflection[axis] - q);  // tension positive
      f[axis] = -force;
      if (!xdot.empty()) xdot[static_cast<std::size_t>(e.state)] = force / s.c;
      break;
    }
    case ElementType::bump_stop: {
      const int axis = static_cast<int>(s.axis);
      const double dl = deflection[axis];
      f[axis] = -std::copysign(bump_stop_force(s, std::abs(dl)), dl);
      break;
    }
    case ElementType::torsion:
      break;
  }

  // Force and moment on body_b (its frame axes) and the reaction on body_a.
  const Eigen::Vector3d f_b = kb.frame.rotation.transpose() * (Ra * f);
  kb.force += f_b;
  kb.moment += arm_b.cross(f_b);
  if (e.a >= 0) {
    BodyKinematics& ka_mut = kin[static_cast<std::size_t>(e.a)];
    ka_mut.force -= f;
    // The reaction acts on the same line as the action, through body_b's attachment point
    // (body_a's point plus d): a massless element passes no net couple, and angular momentum
    // is conserved when the two points separate under a preload.
    ka_mut.moment -= (arm_a + d).cross(f);
  }
}

}  // namespace ferro::vehicle::detail
