#pragma once
// The track a vehicle runs on: design alignment plus irregularities, evaluated together.
//
// Rail reference points include the irregularities in track axes:
//   p_left  = position + R (0,  b/2 + y_left_irr,  z_left_irr),
//   p_right = position + R (0, -b/2 + y_right_irr, z_right_irr),
// with b = rail_spacing and the per-rail irregularities of irregularity.hpp. Twist over a base
// length is the change of total cross-level (design cant + cross-level irregularity) over that
// base divided by the base (EN 13848-1 twist, as a gradient).
//
// References: EN 13848-1:2019 §3 (twist over a base length); irregularity and alignment
// conventions as alignment.hpp and irregularity.hpp.
// Known deviations: irregularities displace the rails in the design track frame (small
// displacements; the frame itself is not rotated by them).

#include <Eigen/Core>
#include <memory>

#include "ferro/track/alignment.hpp"
#include "ferro/track/irregularity.hpp"

namespace ferro::track {

/// Design frame and irregularities at one arc length.
struct TrackPoint {
  TrackFrame frame;
  IrregularitySample irregularity;

  /// Rail reference points with irregularities, ground frame [m].
  [[nodiscard]] Eigen::Vector3d left_rail_position() const;
  [[nodiscard]] Eigen::Vector3d right_rail_position() const;
  /// Actual gauge (design gauge incl. widening + gauge irregularity) [m].
  [[nodiscard]] double gauge() const { return frame.gauge + irregularity.gauge; }
  /// Actual cross-level z_right - z_left (design cant + cross-level irregularity) [m].
  [[nodiscard]] double cross_level() const { return frame.cant + irregularity.cross_level; }
};

class Track {
 public:
  /// `irregularities` may be null (perfect track).
  Track(Alignment alignment, std::shared_ptr<const Irregularity> irregularities = nullptr);

  [[nodiscard]] TrackPoint at(double s) const;
  /// Twist over `base` ending at s: (cross_level(s) - cross_level(s - base)) / base [m/m];
  /// both ends must lie on the design.
  [[nodiscard]] double twist(double s, double base) const;

  [[nodiscard]] const Alignment& alignment() const { return alignment_; }
  [[nodiscard]] const Irregularity* irregularities() const { return irregularities_.get(); }

 private:
  Alignment alignment_;
  std::shared_ptr<const Irregularity> irregularities_;
};

}  // namespace ferro::track
