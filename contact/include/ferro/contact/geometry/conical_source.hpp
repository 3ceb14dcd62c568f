#pragma once
// Analytic conical wheels on knife-edge rail crowns (linear studies) as a contact geometry source.
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
// rolling radii r0 +- gamma y, roll coefficient).
// Known deviations: the contact point on the rail is fixed at the crown line (knife-edge rail,
// the given curvatures A, B only set the Hertz ellipse), yaw does not move the points (x = 0;
// first-order exact for small yaw), no flange.

#include <limits>
#include <string_view>
#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"

namespace ferro::contact {

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
  using ContactGeometrySource::contacts;
  void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out,
                ContactScratch& scratch) const override;
  /// The point of one wheel whether or not it penetrates (vertical_gap > 0: separated).
  [[nodiscard]] WheelRailContact wheel_point(const WheelsetPose& pose, Side side) const;
  [[nodiscard]] const ConicalContactParams& params() const { return params_; }

 private:
  ConicalContactParams params_;
};

}  // namespace ferro::contact
