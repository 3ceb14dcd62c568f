#pragma once
// The moving track frame along the arc length of a design alignment.
//
// Frames: ground frame x, y horizontal, z up. Track frame at arc length s: x along the
// centreline tangent, y lateral to the left in the cant plane, z normal to the cant plane
// (up). R_ground_track = Rz(heading) * Rx(-cant_angle): a positive cant raises the right rail
// and banks the track plane towards +y (the inside of a left-hand curve).
//
// References: EN 13803:2017 (clothoid = linear curvature in arc length; linear cant ramps);
// Abramowitz & Stegun (1964) §7.3 (Fresnel integrals, used as the oracle of the tests);
// Toumi (2016) eq. (148).
// Known deviations: clothoid positions come from Gauss-Legendre quadrature of the tangent
// (Boost.Math, 8 nodes per panel, panels of at most 0.5 rad heading change: error below 1e-13 m
// per panel for sections up to a few km), not from Fresnel integrals, because Fresnel
// differences lose precision in transitions between two curves of nearly equal radius. The cant second
// derivative is zero inside linear ramps and undefined (a Dirac) at their ends; the frame
// returns the one-sided value of the section that contains s. Beyond the design ends the frame
// throws std::out_of_range (append a straight if a vehicle must look further).

#include <Eigen/Core>
#include <vector>

#include "ferro/track/design.hpp"

namespace ferro::track {

/// Everything about the design track at one arc length. SI units; derivatives are with respect
/// to the arc length s.
struct TrackFrame {
  double s = 0.0;                                          ///< arc length [m]
  Eigen::Vector3d position = Eigen::Vector3d::Zero();      ///< centreline, ground frame [m]
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< R_ground_track (columns: track axes)
  double heading = 0.0;        ///< angle of the tangent from ground +x [rad]
  double curvature = 0.0;      ///< d heading / ds [1/m], positive turning left
  double d_curvature = 0.0;    ///< d curvature / ds [1/m^2]
  double cant = 0.0;           ///< superelevation z_right - z_left [m]
  double d_cant = 0.0;         ///< [m/m]
  double dd_cant = 0.0;        ///< [1/m]
  double cant_angle = 0.0;     ///< asin(cant / rail_spacing) [rad]
  double d_cant_angle = 0.0;   ///< [rad/m]
  double dd_cant_angle = 0.0;  ///< [rad/m^2]
  double gauge = 0.0;          ///< nominal gauge + widening [m]
  double d_gauge = 0.0;        ///< [m/m]
  double rail_spacing = 0.0;   ///< distance between rail contact points (2e) [m]
  int section = 0;             ///< index of the section containing s

  /// Angular rate of the track frame per unit arc length, in track axes [rad/m]:
  /// (-d_cant_angle, -curvature sin(cant_angle), curvature cos(cant_angle)).
  [[nodiscard]] Eigen::Vector3d angular_rate_per_length() const;
  /// Its derivative with respect to s [rad/m^2].
  [[nodiscard]] Eigen::Vector3d d_angular_rate_per_length() const;
  /// The same two with sin(cant_angle) and cos(cant_angle) given by the caller (who needs them
  /// for more than these).
  [[nodiscard]] Eigen::Vector3d angular_rate_per_length(double sin_cant, double cos_cant) const;
  [[nodiscard]] Eigen::Vector3d d_angular_rate_per_length(double sin_cant, double cos_cant) const;
  /// Nominal position of the left (+y) / right rail contact reference point, at +-rail_spacing/2
  /// along the track y axis, ground frame [m].
  [[nodiscard]] Eigen::Vector3d left_rail_position() const;
  [[nodiscard]] Eigen::Vector3d right_rail_position() const;
};

/// Design alignment built from a TrackDesign. Read-only after construction; frame() is const
/// and thread-safe.
class Alignment {
 public:
  /// Validates the design (throws std::invalid_argument naming the field) and precomputes the
  /// start state of every section.
  explicit Alignment(const TrackDesign& design);

  /// The track frame at arc length s in [start_s, end_s]; throws std::out_of_range outside.
  [[nodiscard]] TrackFrame frame(double s) const;
  /// Position of the centreline only (cheaper than frame()).
  [[nodiscard]] Eigen::Vector3d position(double s) const;

  [[nodiscard]] double start_s() const { return starts_.front().s; }
  [[nodiscard]] double end_s() const { return end_s_; }
  [[nodiscard]] const TrackDesign& design() const { return design_; }
  /// Arc length where section i starts.
  [[nodiscard]] double section_start(int i) const { return starts_.at(i).s; }

 private:
  /// Precomputed state at the start of a section and its linear variations.
  struct SectionState {
    double s = 0.0, length = 0.0;
    double x = 0.0, y = 0.0, heading = 0.0;
    double curvature = 0.0, d_curvature = 0.0;
    double cant = 0.0, d_cant = 0.0;
    double widening = 0.0, d_widening = 0.0;
  };
  [[nodiscard]] int locate(double s) const;
  [[nodiscard]] static Eigen::Vector2d plan_offset(const SectionState& st, double u);

  TrackDesign design_;
  std::vector<SectionState> starts_;
  double end_s_ = 0.0;
};

}  // namespace ferro::track
