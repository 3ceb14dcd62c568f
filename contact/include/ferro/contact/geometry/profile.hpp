#pragma once
// Wheel and rail cross-section profiles: reading (SIMPACK .prw/.prr, plain two-column mm files),
// checks, inclination, gauge point, resampling and smoothing, generators.
//
// Profile frame (both wheel and rail, for the RIGHT-hand side of the track): y lateral, positive
// towards the field side (away from the track centre); z vertical, positive DOWNWARDS. For a wheel,
// z is the radius increase over the nominal radius at y = 0 (taping line), so the flange has large
// positive z at negative y. For a rail, z is the depth below the profile origin, the gauge face
// is at negative y. This is the frame of SIMPACK files after their own mirror/inversion flags.
// All coordinates are in metres (files in mm are converted once at load).
//
// References: SIMPACK Rail-Wheel Profile file format (header/spline/point blocks, processing
// flags 1-7 applied in their numbered order); EN 13715 (wheel profile datum: taping line 70 mm
// from the flange back); EN 13848-1 (gauge measured 14 mm below the top of rail).
// Known deviations: SIMPACK "approx.smooth" and per-point weights are read but ignored (the
// profiles are used as given); "bound.*" limits are applied only when min < max; rotation
// ("rotate") is applied about the file origin.

#include <limits>
#include <string>
#include <vector>

namespace ferro::contact {

enum class ProfileKind { wheel, rail };

/// A profile as an ordered polyline, y strictly increasing after `check_profile`. SI units.
struct Profile {
  ProfileKind kind = ProfileKind::rail;
  std::vector<double> y;  ///< lateral coordinate [m], increasing
  std::vector<double> z;  ///< vertical coordinate [m], positive downwards
  std::vector<int> line;  ///< source-file line of each point (0 when generated)
  std::string source;     ///< file name or generator description, for messages

  [[nodiscard]] std::size_t size() const { return y.size(); }
};

/// Reads a SIMPACK rail (.prr) or wheel (.prw) profile. Applies shift, rotate, bound, mirror and
/// inversion flags and the length unit factor, orders the points by increasing y and checks them.
/// Throws std::invalid_argument("<file>:<line>: ...") for unreadable, non-monotone or
/// self-intersecting data.
[[nodiscard]] Profile read_simpack_profile(const std::string& path);

/// Reads a plain text file of "y z" pairs in millimetres (blank lines and lines starting with
/// '#', '!' or '%' are skipped; ',' ';' and tabs separate columns). Same checks as above.
[[nodiscard]] Profile read_two_column_profile(const std::string& path, ProfileKind kind);

/// Reads by extension: .prw (wheel) / .prr (rail) as SIMPACK, anything else as two-column mm
/// with the given kind.
[[nodiscard]] Profile read_profile(const std::string& path, ProfileKind kind_if_plain);

/// Orders the points by increasing y and throws std::invalid_argument naming the source and line
/// when two segments intersect (self-intersecting) or y is not strictly monotone (a profile must
/// be single-valued in y to be used by the contact search), or fewer than 4 points.
void check_profile(Profile& profile);

/// Rotates a rail profile by `inclination` [rad] about its origin so that its head leans
/// towards the track centre (1:40 -> atan(1/40)): y' = c y + s z, z' = -s y + c z. Points of
/// a flank that the rotation turns under the head (not visible from above) are dropped.
[[nodiscard]] Profile incline_rail(const Profile& rail, double inclination);

/// Top of rail: the highest point (smallest z) of a rail profile, y and z [m].
struct RailReference {
  double top_y = std::numeric_limits<double>::quiet_NaN();    ///< [m]
  double top_z = std::numeric_limits<double>::quiet_NaN();    ///< [m]
  double gauge_y = std::numeric_limits<double>::quiet_NaN();  ///< [m] gauge point
  double gauge_z = std::numeric_limits<double>::quiet_NaN();  ///< [m]
};
/// Finds the top of rail and the gauge point: the innermost (smallest y) point of the gauge
/// face at `gauge_depth` [m] below the top of rail (14 mm by EN 13848-1). Throws if the profile
/// does not reach that depth on its gauge side.
[[nodiscard]] RailReference rail_reference(const Profile& rail, double gauge_depth = 0.014);

/// Resamples by arc length at spacing `ds` [m] along a chord-length cubic spline through the
/// points: every original corner is kept to within the spline's accuracy, so the flange and the
/// gauge corner survive.
[[nodiscard]] Profile resample_profile(const Profile& profile, double ds);

/// Gaussian smoothing along the arc length with standard deviation `sigma` [m] (|window| = 3
/// sigma); end points are fixed. Corners with radius well above sigma (S1002 flange root
/// R = 12-20 mm, 60E1 gauge corner R = 13 mm) keep their shape to O(sigma^2 / R).
[[nodiscard]] Profile smooth_profile(const Profile& profile, double sigma);

/// A purely conical wheel tread of given conicity (tan of the cone half-angle complement, e.g.
/// 0.1 for 1/10): z(y) = -conicity * y over [y_min, y_max] [m] with spacing `step` [m].
[[nodiscard]] Profile make_conical_tread(double conicity, double y_min = -0.060,
                                         double y_max = 0.060, double step = 0.5e-3);

/// Replaces the tread of a wheel profile for y >= y_join [m] by a cone of the given conicity,
/// continuous in z at y_join (the flange and its root are kept). The thesis' 1/10 variant.
[[nodiscard]] Profile splice_conical_tread(const Profile& wheel, double conicity, double y_join);

/// S1002 wheel profile from the piecewise EN 13715 definition (sections A-H: a line, two
/// polynomials of degree 8 and 7, a line and four circular arcs), in the profile frame above
/// (flange back at y = -70 mm, taping line at y = 0, z = radius increase), sampled every
/// `step` [m] over [-70, 60] mm, plus the section boundaries.
[[nodiscard]] Profile make_s1002_wheel(double step = 0.1e-3);

/// 60E1 (UIC60) rail head from its arcs: R300 crown, R80, R13 gauge/field corners, 1:20 head
/// flanks, symmetric, each arc tangent to the next; rail frame with the origin at the crown top
/// on the rail axis, not inclined (use incline_rail). The radii and the flank slope are those of
/// EN 13674-1; the lateral ends of the R300 and R80 arcs (`y_r300_end`, `y_r80_end` [m]) are
/// parameters: their defaults (10.50 mm, 25.99 mm) are reconstructed from the Manchester
/// benchmark rail file, which is this exact construction (residual 0.03 um), not taken from the
/// EN drawing. Sampled every `step` [m] down to `depth` [m] below the crown.
[[nodiscard]] Profile make_60e1_rail(double y_r300_end = 10.50e-3, double y_r80_end = 25.99e-3,
                                     double depth = 0.035, double step = 0.1e-3);

}  // namespace ferro::contact
