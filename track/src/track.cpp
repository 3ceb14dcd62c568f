// Track = design alignment + irregularities.
//
// References: EN 13848-1:2019 (twist). Known deviations: see track.hpp.

#include "ferro/track/track.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace ferro::track {

Eigen::Vector3d TrackPoint::left_rail_position() const {
  const RailIrregularity r = irregularity.left_rail();
  return frame.position +
         frame.rotation * Eigen::Vector3d(0.0, 0.5 * frame.rail_spacing + r.lateral, r.vertical);
}

Eigen::Vector3d TrackPoint::right_rail_position() const {
  const RailIrregularity r = irregularity.right_rail();
  return frame.position +
         frame.rotation * Eigen::Vector3d(0.0, -0.5 * frame.rail_spacing + r.lateral, r.vertical);
}

Track::Track(Alignment alignment, std::shared_ptr<const Irregularity> irregularities)
    : alignment_(std::move(alignment)), irregularities_(std::move(irregularities)) {}

TrackPoint Track::at(double s) const {
  TrackPoint p;
  p.frame = alignment_.frame(s);
  if (irregularities_) p.irregularity = irregularities_->at(s);
  return p;
}

double Track::twist(double s, double base) const {
  if (!(base > 0.0)) {
    throw std::invalid_argument(fmt::format("twist: base must be positive [m] (got {})", base));
  }
  return (at(s).cross_level() - at(s - base).cross_level()) / base;
}

}  // namespace ferro::track
