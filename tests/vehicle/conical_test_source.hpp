#pragma once
// Analytic conical wheels on rail crowns for the vehicle tests: one contact point per wheel at
// the rail's reference point (+-e), rolling radius r0 -+ gamma * lateral, penetration from the
// axle-centre height and roll, curvatures given. Two variants:
//  - cone: the wheel is a true cone: the contact angle is atan(gamma) on both wheels (normal
//    leaning towards the track centre) and a lateral shift changes the penetration (the wheel
//    radius under the rail changes), so gravitational stiffness and spin creep appear;
//  - kinematic: the idealisation of the textbook linear models (Toumi eq. 150, Wickens ch. 2):
//    the rolling radius changes with the lateral shift but the contact is flat (angle 0) and the
//    penetration does not depend on the shift (no gravitational stiffness).
// Contact-layer frame: x forward, y right, z down; the left wheel is at y = -e.

#include <cmath>
#include <string_view>
#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"

namespace ferro::vehicle::testing {

struct ConicalTestParams {
  double conicity = 0.1;          ///< gamma [-]
  double half_distance = 0.75;    ///< e [m]
  double nominal_radius = 0.46;   ///< r0 [m]
  double curvature_a = 1.087;     ///< A [1/m]
  double curvature_b = 1.0;       ///< B [1/m]
  double rail_raise = 0.0;        ///< rails raised by this much (penetration at rest) [m]
  bool kinematic = false;         ///< see above
};

class ConicalTestSource final : public contact::ContactGeometrySource {
 public:
  explicit ConicalTestSource(ConicalTestParams p) : p_(p) {}
  [[nodiscard]] std::string_view name() const override { return "conical_test"; }
  void contacts(const contact::WheelsetPose& pose,
                std::vector<contact::WheelRailContact>& out) const override {
    out.clear();
    const double angle = p_.kinematic ? 0.0 : std::atan(p_.conicity);
    for (contact::Side side : {contact::Side::left, contact::Side::right}) {
      const double sy = side == contact::Side::left ? -1.0 : 1.0;  // contact-frame y sign
      // Right wheel radius grows when the wheelset moves right (+y): r = r0 + sy gamma y.
      const double radius = p_.nominal_radius + sy * p_.conicity * pose.lateral;
      // Vertical approach: axle drop + roll (lowers the right wheel) + radius change (cone).
      double drop = pose.vertical + sy * p_.half_distance * std::sin(pose.roll) + p_.rail_raise;
      if (!p_.kinematic) drop += radius - p_.nominal_radius;
      const double penetration = drop * std::cos(angle);
      if (!(penetration > 0.0)) continue;
      contact::WheelRailContact c;
      c.side = side;
      c.x = 0.0;
      c.y = sy * p_.half_distance;
      c.z = 0.0;
      c.contact_angle = angle;
      c.rolling_radius = radius;
      c.penetration = penetration;
      c.curvature_a = p_.curvature_a;
      c.curvature_b = p_.curvature_b;
      out.push_back(c);
    }
  }

 private:
  ConicalTestParams p_;
};

}  // namespace ferro::vehicle::testing
