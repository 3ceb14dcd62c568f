// The contact geometry source a vehicle's wheel_rail block asks for (table, search, imported,
// conical), built by the contact layer.

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "ferro/contact/geometry/contact_source_factory.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::vehicle {
std::shared_ptr<const contact::ContactGeometrySource> make_geometry_source(
    const WheelRailSpec& spec, const std::string& base_dir) {
  const auto resolve = [&base_dir](const std::string& path) {
    if (path.empty() || path.front() == '/' || base_dir.empty()) return path;
    return base_dir + "/" + path;
  };
  spec.validate_geometry("wheel_rail");
  contact::ContactSourceSpec cs;
  cs.kind = spec.geometry;
  if (spec.geometry == "conical") {
    cs.conical.conicity = spec.conicity;
    cs.conical.contact_half_distance = spec.contact_half_distance;
    cs.conical.nominal_radius = spec.nominal_radius;
    cs.conical.curvature_a = spec.conical_curvature_a;
    cs.conical.curvature_b = spec.conical_curvature_b;
  } else if (spec.geometry == "search" || spec.geometry == "table") {
    cs.wheel_profile = resolve(spec.wheel_profile);
    cs.rail_profile = resolve(spec.rail_profile);
    cs.pair.track_gauge = spec.track_gauge;
    cs.pair.flange_back_distance = spec.flange_back_distance;
    cs.pair.flange_back_y = spec.flange_back_y;
    cs.pair.nominal_radius = spec.nominal_radius;
    cs.pair.rail_inclination = spec.rail_inclination;
    cs.table_file = resolve(spec.table_file);
    if (spec.table_yaw_max > 0.0) {
      cs.table.yaw_min = -spec.table_yaw_max;
      cs.table.yaw_max = spec.table_yaw_max;
      cs.table.yaw_step = spec.table_yaw_step;
    }
    if (std::isfinite(spec.wheel_tread_conicity)) {
      cs.wheel_tread_conicity = spec.wheel_tread_conicity;
      cs.wheel_tread_join_y = spec.wheel_tread_join_y;
    }
  } else if (spec.geometry == "imported") {
    cs.imported_table = resolve(spec.imported_table);
  }
  try {
    return contact::make_contact_source(cs);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(
        fmt::format("wheel_rail (geometry {}): {}", spec.geometry, e.what()));
  }
}

}  // namespace ferro::vehicle
