#pragma once
// Implementations of ContactGeometrySource and the normal contact the dynamics computes from
// their points:
// - SearchContactSource: the online 3D contact search of wheel_rail_geometry.hpp at every call;
// - ConicalContactSource: analytic conical wheels on knife-edge rail crowns (linear studies);
// - hertz_patch_from_penetration(): normal force, semi-axes and peak pressure of one point from
//   its penetration, through the one Hertz implementation of hertz.hpp or, for imported tables,
//   from the point's reference Hertz state.
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

#include <memory>
#include <string_view>
#include <vector>

#include "ferro/contact/contact_patch.hpp"
#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

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

}  // namespace ferro::contact
