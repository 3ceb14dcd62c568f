// One-point contact table imported from CSV (data/cooperrider_wagon/ layout): strict columns
// through the one CSV reader (located errors), natural cubic spline per column, frame conversion,
// normal-law state.
//
// References: see ImportedContactTable in imported_contact_table.hpp.
// Known deviations: see ImportedContactTable in imported_contact_table.hpp.

#include "ferro/contact/geometry/imported_contact_table.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "ferro/io/csv.hpp"
#include "ferro/numerics/interpolation.hpp"

namespace ferro::contact {
namespace {

constexpr std::array<const char*, ImportedContactTable::kColumns> kHeader{
    "lateral_displacement_m",
    "normal_force_N",
    "contact_angle_rad",
    "semi_axis_a_longitudinal_m",
    "semi_axis_b_lateral_m",
    "wheel_contact_lateral_position_m",
    "rolling_radius_m",
    "kalker_c11",
    "kalker_c22",
    "kalker_c23",
    "rail_contact_vertical_position_m",
    "penetration_m",
    "rail_contact_lateral_position_m"};

enum Column {
  kLat = 0,
  kNormalForce,
  kAngle,
  kSemiA,
  kSemiB,
  kLever,
  kRadius,
  kC11,
  kC22,
  kC23,
  kRailZ,
  kPenetration,
  kRailY
};

}  // namespace

struct ImportedContactTable::Data {
  std::vector<double> lateral;
  std::array<std::vector<double>, kColumns> values;
  std::array<numerics::NaturalCubicSpline, kColumns> splines;
};

ImportedContactTable::ImportedContactTable(const std::string& csv_path) : path_(csv_path) {
  io::CsvReader csv = io::CsvReader::open(csv_path, io::CsvFormat::csv(), "contact table");
  auto data = std::make_shared<Data>();
  auto fail = [&](const std::string& what) { throw std::invalid_argument(csv.located(what)); };
  // Header: exactly the expected names, in order.
  const std::vector<std::string>& head = csv.header();
  if (head.size() != kColumns) {
    fail(fmt::format("header has {} columns, expected {}: {}", head.size(), kColumns,
                     fmt::join(kHeader, ",")));
  }
  for (int c = 0; c < kColumns; ++c) {
    if (head[static_cast<std::size_t>(c)] != kHeader[static_cast<std::size_t>(c)]) {
      fail(fmt::format("column {}: header '{}', expected '{}'", c + 1,
                       head[static_cast<std::size_t>(c)], kHeader[static_cast<std::size_t>(c)]));
    }
  }
  std::vector<std::string> cells;
  while (csv.next(cells)) {
    for (int c = 0; c < kColumns; ++c) {
      const double v = csv.number(cells, static_cast<std::size_t>(c));
      if (c == kLat) {
        if (!data->lateral.empty() && !(v > data->lateral.back())) {
          fail(fmt::format("column 1 ({}): {} does not increase (previous {})", kHeader[0], v,
                           data->lateral.back()));
        }
        data->lateral.push_back(v);
      }
      data->values[static_cast<std::size_t>(c)].push_back(v);
    }
    const auto& v = data->values;
    const auto at = [&](int c) { return v[static_cast<std::size_t>(c)].back(); };
    if (!(at(kNormalForce) > 0.0) || !(at(kPenetration) > 0.0) || !(at(kSemiA) > 0.0) ||
        !(at(kSemiB) > 0.0) || !(at(kRadius) > 0.0) || !(at(kLever) > 0.0)) {
      fail(fmt::format("columns {} must be > 0",
                       "normal_force_N, penetration_m, semi_axis_a_longitudinal_m, "
                       "semi_axis_b_lateral_m, rolling_radius_m, wheel_contact_lateral_position_m"));
    }
  }
  if (data->lateral.size() < 4) {
    throw std::invalid_argument(
        fmt::format("{}: {} data rows, need at least 4", csv_path, data->lateral.size()));
  }
  if (!(data->lateral.front() < 0.0 && data->lateral.back() > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "{}: lateral_displacement_m must span y = 0 (got [{}, {}])", csv_path,
        data->lateral.front(), data->lateral.back()));
  }
  for (int c = 1; c < kColumns; ++c) {
    data->splines[static_cast<std::size_t>(c)] =
        numerics::NaturalCubicSpline(data->lateral, data->values[static_cast<std::size_t>(c)]);
  }
  // The source tool's limit: the magnitude of the first value, applied to |y|, both wheels.
  limit_ = std::min(-data->lateral.front(), data->lateral.back());
  data_ = std::move(data);
}

const std::vector<double>& ImportedContactTable::lateral() const { return data_->lateral; }

const std::vector<double>& ImportedContactTable::column_values(int column) const {
  if (column < 0 || column >= kColumns) {
    throw std::invalid_argument(fmt::format("ImportedContactTable: column {} outside [0, {})",
                                            column, kColumns));
  }
  return data_->values[static_cast<std::size_t>(column)];
}

double ImportedContactTable::column(int column, double y_file) const {
  if (column < 1 || column >= kColumns) {
    throw std::invalid_argument(
        fmt::format("ImportedContactTable: column {} outside [1, {})", column, kColumns));
  }
  const numerics::NaturalCubicSpline& s = data_->splines[static_cast<std::size_t>(column)];
  double f, df, ddf;
  s.eval(s.segment(y_file), y_file, f, df, ddf);
  return f;
}

WheelRailContact ImportedContactTable::wheel_point(const WheelsetPose& pose, Side side) const {
  if (!(std::abs(pose.lateral) <= limit_)) {
    throw std::out_of_range(fmt::format(
        "{}: wheelset lateral shift {} m outside the table's |y| <= {} m (the source tool stops "
        "the run as a derailment there)",
        path_, pose.lateral, limit_));
  }
  // File frame: y left, z up; the left wheel reads +y_file, the right wheel -y_file.
  const double y_file = -pose.lateral;
  const double y = side == Side::left ? y_file : -y_file;
  const std::size_t seg = data_->splines[kNormalForce].segment(y);
  auto col = [&](int c) {
    double f, df, ddf;
    data_->splines[static_cast<std::size_t>(c)].eval(seg, y, f, df, ddf);
    return f;
  };
  const double n0 = col(kNormalForce), delta = col(kAngle), a0 = col(kSemiA), b0 = col(kSemiB);
  const double lever = col(kLever), radius = col(kRadius), q0 = col(kPenetration);
  const double phi = pose.roll, z = -pose.vertical;
  const double sp = std::sin(phi), cp = std::cos(phi), tp = sp / cp;
  double dq = 0.0, angle = 0.0;
  if (side == Side::left) {
    const double e = (radius - lever * tp) * sp + lever / cp - lever - radius * phi;
    angle = delta + phi;
    dq = -e * std::sin(angle) - (z + lever * phi) * std::cos(angle);
  } else {
    const double e = (radius + lever * tp) * sp - lever / cp + lever - radius * phi;
    angle = delta - phi;
    dq = e * std::sin(angle) - (z - lever * phi) * std::cos(angle);
  }
  WheelRailContact c;
  c.side = side;
  c.x = 0.0;
  c.y = pose.lateral + (side == Side::left ? -lever : lever);
  c.z = -col(kRailZ);
  c.contact_angle = angle;
  c.rolling_radius = radius;
  c.penetration = q0 + dq;
  c.ref_normal_force = n0;
  c.ref_penetration = q0;
  c.ref_semi_axis_a = a0;
  c.ref_semi_axis_b = b0;
  c.c11 = col(kC11);
  c.c22 = col(kC22);
  c.c23 = col(kC23);
  return c;
}

void ImportedContactTable::contacts(const WheelsetPose& pose, std::vector<WheelRailContact>& out,
                                    ContactScratch& /*scratch*/) const {
  out.clear();
  for (const Side side : {Side::left, Side::right}) {
    const WheelRailContact c = wheel_point(pose, side);
    if (c.penetration > 0.0) out.push_back(c);
  }
}

}  // namespace ferro::contact
