#pragma once
// Builds the contact geometry source a scene asks for: the multi-point table (default), the
// online search, an imported one-point table or the analytic cone.
//
// References: see each source's header.
// Known deviations: see each source's header.

#include <array>
#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "ferro/contact/geometry/conical_source.hpp"
#include "ferro/contact/geometry/contact_geometry_source.hpp"
#include "ferro/contact/geometry/multi_point_contact_table.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::contact {

/// What make_contact_source() builds. SI units; files as paths (relative to the working
/// directory; callers resolve them against their own base directory first).
struct ContactSourceSpec {
  /// "table" (multi-point table, default), "search" (online 3D search), "imported" (one-point
  /// CSV table), "conical" (analytic cone).
  std::string kind = "table";
  std::string wheel_profile;  ///< table, search: wheel profile file (read_profile)
  /// table, search: when finite, the wheel's tread is replaced by a cone of this conicity from
  /// wheel_tread_join_y on (splice_conical_tread(); the thesis' 1/10 variant) [-, m].
  double wheel_tread_conicity = std::numeric_limits<double>::quiet_NaN();
  double wheel_tread_join_y = std::numeric_limits<double>::quiet_NaN();
  std::string rail_profile;     ///< table, search: rail profile file (read_profile)
  WheelRailPairParams pair;     ///< table, search
  MultiPointTableParams table;  ///< table: grid
  /// table: HDF5 cache. Read when it exists and was built from the same profiles, pair and grid
  /// (fingerprint attribute); otherwise built and written there. Empty: built in memory only.
  std::string table_file;
  std::string imported_table;    ///< imported: CSV file
  ConicalContactParams conical;  ///< conical
};

/// The allowed values of ContactSourceSpec::kind.
inline constexpr std::array<std::string_view, 4> kContactSourceKinds{"table", "search", "imported",
                                                                     "conical"};

/// Builds the source `spec` asks for. Throws std::invalid_argument naming the field (e.g.
/// "ContactSourceSpec.kind: 'x' is not one of table, search, imported, conical") or the file.
[[nodiscard]] std::shared_ptr<const ContactGeometrySource> make_contact_source(
    const ContactSourceSpec& spec);

}  // namespace ferro::contact
