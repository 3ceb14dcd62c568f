#pragma once
// The geometry report of a wheel-rail pair (`ferrodyn geometry pair`): the contact table over
// lateral shifts of +-12 mm every 0.1 mm (HDF5), the contact-point diagram and delta_r(y)
// (contact_points.csv), the equivalent conicity against amplitude (conicity.csv) and both
// profiles in track coordinates (profiles.csv). The CSV files are in mm, rad and degrees, each
// column naming its unit.

#include <string>
#include <vector>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::scenarios {

/// Writes the report into `folder` (created when missing); returns the file names written.
std::vector<std::string> write_pair_report(const contact::WheelRailPair& pair,
                                           const std::string& folder);

}  // namespace ferro::scenarios
