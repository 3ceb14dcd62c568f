#pragma once
// A one-point contact table imported from another tool (CSV) as a contact geometry source.
//
// References: see ImportedContactTable below.
// Known deviations: see ImportedContactTable below.

#include <cmath>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ferro/contact/geometry/contact_geometry_source.hpp"

namespace ferro::contact {

/// One-point contact table imported from another tool, in the CSV layout of
/// data/cooperrider_wagon/ (README.md there): one row per wheelset lateral displacement, the
/// columns lateral_displacement_m, normal_force_N, contact_angle_rad, semi_axis_a_longitudinal_m,
/// semi_axis_b_lateral_m, wheel_contact_lateral_position_m, rolling_radius_m, kalker_c11,
/// kalker_c22, kalker_c23, rail_contact_vertical_position_m, penetration_m,
/// rail_contact_lateral_position_m (the last one is read and ignored).
///
/// The file's frame is the source tool's: y LEFT, z UP, and the table describes the LEFT wheel
/// as a function of the displacement y towards it; the right wheel reads the table at -y. The
/// conversion to the contact layer's frame (y right, z down) happens here and only here:
/// y_file = -pose.lateral, z_file = -pose.vertical; roll is the same rotation in both frames
/// (+ lowers the right wheel). So the left wheel reads the table at -pose.lateral and the right
/// wheel at +pose.lateral.
///
/// Each column is a natural cubic spline in y through all rows. pose.vertical and pose.roll are
/// deviations from the table's quasi-static state at that y (the state in which each wheel
/// carries the table's N0 at approach q0), as the source tool defines them. The extra approach
/// along the normal (file frame, a, r, delta the table's lever arm, rolling radius and contact
/// angle of that wheel, phi the roll, z = -pose.vertical):
///   left:  e = (r - a tan phi) sin phi + a / cos phi - a - r phi,
///          dq = -e sin(delta + phi) - (z + a phi) cos(delta + phi);
///   right: e = (r + a tan phi) sin phi - a / cos phi + a - r phi,
///          dq = +e sin(delta - phi) - (z - a phi) cos(delta - phi).
/// The point carries penetration = q0 + dq and the reference state (N0, q0, a0, b0), so that
/// hertz_patch_from_penetration() gives N = N0 (1 + dq/q0)^1.5 and a, b scaled by (N/N0)^(1/3);
/// C11, C22, C23 are passed through. Contact angle in the track frame: delta + phi (left),
/// delta - phi (right), + towards the track centre. Point: x = 0, y = pose.lateral -+ a (left,
/// right), z = -(rail contact vertical position) (below top of rail).
///
/// References: DYTSI (D. Bigoni, DTU, 2011-2014) as restated in data/cooperrider_wagon/
/// wagon.yaml (normal law, penetration change, lookup and mirror convention); de Boor, "A
/// Practical Guide to Splines" (natural cubic spline).
/// Known deviations: the source tool drops a point whose table or dynamic force is below 1 N;
/// here every point with q0 + dq > 0 is reported (the force goes continuously to zero).
class ImportedContactTable final : public ContactGeometrySource {
 public:
  /// Reads and checks the CSV file (std::invalid_argument with file:line: column on bad input).
  explicit ImportedContactTable(const std::string& csv_path);
  [[nodiscard]] std::string_view name() const override { return "imported"; }
  /// Both wheels (left first, at most one point each). Throws std::out_of_range naming the file
  /// and the limit when |pose.lateral| exceeds lateral_limit() (the source tool stops such a run
  /// as a derailment). No allocation once `out` holds 2 entries.
  using ContactGeometrySource::contacts;
  void contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out,
                ContactScratch& scratch) const override;
  /// The point of one wheel whether or not it penetrates (penetration may be <= 0).
  [[nodiscard]] WheelRailContact wheel_point(const WheelsetPose& pose, Side side) const;
  /// |y| limit of the table: the magnitude of its first lateral value [m].
  [[nodiscard]] double lateral_limit() const { return limit_; }
  [[nodiscard]] bool in_range(const WheelsetPose& pose) const {
    return std::abs(pose.lateral) <= limit_;
  }
  /// Knots (file rows) and the spline of column `column` (1 .. 11: normal_force_N ..
  /// penetration_m, in file order) at file-frame displacement y [m].
  [[nodiscard]] const std::vector<double>& lateral() const;
  [[nodiscard]] double column(int column, double y_file) const;
  [[nodiscard]] const std::vector<double>& column_values(int column) const;
  static constexpr int kColumns = 13;

 private:
  struct Data;  // knots and one natural cubic spline per column
  std::shared_ptr<const Data> data_;
  std::string path_;
  double limit_ = 0.0;
};

}  // namespace ferro::contact
