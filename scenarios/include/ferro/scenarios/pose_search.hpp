#pragma once
// Contact points of prescribed wheelset positions (`ferrodyn geometry search`): the pair built
// from two profile files and a few track and wheelset numbers, the pose solved for what is
// given (rigid contact, a prescribed axle height, or a total vertical load), and the lead of
// each contact point ahead of the axle. SI units throughout; the batch CSV writes profile
// millimetres as the Manchester benchmark files do, every column naming its unit.

#include <functional>
#include <istream>
#include <limits>
#include <string>
#include <vector>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/scenarios/parameters.hpp"

namespace ferro::scenarios {

/// A wheel-rail pair from two profile files (SI).
struct SearchPairOptions {
  std::string wheel, rail;     ///< profile files (.prw/.prr or two-column mm)
  double gauge = 1.435;        ///< track gauge [m]
  double gauge_depth = 0.014;  ///< gauge measured below the top of rail [m]
  double flange_back = 1.360;  ///< flange-back distance [m]
  /// Flange-back position in wheel-profile coordinates [m] (NaN: the profile's first point).
  double flange_back_y = std::numeric_limits<double>::quiet_NaN();
  double radius = 0.460;          ///< nominal wheel radius at the taping line [m]
  std::string inclination = "0";  ///< rail inclination: 1:40, 1:20, 0 or an angle [rad]
  double section_step = 0.5e-3;   ///< wheel section spacing [m]
  double shear_modulus = 82.0e9;  ///< of wheel and rail, for a load solve [Pa]
  double poisson = 0.28;          ///< of wheel and rail, for a load solve [-]
};
/// Reads the profiles and builds the pair; errors name the file or the option
/// (`inclination_name` for the inclination).
[[nodiscard]] contact::WheelRailPair make_search_pair(
    const SearchPairOptions& options, const std::string& inclination_name = "inclination");

/// What is prescribed of the wheelset (SI). With neither height nor load: rigid contact, just
/// touching (roll solved unless given non-zero).
struct PoseInput {
  double y = 0.0;     ///< lateral shift, + to the right [m]
  double roll = 0.0;  ///< [rad], + lowers the right wheel
  double yaw = 0.0;   ///< [rad], + turns the front to the right
  double height = std::numeric_limits<double>::quiet_NaN();  ///< axle drop, + down [m]
  double load = std::numeric_limits<double>::quiet_NaN();    ///< total vertical load [N]
};

struct PoseResult {
  contact::WheelsetPose pose;
  std::vector<contact::ContactPoint> points;
};

/// Plane-strain modulus E* = E / (2 (1 - nu^2)) of two equal bodies of shear modulus
/// `shear_modulus` [Pa] and Poisson ratio `poisson` [-], for the load solve [Pa].
[[nodiscard]] double pose_search_modulus(double shear_modulus, double poisson);

/// The options and the pose as parameters (see parameters.hpp).
[[nodiscard]] Parameters parameters(SearchPairOptions& options);
[[nodiscard]] Parameters parameters(PoseInput& pose);

/// The pose and its contact points for `in`; `estar` [Pa] (pose_search_modulus) is used only
/// with a load.
[[nodiscard]] PoseResult solve_pose(const contact::WheelRailPair& pair, const PoseInput& in,
                                    double estar);

/// Longitudinal position of a contact point ahead of the axle centre [m] (track x): the point's
/// own x plus the yaw's lever on its lateral position.
[[nodiscard]] double contact_lead(const contact::WheelRailPair& pair,
                                  const contact::WheelsetPose& pose,
                                  const contact::ContactPoint& p);

/// Batch search over a CSV (header with y [m] and optional roll, yaw [rad], height [m], load
/// [N]; y_mm, roll_rad, yaw_rad, height_mm, load_n also read; other columns are copied): `emit`
/// receives the header line, then for each input row its lines, one per contact point (or one
/// "none" line), each ending in '\n'. Errors name `source` and the line.
void search_pose_batch(const contact::WheelRailPair& pair, std::istream& in,
                       const std::string& source, const PoseInput& defaults, double estar,
                       const std::function<void(const std::string&)>& emit);

}  // namespace ferro::scenarios
