#pragma once
// The description of a rail vehicle as the multibody model reads it: rigid bodies (car body,
// bogie frames, wheelsets) with their degrees of freedom, suspension elements between attachment
// points, and the wheel-rail contact choice. Plain data, SI units, no YAML: the scene loader
// (scenarios/) expands the engineers' compact vehicle files (per-axlebox primary, per-side
// secondary, ...) into this explicit form.
//
// Frame (vehicle and track, docs/DESIGN.md): x forward, y LEFT, z UP, right-handed; origin on
// the track centreline at top-of-rail level, moving along the alignment with the vehicle's
// reference point. Body positions are the centres of mass in that frame at rest; attachment
// points are in body axes relative to the centre of mass. Angles: roll about x, pitch about y,
// yaw about z (positive yaw turns the nose left). The contact layer's frame (y right, z down)
// is converted to this one at exactly one place, the wheel-rail coupling.

#include <Eigen/Core>
#include <array>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ferro/contact/kij/reduction_factors.hpp"

namespace ferro::vehicle {

/// A specification value outside its allowed range. field() names it relative to the struct
/// validated ("mass", "friction", "reduction.k22", ...) so that a loader can point at the key it
/// came from, rule() says what is allowed and what was given; what() reads
/// "<where>.<field>: <rule>".
class SpecError : public std::invalid_argument {
 public:
  SpecError(const std::string& where, std::string field, std::string rule)
      : std::invalid_argument(where + "." + field + ": " + rule),
        field_(std::move(field)),
        rule_(std::move(rule)) {}
  [[nodiscard]] const std::string& field() const noexcept { return field_; }
  [[nodiscard]] const std::string& rule() const noexcept { return rule_; }

 private:
  std::string field_, rule_;
};

/// Degrees of freedom of a body relative to the track frame, in state order.
enum class Dof : int { x = 0, y = 1, z = 2, roll = 3, pitch = 4, yaw = 5 };
inline constexpr std::array<const char*, 6> kDofNames{"x", "y", "z", "roll", "pitch", "yaw"};

enum class BodyKind { car_body, bogie_frame, wheelset };

struct RigidBodySpec {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::string name;  ///< unique, e.g. "car_body", "bogie_1", "wheelset_2"
  BodyKind kind = BodyKind::car_body;
  double mass = kNaN;                                         ///< [kg]
  Eigen::Vector3d inertia = Eigen::Vector3d::Constant(kNaN);  ///< roll, pitch, yaw [kg m^2]
  /// Centre of mass at rest in the vehicle/track frame [m] (x from the vehicle reference
  /// point, z above top of rail).
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  /// Which of x, y, z, roll, pitch, yaw are states (false: held at the rest value).
  std::array<bool, 6> active{true, true, true, true, true, true};
  // Wheelsets only:
  double nominal_rolling_radius = kNaN;  ///< r0 [m]
  bool spin_dof = false;  ///< spin-speed perturbation beta as a state (else rolling at V/r0)

  /// The only definition of a body's limits; throws SpecError naming `where`.field.
  void validate(const std::string& where) const;
};

enum class ElementType {
  spring_damper,  ///< linear spring + damper along each track axis between the two points
  series_damper,  ///< damper c in series with stiffness k along one axis (e.g. yaw damper)
  bump_stop,      ///< along one axis: free play `clearance`, then the force table
  torsion,        ///< rotational spring + damper about one axis between the bodies (anti-roll
                  ///< bar about x, bogie yaw stiffness about z)
};

struct SuspensionElementSpec {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::string name;
  ElementType type = ElementType::spring_damper;
  /// Body indices into VehicleConfig::bodies; -1 = the track frame (a fixed point moving
  /// with the track frame at body_a_point given in the track frame).
  int body_a = -1;  ///< the upper body (e.g. bogie for a primary element)
  int body_b = -1;  ///< the lower body (e.g. wheelset)
  Eigen::Vector3d point_a = Eigen::Vector3d::Zero();  ///< in body_a axes [m]
  Eigen::Vector3d point_b = Eigen::Vector3d::Zero();  ///< in body_b axes [m]
  // spring_damper: per axis x, y, z (track-frame axes to first order).
  Eigen::Vector3d stiffness = Eigen::Vector3d::Zero();  ///< [N/m]
  Eigen::Vector3d damping = Eigen::Vector3d::Zero();    ///< [N s/m]
  Eigen::Vector3d preload = Eigen::Vector3d::Zero();    ///< force at rest, on body_b [N]
  // series_damper, bump_stop, torsion: one axis.
  Dof axis = Dof::x;       ///< x, y, z (translation) or roll, yaw (torsion)
  double k = 0.0;          ///< series stiffness [N/m] / torsional stiffness [N m/rad]
  double c = 0.0;          ///< damping [N s/m] / torsional damping [N m s/rad]
  double clearance = 0.0;  ///< bump stop free play [m]
  std::vector<double> table_displacement;  ///< bump stop: total displacement [m], increasing
  std::vector<double> table_force;         ///< bump stop: force at those displacements [N]

  /// The only definition of an element's limits (`n_bodies`: the bodies body_a/body_b index);
  /// throws SpecError naming `where`.field.
  void validate(const std::string& where, int n_bodies) const;
};

/// Wheel-rail contact of every wheelset.
struct WheelRailSpec {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  /// Contact geometry: "table" (precomputed multi-point, default), "search" (online 3D),
  /// "imported" (one-point CSV table of another tool), "conical" (analytic cone, linear
  /// single-wheelset studies).
  std::string geometry = "table";
  std::string wheel_profile;  ///< file [path]
  std::string rail_profile;   ///< file [path]
  std::string imported_table; ///< CSV file for geometry "imported"
  /// Geometry "table": HDF5 cache of the multi-point table, read when it was built from the
  /// same profiles, pair and grid, otherwise built and written there; empty: in memory only.
  std::string table_file;
  /// Geometry "table": its yaw axis (the wheelset's yaw relative to the rails), symmetric from
  /// -table_yaw_max to table_yaw_max in steps of table_yaw_step, yaw 0 a node [rad]. Both 0: no
  /// yaw axis, the table answers at any yaw as at yaw 0.
  double table_yaw_max = 0.0;
  double table_yaw_step = 0.0;  ///< [rad]
  double track_gauge = 1.435;           ///< [m]
  double flange_back_distance = 1.360;  ///< [m]
  /// Flange-back position in wheel-profile coordinates [m]; NaN: the profile's smallest y
  /// (EN 13715 / S1002 profiles: -0.070).
  double flange_back_y = kNaN;
  double rail_inclination = 0.0;        ///< applied to the rail profile as read [rad]
  /// Geometry "table" / "search": when finite, the wheel tread for wheel-profile y >=
  /// wheel_tread_join_y is replaced by a cone of this conicity, continuous at the join, flange
  /// and root kept (contact::splice_conical_tread; the thesis' S1002 with a 1/10 conical tread).
  /// NaN: the wheel profile as read [-].
  double wheel_tread_conicity = kNaN;
  double wheel_tread_join_y = kNaN;     ///< [m], wheel-profile coordinates
  double conicity = kNaN;               ///< geometry "conical" [-]
  double contact_half_distance = kNaN;  ///< e, geometry "conical" [m]
  double conical_curvature_a = kNaN;    ///< A, geometry "conical" [1/m]
  double conical_curvature_b = kNaN;    ///< B, geometry "conical" [1/m]
  /// Nominal rolling radius r0 of the wheels the geometry is built for [m] (the wheelsets'
  /// nominal_rolling_radius; required by every geometry).
  double nominal_radius = kNaN;
  double friction = 0.3;                ///< mu [-]
  double shear_modulus = 82.0e9;        ///< wheel and rail G [Pa]
  double poisson = 0.28;                ///< wheel and rail nu [-]
  std::string normal_model = "hertz";   ///< hertz | semi_hertz
  std::string tangential_model = "chopaya";
  std::map<std::string, std::string> tangential_options;
  /// K_ij: constants, or a table (HDF5, docs/KIJ_TABLE.md) looked up per contact.
  contact::ReductionFactors reduction;                  ///< K11, K22, K23, K33
  std::string reduction_table;                          ///< path, empty: constants
  /// Values of the table's axes other than the patch's own (normal_force, peak_pressure, taken
  /// from each contact patch): e.g. layer_thickness, layer_shear_modulus [SI].
  std::map<std::string, double> reduction_table_point;
  /// Creepages use max(|V|, regularisation_speed) in the denominator [m/s].
  double regularisation_speed = 0.1;
  /// Hunt-Crossley damping of the normal contact force: N = N_Hertz (1 + alpha d(delta)/dt),
  /// clamped at N >= 0, with d(delta)/dt the penetration rate [s/m]. 0: undamped normal
  /// contact (Hertz alone). Linearised about a static load N0, each point adds a viscous
  /// coefficient alpha N0 [N s/m] (see wheel_rail.cpp).
  double hunt_crossley_alpha = 0.0;

  /// The only definition of the wheel-rail limits; throws SpecError naming `where`.field.
  /// validate_geometry: the geometry kind and what it requires (profiles, cone, gauge, r0; files
  /// are not opened here), checked where the source is built (make_geometry_source);
  /// validate_mechanics: friction, material, normal and tangential choice, K_ij, damping,
  /// checked by the model (which receives its geometry source built); validate: both, and the
  /// normal model's needs of the geometry (the scene loader).
  void validate_geometry(const std::string& where = "wheel_rail") const;
  void validate_mechanics(const std::string& where = "wheel_rail") const;
  void validate(const std::string& where = "wheel_rail") const;
};

struct VehicleConfig {
  std::string name;
  std::vector<RigidBodySpec> bodies;
  std::vector<SuspensionElementSpec> elements;
  WheelRailSpec wheel_rail;
  double gravity = 9.81;  ///< [m/s^2]

  /// Every body, element and the wheel-rail mechanics (fields named "mass", "k", "friction",
  /// "gravity" ... with `where` "bodies[i] ('name')", "elements[j] ('name')", "wheel_rail",
  /// "vehicle"); the geometry source is validated where it is built.
  void validate() const;
};

/// What a scene models of a vehicle: the whole vehicle, one bogie (its frame and wheelsets,
/// the car body replaced by the track frame), or one wheelset (its suspension attached to the
/// track frame at the rest positions); any DOF may be frozen, by "body.dof" (e.g.
/// "wheelset_1.roll") or by dof name for every body ("z").
struct ModelSelection {
  std::string scope = "vehicle";  ///< vehicle | bogie | wheelset
  int index = 0;                  ///< which bogie / wheelset (0-based, front first)
  std::vector<std::string> frozen;
};

}  // namespace ferro::vehicle
