#pragma once
// Track irregularities: deviations of the rails from the design geometry, as functions of the
// arc length s. One small interface (Irregularity), summable (IrregularitySum), with
// implementations for isolated defects (this file), stochastic irregularities from spectra
// (stochastic_irregularity.hpp) and measured irregularities (measured_irregularity.hpp).
//
// Conventions (track axes, see alignment.hpp): lateral alignment and vertical profile are
// displacements of the track centreline along +y (left) and +z (up); cross-level is
// z_right - z_left (same sign as cant); gauge deviation is positive when the gauge is wider.
// Per rail: y_left = lateral + gauge/2, y_right = lateral - gauge/2,
//           z_left = vertical - cross_level/2, z_right = vertical + cross_level/2.
//
// References: EN 13848-1:2019 (definitions of alignment, longitudinal level, cross-level,
// gauge); Toumi (2016) §4.3-4.4 (isolated lateral alignment defect used to excite hunting;
// local twist defect in the exit transition of the Fig. 4.4 case).
// Known deviations: alignment and level are given for the centreline, so the per-rail values
// follow from gauge and cross-level; a measured left/right rail pair must be converted first
// (lateral = (y_left + y_right)/2, gauge = y_left - y_right).

#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ferro::track {

enum class IrregularityChannel { kLateral, kVertical, kCrossLevel, kGauge };

/// Parses "lateral" (or "alignment"), "vertical" (or "level"), "cross_level", "gauge"; throws
/// std::invalid_argument naming `where` and the allowed values otherwise.
[[nodiscard]] IrregularityChannel irregularity_channel_from_string(std::string_view name,
                                                                   const std::string& where);
[[nodiscard]] std::string_view to_string(IrregularityChannel channel);

/// Irregularity of one rail.
struct RailIrregularity {
  double lateral = 0.0;     ///< y displacement [m]
  double vertical = 0.0;    ///< z displacement [m]
  double d_lateral = 0.0;   ///< d/ds [m/m]
  double d_vertical = 0.0;  ///< d/ds [m/m]
};

/// Irregularities at one arc length and their derivatives d/ds (multiply by the speed for time
/// rates). SI units.
struct IrregularitySample {
  double lateral = 0.0;      ///< centreline alignment, +y [m]
  double vertical = 0.0;     ///< centreline vertical profile, +z [m]
  double cross_level = 0.0;  ///< z_right - z_left [m]
  double gauge = 0.0;        ///< gauge deviation, + wider [m]
  double d_lateral = 0.0;
  double d_vertical = 0.0;
  double d_cross_level = 0.0;
  double d_gauge = 0.0;

  /// Value and derivative of one channel.
  [[nodiscard]] double value(IrregularityChannel channel) const;
  [[nodiscard]] double derivative(IrregularityChannel channel) const;
  /// Adds `value` and `derivative` to one channel.
  void add(IrregularityChannel channel, double value, double derivative);

  IrregularitySample& operator+=(const IrregularitySample& other);
  [[nodiscard]] RailIrregularity left_rail() const;
  [[nodiscard]] RailIrregularity right_rail() const;
};

/// One source of irregularity. Implementations are immutable after construction, so at() is
/// const and thread-safe.
class Irregularity {
 public:
  virtual ~Irregularity() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  /// Irregularities at arc length s [m].
  [[nodiscard]] virtual IrregularitySample at(double s) const = 0;
};

/// Sum of any number of irregularities (itself an Irregularity).
class IrregularitySum final : public Irregularity {
 public:
  IrregularitySum() = default;
  explicit IrregularitySum(std::vector<std::shared_ptr<const Irregularity>> parts);
  void add(std::shared_ptr<const Irregularity> part);
  [[nodiscard]] std::string name() const override;
  [[nodiscard]] IrregularitySample at(double s) const override;
  [[nodiscard]] std::size_t size() const { return parts_.size(); }

 private:
  std::vector<std::shared_ptr<const Irregularity>> parts_;
};

enum class DefectShape {
  /// amplitude/2 (1 - cos(2 pi x / wavelength)) per period: a bump of peak `amplitude`, value
  /// and slope continuous at both ends.
  kOneMinusCosine,
  /// amplitude sin(2 pi x / wavelength): full sine periods, value continuous, slope jumps.
  kSine,
  /// amplitude (1 - |2 x / wavelength - 1|) per period, a V: the level runs straight to
  /// `amplitude` at mid-wavelength and straight back, as the two dipped rail ends of a joint
  /// (negative amplitude: a dip). The path's slope turns by 2 alpha at the joint, alpha =
  /// 2 |amplitude| / wavelength, and by alpha at each end.
  kDippedJoint,
};
/// Parses "one_minus_cosine" (or "1-cos"), "sine" and "dipped_joint".
[[nodiscard]] DefectShape defect_shape_from_string(std::string_view name, const std::string& where);

/// An isolated defect on one channel: e.g. a lateral alignment defect (channel kLateral), a
/// vertical dip, a cross-level defect (channel kCrossLevel; its s-derivative is the twist), a
/// gauge narrowing (negative amplitude on kGauge).
struct IsolatedDefectSpec {
  IrregularityChannel channel = IrregularityChannel::kLateral;
  DefectShape shape = DefectShape::kOneMinusCosine;
  double amplitude = std::numeric_limits<double>::quiet_NaN();   ///< peak [m], signed
  double wavelength = std::numeric_limits<double>::quiet_NaN();  ///< [m], > 0
  double start_s = std::numeric_limits<double>::quiet_NaN();     ///< where the defect begins [m]
  int periods = 1;  ///< number of wavelengths the defect lasts, >= 1

  /// Throws std::invalid_argument naming `where` + field.
  void validate(const std::string& where = "defect") const;
};

class IsolatedDefect final : public Irregularity {
 public:
  explicit IsolatedDefect(const IsolatedDefectSpec& spec);
  [[nodiscard]] std::string name() const override;
  [[nodiscard]] IrregularitySample at(double s) const override;
  [[nodiscard]] const IsolatedDefectSpec& spec() const { return spec_; }

 private:
  IsolatedDefectSpec spec_;
};

}  // namespace ferro::track
