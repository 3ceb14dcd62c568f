#pragma once
// Kinematic cone for the linear-model tests: the idealisation of the textbook linear wheelset
// and bogie (Toumi eq. 150, Wickens ch. 2). One contact point per wheel at the rail's reference
// point (+-e); the rolling radius changes with the lateral shift, r0 -+ gamma * lateral, but the
// contact is flat (contact angle 0) and the penetration depends only on the axle height and roll
// (no gravitational stiffness), curvatures given. The true cone (contact angle atan(gamma),
// gravitational stiffness) is contact::ConicalContactSource.
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
};

class ConicalTestSource final : public contact::ContactGeometrySource {
 public:
  explicit ConicalTestSource(ConicalTestParams p) : p_(p) {}
  [[nodiscard]] std::string_view name() const override { return "conical_test"; }
  using contact::ContactGeometrySource::contacts;
  void contacts(const contact::WheelsetPose& pose, std::vector<contact::WheelRailContact>& out,
                contact::ContactScratch& /*scratch*/) const override {
    out.clear();
    for (contact::Side side : {contact::Side::left, contact::Side::right}) {
      const double sy = side == contact::Side::left ? -1.0 : 1.0;  // contact-frame y sign
      // Right wheel radius grows when the wheelset moves right (+y): r = r0 + sy gamma y.
      const double radius = p_.nominal_radius + sy * p_.conicity * pose.lateral;
      // Vertical approach: axle drop + roll (lowers the right wheel).
      const double penetration =
          pose.vertical + sy * p_.half_distance * std::sin(pose.roll) + p_.rail_raise;
      if (!(penetration > 0.0)) continue;
      contact::WheelRailContact c;
      c.side = side;
      c.x = 0.0;
      c.y = sy * p_.half_distance;
      c.z = 0.0;
      c.contact_angle = 0.0;
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
