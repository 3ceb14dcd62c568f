#pragma once
// Design (nominal) geometry of a track as plain parameter structs: a sequence of sections along
// the arc length (straight, clothoid transition, circular curve), cant and gauge widening.
// The scene loader fills these from YAML; Alignment (alignment.hpp) turns them into the moving
// track frame.
//
// References: Toumi (2016) §4.2, eq. (148) (cant D = 2 e V^2 / (R g), e = half the distance
// between the rails); EN 13803:2017 "Track alignment design parameters" (clothoid transitions
// with linear curvature and linear cant ramps; 1500 mm reference distance between the rail
// contact points for standard gauge; cant deficiency I = 11.8 V^2/R - D in mm, km/h).
// Known deviations: plan geometry only (no vertical gradient or vertical curves: z of the
// centreline is 0); cant is a rotation about the centreline (real track usually keeps the low
// rail at grade, which lifts the centreline by |D|/2); only linear cant ramps (no Bloss or
// sinusoidal ramps).

#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace ferro::track {

enum class SectionKind {
  kStraight,    ///< zero curvature, zero cant
  kTransition,  ///< clothoid: curvature, cant and gauge widening vary linearly between neighbours
  kCurve,       ///< circular arc of constant radius, cant and gauge widening
};

/// Parses "straight", "transition" (or "clothoid") and "curve" (or "circular"); throws
/// std::invalid_argument naming `where` and the allowed values otherwise.
[[nodiscard]] SectionKind section_kind_from_string(std::string_view name,
                                                   const std::string& where = "kind");
[[nodiscard]] std::string_view to_string(SectionKind kind);

/// One section of the design alignment.
///
/// A transition takes its end values (curvature, cant, gauge widening) from its neighbours:
/// the value at the end of the previous section and at the start of the next one (a straight,
/// or the track end, counts as zero). So a typical curve is written straight, transition,
/// curve, transition, straight, and only the curve carries radius and cant.
struct SectionSpec {
  SectionKind kind = SectionKind::kStraight;
  double length = std::numeric_limits<double>::quiet_NaN();  ///< arc length [m], > 0
  /// Curve only: signed radius [m]; positive turns left (towards +y, heading increases).
  double radius = std::numeric_limits<double>::quiet_NaN();
  /// Curve only: cant (superelevation) = height of the right rail minus the left rail [m],
  /// measured over `TrackDesign::rail_spacing`. Positive cant compensates a left-hand curve,
  /// i.e. cant normally has the sign of the curvature.
  double cant = 0.0;
  /// Curve only: gauge widening added to the nominal gauge [m], >= 0.
  double gauge_widening = 0.0;

  /// Throws std::invalid_argument naming `where` + field (e.g. "sections[2].radius").
  void validate(const std::string& where = "section") const;
};

/// The whole design alignment, starting at arc length `start_s` at a given plan position and
/// heading.
struct TrackDesign {
  std::vector<SectionSpec> sections;  ///< at least one
  double start_s = 0.0;               ///< arc length of the first section's start [m]
  double start_x = 0.0;               ///< plan position of the start [m]
  double start_y = 0.0;               ///< [m]
  double start_heading = 0.0;         ///< heading of the start tangent from +x [rad]
  /// Nominal track gauge [m] (standard gauge 1435 mm, measured 14 mm below the top of rail).
  double gauge = 1.435;
  /// Distance between the rail contact points used to turn cant (a height) into the cant angle,
  /// 2e in eq. (148) [m]. EN 13803 uses 1500 mm for standard gauge.
  double rail_spacing = 1.5;

  /// Checks every field and the section sequence (a transition may not follow a transition;
  /// cant must be smaller than rail_spacing); throws std::invalid_argument naming the field,
  /// e.g. "sections[2].radius: must be non-zero and finite for a curve (got 0)"; with a
  /// non-empty `where` every field is prefixed, e.g. "track.sections[2].radius: ...".
  void validate(const std::string& where = "") const;
  /// Sum of section lengths [m].
  [[nodiscard]] double total_length() const;
};

}  // namespace ferro::track
