#pragma once
// Contact tables of a wheel-rail pair over lateral shift (and yaw): rigid contact (both wheels
// touching, roll free) per EN 15302, stored to / read from HDF5, interpolated at run time; and the
// equivalent conicity by harmonic linearisation of the rolling-radius difference.
//
// References: EN 15302:2008+A1:2010 (rolling-radius difference of the rigid wheelset, equivalent
// conicity); Gelb & Vander Velde, "Multiple-input describing functions" (1968) (harmonic
// linearisation: the equivalent gain is the first Fourier coefficient over the amplitude);
// Wickens, "Fundamentals of Rail Vehicle Dynamics" (2003) ch. 2 (roll coefficient).
// Known deviations: equivalent conicity uses the harmonic-linearisation formula
// lambda_e(a) = 1/(2 pi a) * integral_0^2pi delta_r(a sin t) sin t dt only; EN 15302's
// regression and Klingel-integration variants are not implemented. Interpolation is
// (bi)linear, so jumps of the contact point (two-point contact) are smeared over one step.

#include <array>
#include <string>
#include <vector>

#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::contact {

/// Grid of a contact table. SI units.
struct ContactTableParams {
  double lateral_min = -0.012;   ///< [m]
  double lateral_max = 0.012;    ///< [m]
  double lateral_step = 0.1e-3;  ///< [m]
  std::vector<double> yaw{0.0};  ///< yaw angles [rad], increasing; one value: no yaw dimension
  void validate() const;
};

/// Interpolated contact quantities of the main (deepest) point on each wheel; index 0 = left,
/// 1 = right.
struct ContactTableEntry {
  double delta_r = 0.0;                    ///< r_right - r_left [m]
  double roll = 0.0;                       ///< wheelset roll [rad]
  double vertical = 0.0;                   ///< axle-centre drop [m]
  double roll_coefficient = 0.0;           ///< sigma = e d(roll)/dy [-]
  std::array<double, 2> rolling_radius{};  ///< [m]
  std::array<double, 2> contact_angle{};   ///< [rad], + towards the track centre
  std::array<double, 2> curvature_a{};     ///< [1/m]
  std::array<double, 2> curvature_b{};     ///< [1/m]
  std::array<double, 2> wheel_y{};         ///< contact point on the wheel profile [m]
  std::array<double, 2> rail_y{};          ///< contact point on the rail profile [m]
  std::array<double, 2> lateral{};         ///< track y of the contact point [m]
  std::array<double, 2> longitudinal{};    ///< track x of the contact point [m]
};

class ContactTable {
 public:
  static constexpr int kColumns = 21;
  static const std::array<const char*, kColumns>& column_names();

  /// Tabulates the rigid contact of `pair` on the grid.
  static ContactTable build(const WheelRailPair& pair, const ContactTableParams& params);
  /// Reads a table written by save_hdf5; throws std::invalid_argument naming the file/dataset.
  static ContactTable load_hdf5(const std::string& path);
  /// Writes /lateral, /yaw and one [n_yaw x n_lateral] dataset per column (SI, units attribute).
  void save_hdf5(const std::string& path) const;

  /// Linear interpolation in lateral shift (bilinear with yaw), clamped at the table ends.
  [[nodiscard]] ContactTableEntry lookup(double lateral, double yaw = 0.0) const;
  /// Only the rolling-radius difference [m] (fast path).
  [[nodiscard]] double delta_r(double lateral, double yaw = 0.0) const;

  [[nodiscard]] const std::vector<double>& lateral() const { return lateral_; }
  [[nodiscard]] const std::vector<double>& yaw() const { return yaw_; }
  /// Column c at yaw index j, lateral index i.
  [[nodiscard]] double value(int column, std::size_t j, std::size_t i) const {
    return data_[static_cast<std::size_t>(column)][j * lateral_.size() + i];
  }

 private:
  std::vector<double> lateral_, yaw_;
  double lat0_ = 0.0, inv_dlat_ = 1.0;
  std::array<std::vector<double>, kColumns> data_;
  void finish_grid();
};

/// How the wheelset roll is treated when tabulating delta_r.
enum class RollTreatment {
  rigid,  ///< roll solved so that both wheels touch (EN 15302 rigid wheelset)
  zero,   ///< roll held at 0, each wheel at its own deepest point (linear-theory kinematics)
};

/// Rolling-radius difference r_right - r_left [m] at each lateral shift (no yaw).
[[nodiscard]] std::vector<double> rolling_radius_difference(
    const WheelRailPair& pair, const std::vector<double>& lateral,
    RollTreatment roll = RollTreatment::rigid);

/// Equivalent conicity at amplitude `amplitude` [m] from a tabulated delta_r(y) (y increasing,
/// linear interpolation, clamped): lambda_e = 1/(2 pi a) int_0^2pi delta_r(a sin t) sin t dt.
[[nodiscard]] double equivalent_conicity(const std::vector<double>& lateral,
                                         const std::vector<double>& delta_r, double amplitude);

}  // namespace ferro::contact
