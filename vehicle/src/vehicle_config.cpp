// Limits of the vehicle description: the one place they are defined. The scene loader calls
// these after reading a block (and points at the key a SpecError names); the model calls them
// before building.

#include "ferro/vehicle/vehicle_config.hpp"

#include <fmt/format.h>

#include <cmath>

namespace ferro::vehicle {
namespace {

void require(bool ok, const std::string& where, const std::string& field,
             const std::string& rule) {
  if (!ok) throw SpecError(where, field, rule);
}

bool finite_positive(double v) { return std::isfinite(v) && v > 0.0; }

void validate_spring_damper(const SuspensionElementSpec& s, const std::string& where) {
  require(s.stiffness.allFinite() && (s.stiffness.array() >= 0.0).all(), where, "stiffness",
          "must be finite and >= 0 N/m");
  require(s.damping.allFinite() && (s.damping.array() >= 0.0).all(), where, "damping",
          "must be finite and >= 0 N s/m");
  require(s.preload.allFinite(), where, "preload", "must be finite [N]");
}

void validate_bump_stop(const SuspensionElementSpec& s, const std::string& where) {
  require(static_cast<int>(s.axis) <= 2, where, "axis", "bump_stop acts along x, y or z");
  require(std::isfinite(s.clearance) && s.clearance >= 0.0, where, "clearance",
          fmt::format("must be >= 0 m, got {}", s.clearance));
  const auto& xs = s.table_displacement;
  require(!xs.empty() && xs.size() == s.table_force.size(), where, "displacement",
          "the displacement and force tables need equal, non-zero lengths");
  require(xs.size() >= 2 || xs.front() > s.clearance, where, "displacement",
          "needs two points or one beyond the clearance");
  for (std::size_t i = 0; i < xs.size(); ++i) {
    require(std::isfinite(xs[i]) && std::isfinite(s.table_force[i]) && xs[i] >= s.clearance &&
                (i == 0 || xs[i] > xs[i - 1]),
            where, "displacement",
            fmt::format("entry {} must be finite, >= the clearance and increasing", i));
  }
}

void validate_conical(const WheelRailSpec& w, const std::string& where) {
  require(finite_positive(w.conicity), where, "conicity",
          fmt::format("required for geometry 'conical': the equivalent conicity (> 0), got {}",
                      w.conicity));
  require(finite_positive(w.contact_half_distance), where, "contact_half_distance",
          fmt::format("required for geometry 'conical': half the lateral distance between the "
                      "contact points (> 0 m), got {}",
                      w.contact_half_distance));
  require(finite_positive(w.conical_curvature_a), where, "conical_curvature_a",
          "required for geometry 'conical': the longitudinal relative curvature A of the Hertz "
          "contact (> 0 1/m)");
  require(finite_positive(w.conical_curvature_b), where, "conical_curvature_b",
          "required for geometry 'conical': the lateral relative curvature B of the Hertz "
          "contact (> 0 1/m)");
}

void validate_profiles(const WheelRailSpec& w, const std::string& where) {
  require(!w.wheel_profile.empty(), where, "wheel_profile",
          fmt::format("required for geometry '{}': the wheel profile file", w.geometry));
  require(!w.rail_profile.empty(), where, "rail_profile",
          fmt::format("required for geometry '{}': the rail profile file", w.geometry));
  require(std::isfinite(w.flange_back_distance) && w.flange_back_distance > 0.0 &&
              w.flange_back_distance < w.track_gauge,
          where, "flange_back_distance",
          fmt::format("must lie in (0, track_gauge = {}) m, got {}", w.track_gauge,
                      w.flange_back_distance));
  require(std::isnan(w.flange_back_y) || std::abs(w.flange_back_y) < 0.2, where, "flange_back_y",
          fmt::format("must lie in (-0.2, 0.2) m (wheel-profile y), got {}", w.flange_back_y));
  require(std::isfinite(w.rail_inclination) && std::abs(w.rail_inclination) <= 0.2, where,
          "rail_inclination",
          fmt::format("must lie in [-0.2, 0.2] rad (1:40 is 0.025), got {}", w.rail_inclination));
  if (!std::isnan(w.wheel_tread_conicity) || !std::isnan(w.wheel_tread_join_y)) {
    require(w.wheel_tread_conicity > 0.0 && w.wheel_tread_conicity < 1.0, where,
            "wheel_conical_tread.conicity",
            fmt::format("must lie in (0, 1), got {}", w.wheel_tread_conicity));
    require(std::abs(w.wheel_tread_join_y) < 0.1, where, "wheel_conical_tread.join_y",
            fmt::format("must lie in (-0.1, 0.1) m (wheel-profile y, taping line at 0), got {}",
                        w.wheel_tread_join_y));
  }
}

}  // namespace

void RigidBodySpec::validate(const std::string& where) const {
  require(!name.empty(), where, "name", "must not be empty");
  require(finite_positive(mass), where, "mass", fmt::format("must be > 0 kg, got {}", mass));
  require(inertia.allFinite() && (inertia.array() > 0.0).all(), where, "inertia",
          fmt::format("roll, pitch, yaw must be > 0 kg m^2, got ({}, {}, {})", inertia.x(),
                      inertia.y(), inertia.z()));
  require(position.allFinite(), where, "position", "must be finite [m]");
  if (kind == BodyKind::wheelset) {
    require(finite_positive(nominal_rolling_radius) && nominal_rolling_radius < 2.0, where,
            "nominal_rolling_radius",
            fmt::format("must lie in (0, 2) m, got {}", nominal_rolling_radius));
  }
}

void SuspensionElementSpec::validate(const std::string& where, int n_bodies) const {
  require(body_b >= 0 && body_b < n_bodies, where, "body_b",
          fmt::format("must index a body (0..{}), got {}", n_bodies - 1, body_b));
  require(body_a >= -1 && body_a < n_bodies && body_a != body_b, where, "body_a",
          fmt::format("must index another body or be -1 (track frame), got {}", body_a));
  require(point_a.allFinite() && point_b.allFinite(), where, "point_a",
          "attachment points must be finite [m]");
  switch (type) {
    case ElementType::spring_damper:
      validate_spring_damper(*this, where);
      break;
    case ElementType::series_damper:
      require(static_cast<int>(axis) <= 2, where, "axis", "series_damper acts along x, y or z");
      require(finite_positive(k), where, "k",
              fmt::format("series stiffness must be > 0 N/m, got {}", k));
      require(finite_positive(c), where, "c", fmt::format("damping must be > 0 N s/m, got {}", c));
      break;
    case ElementType::bump_stop:
      validate_bump_stop(*this, where);
      break;
    case ElementType::torsion:
      require(axis == Dof::roll || axis == Dof::yaw, where, "axis",
              "torsion acts about roll or yaw");
      require(std::isfinite(k) && k >= 0.0, where, "k",
              fmt::format("must be finite and >= 0 N m/rad, got {}", k));
      require(std::isfinite(c) && c >= 0.0, where, "c",
              fmt::format("must be finite and >= 0 N m s/rad, got {}", c));
      break;
  }
}

namespace {

// The table's yaw axis: symmetric about 0, 0 a node, at most kMaxTableYaw (the angles of attack
// of railway wheelsets stay below ~0.03 rad even in 100 m curves).
void validate_table_yaw(const WheelRailSpec& w, const std::string& where) {
  constexpr double kMaxTableYaw = 0.1;  // [rad]
  require(w.geometry == "table", where, "table_yaw",
          fmt::format("applies to geometry table, not '{}'", w.geometry));
  require(std::isfinite(w.table_yaw_max) && w.table_yaw_max > 0.0 &&
              w.table_yaw_max <= kMaxTableYaw,
          where, "table_yaw.max",
          fmt::format("must lie in (0, {}] rad, got {}", kMaxTableYaw, w.table_yaw_max));
  require(std::isfinite(w.table_yaw_step) && w.table_yaw_step > 0.0 &&
              w.table_yaw_step <= w.table_yaw_max,
          where, "table_yaw.step",
          fmt::format("must lie in (0, max = {}] rad, got {}", w.table_yaw_max,
                      w.table_yaw_step));
  const double steps = w.table_yaw_max / w.table_yaw_step;
  require(std::abs(steps - std::round(steps)) <= 1e-6 * steps, where, "table_yaw.step",
          fmt::format("max / step = {} must be a whole number (yaw 0 is a node of the axis)",
                      steps));
}

}  // namespace

void WheelRailSpec::validate_geometry(const std::string& where) const {
  require(geometry == "table" || geometry == "search" || geometry == "imported" ||
              geometry == "conical",
          where, "geometry",
          fmt::format("'{}' is not one of table, search, imported, conical", geometry));
  require(std::isfinite(track_gauge) && track_gauge > 1.0 && track_gauge < 2.0, where,
          "track_gauge", fmt::format("must lie in (1, 2) m, got {}", track_gauge));
  if (geometry == "table" || geometry == "search") validate_profiles(*this, where);
  if (geometry == "imported") {
    require(!imported_table.empty(), where, "imported_table",
            "required for geometry 'imported': the CSV contact table");
  }
  if (geometry == "conical") validate_conical(*this, where);
  if (table_yaw_max != 0.0 || table_yaw_step != 0.0) validate_table_yaw(*this, where);
  if (geometry != "table" && geometry != "search") {
    require(std::isnan(wheel_tread_conicity), where, "wheel_conical_tread",
            fmt::format("applies to geometry table or search, not '{}'", geometry));
  }
  require(finite_positive(nominal_radius), where, "nominal_radius",
          fmt::format("the wheels' nominal rolling radius must be > 0 m, got {}",
                      nominal_radius));
}

void WheelRailSpec::validate_mechanics(const std::string& where) const {
  require(std::isfinite(friction) && friction > 0.0 && friction <= 2.0, where, "friction",
          fmt::format("must lie in (0, 2], got {}", friction));
  require(finite_positive(shear_modulus), where, "shear_modulus",
          fmt::format("must be > 0 Pa, got {}", shear_modulus));
  require(std::isfinite(poisson) && poisson >= 0.0 && poisson < 0.5, where, "poisson",
          fmt::format("must lie in [0, 0.5), got {}", poisson));
  require(normal_model == "hertz" || normal_model == "semi_hertz", where, "normal",
          fmt::format("'{}' is not available in the vehicle model; allowed: hertz, semi_hertz",
                      normal_model));
  const std::pair<const char*, double> factors[] = {{"k11", reduction.k11},
                                                    {"k22", reduction.k22},
                                                    {"k23", reduction.k23},
                                                    {"k33", reduction.k33}};
  for (const auto& [name, k] : factors) {
    require(std::isfinite(k) && k > 0.0 && k <= 1.0, where, fmt::format("reduction.{}", name),
            fmt::format("K_ij must lie in (0, 1], got {}", k));
  }
  for (const auto& [axis, value] : reduction_table_point) {
    require(std::isfinite(value), where, fmt::format("reduction_table_point.{}", axis),
            "must be finite");
  }
  require(finite_positive(regularisation_speed), where, "regularisation_speed",
          fmt::format("must be > 0 m/s, got {}", regularisation_speed));
  require(std::isfinite(hunt_crossley_alpha) && hunt_crossley_alpha >= 0.0, where,
          "hunt_crossley_alpha",
          fmt::format("must be finite and >= 0 s/m (0: undamped normal contact), got {}",
                      hunt_crossley_alpha));
}

void WheelRailSpec::validate(const std::string& where) const {
  validate_geometry(where);
  validate_mechanics(where);
  require(normal_model != "semi_hertz" || geometry == "table" || geometry == "search", where,
          "normal",
          fmt::format("semi_hertz reads the gap of the wheel and rail profiles around each "
                      "contact point, which geometry '{}' does not have; allowed: normal hertz "
                      "with geometry '{}', or normal semi_hertz with geometry table or search",
                      geometry, geometry));
}

void VehicleConfig::validate() const {
  require(std::isfinite(gravity) && gravity > 0.0, "vehicle", "gravity",
          fmt::format("must be > 0 m/s^2, got {}", gravity));
  require(!bodies.empty(), "vehicle", "bodies", "at least one body is required");
  const int n = static_cast<int>(bodies.size());
  for (int i = 0; i < n; ++i) {
    const RigidBodySpec& b = bodies[static_cast<std::size_t>(i)];
    const std::string where = fmt::format("bodies[{}] ('{}')", i, b.name);
    b.validate(where);
    for (int j = 0; j < i; ++j) {
      require(bodies[static_cast<std::size_t>(j)].name != b.name, where, "name",
              fmt::format("duplicate of bodies[{}]", j));
    }
  }
  for (std::size_t i = 0; i < elements.size(); ++i) {
    elements[i].validate(fmt::format("elements[{}] ('{}')", i, elements[i].name), n);
  }
  wheel_rail.validate_mechanics("wheel_rail");
}

}  // namespace ferro::vehicle
