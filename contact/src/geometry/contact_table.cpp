// Contact tables (rigid wheelset over lateral shift and yaw), HDF5 I/O, run-time interpolation,
// equivalent conicity.
//
// References: EN 15302 (delta_r of the rigid wheelset, equivalent conicity); Gelb & Vander Velde
// (1968) (describing function); Wickens (2003) (roll coefficient sigma, roll = sigma y / e).
// Known deviations: see contact_table.hpp.

#include "ferro/contact/geometry/contact_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ferro/io/hdf5.hpp"
#include "ferro/numerics/interpolation.hpp"

namespace ferro::contact {
namespace {

enum Col {
  kDeltaR,
  kRoll,
  kVertical,
  kRollCoef,
  kRadiusL,
  kRadiusR,
  kAngleL,
  kAngleR,
  kAL,
  kAR,
  kBL,
  kBR,
  kWheelYL,
  kWheelYR,
  kRailYL,
  kRailYR,
  kLatL,
  kLatR,
  kLongL,
  kLongR,
  kNumPoints
};

}  // namespace

const std::array<const char*, ContactTable::kColumns>& ContactTable::column_names() {
  static const std::array<const char*, kColumns> names{"delta_r",
                                                       "roll",
                                                       "vertical",
                                                       "roll_coefficient",
                                                       "rolling_radius_left",
                                                       "rolling_radius_right",
                                                       "contact_angle_left",
                                                       "contact_angle_right",
                                                       "curvature_a_left",
                                                       "curvature_a_right",
                                                       "curvature_b_left",
                                                       "curvature_b_right",
                                                       "wheel_y_left",
                                                       "wheel_y_right",
                                                       "rail_y_left",
                                                       "rail_y_right",
                                                       "lateral_left",
                                                       "lateral_right",
                                                       "longitudinal_left",
                                                       "longitudinal_right",
                                                       "points_in_contact"};
  return names;
}

void ContactTableParams::validate() const {
  if (!(lateral_max > lateral_min) || !(lateral_step > 0.0) ||
      (lateral_max - lateral_min) / lateral_step > 1e5) {
    throw std::invalid_argument(fmt::format(
        "ContactTableParams.lateral_min/max/step: need max > min and 0 < step with at most 1e5 "
        "points, got {} {} {}",
        lateral_min, lateral_max, lateral_step));
  }
  if (yaw.empty() || !std::is_sorted(yaw.begin(), yaw.end()) ||
      std::adjacent_find(yaw.begin(), yaw.end()) != yaw.end()) {
    throw std::invalid_argument("ContactTableParams.yaw: need at least one, strictly increasing");
  }
}

void ContactTable::finish_grid() {
  lat0_ = lateral_.front();
  inv_dlat_ = lateral_.size() > 1 ? 1.0 / (lateral_[1] - lateral_[0]) : 1.0;
}

ContactTable ContactTable::build(const WheelRailPair& pair, const ContactTableParams& params) {
  params.validate();
  ContactTable t;
  const auto n = static_cast<std::size_t>(std::llround((params.lateral_max - params.lateral_min) /
                                                       params.lateral_step)) +
                 1;
  for (std::size_t i = 0; i < n; ++i) {
    t.lateral_.push_back(params.lateral_min + params.lateral_step * static_cast<double>(i));
  }
  t.yaw_ = params.yaw;
  for (auto& col : t.data_) col.assign(n * t.yaw_.size(), 0.0);
  for (std::size_t j = 0; j < t.yaw_.size(); ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const RigidContact rc = solve_rigid_contact(pair, t.lateral_[i], t.yaw_[j]);
      const std::size_t k = j * n + i;
      const ContactPoint& l = rc.main[0];
      const ContactPoint& r = rc.main[1];
      t.data_[kDeltaR][k] = r.rolling_radius - l.rolling_radius;
      t.data_[kRoll][k] = rc.pose.roll;
      t.data_[kVertical][k] = rc.pose.vertical;
      t.data_[kRadiusL][k] = l.rolling_radius;
      t.data_[kRadiusR][k] = r.rolling_radius;
      t.data_[kAngleL][k] = l.contact_angle;
      t.data_[kAngleR][k] = r.contact_angle;
      t.data_[kAL][k] = l.curvature_a;
      t.data_[kAR][k] = r.curvature_a;
      t.data_[kBL][k] = l.curvature_b;
      t.data_[kBR][k] = r.curvature_b;
      t.data_[kWheelYL][k] = l.wheel_y;
      t.data_[kWheelYR][k] = r.wheel_y;
      t.data_[kRailYL][k] = l.rail_y;
      t.data_[kRailYR][k] = r.rail_y;
      t.data_[kLatL][k] = l.y;
      t.data_[kLatR][k] = r.y;
      t.data_[kLongL][k] = l.x;
      t.data_[kLongR][k] = r.x;
      t.data_[kNumPoints][k] = static_cast<double>(rc.points.size());
    }
    // Roll coefficient sigma = e d(roll)/dy, e = half the distance between the contact points.
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t a = i > 0 ? i - 1 : i, b = i + 1 < n ? i + 1 : i;
      const std::size_t k = j * n + i;
      const double e = 0.5 * (t.data_[kLatR][k] - t.data_[kLatL][k]);
      t.data_[kRollCoef][k] = e * (t.data_[kRoll][j * n + b] - t.data_[kRoll][j * n + a]) /
                              (t.lateral_[b] - t.lateral_[a]);
    }
  }
  t.finish_grid();
  return t;
}

ContactTableEntry ContactTable::lookup(double lateral, double yaw) const {
  const std::size_t n = lateral_.size();
  double u = (lateral - lat0_) * inv_dlat_;
  u = std::clamp(u, 0.0, static_cast<double>(n - 1) - 1e-12);
  const auto i = static_cast<std::size_t>(u);
  const double t = u - static_cast<double>(i);
  std::size_t j = 0;
  double w = 0.0;
  if (yaw_.size() > 1) {
    const numerics::AxisCell cell = numerics::locate(yaw_, yaw);
    j = cell.index;
    w = cell.t;
  }
  const std::size_t k00 = j * n + i;
  const std::size_t k10 = yaw_.size() > 1 ? k00 + n : k00;
  double v[kColumns];
  for (int c = 0; c < kColumns; ++c) {
    const std::vector<double>& d = data_[static_cast<std::size_t>(c)];
    v[c] = numerics::lerp(numerics::lerp(d[k00], d[k00 + 1], t),
                          numerics::lerp(d[k10], d[k10 + 1], t), w);
  }
  ContactTableEntry e;
  e.delta_r = v[kDeltaR];
  e.roll = v[kRoll];
  e.vertical = v[kVertical];
  e.roll_coefficient = v[kRollCoef];
  e.rolling_radius = {v[kRadiusL], v[kRadiusR]};
  e.contact_angle = {v[kAngleL], v[kAngleR]};
  e.curvature_a = {v[kAL], v[kAR]};
  e.curvature_b = {v[kBL], v[kBR]};
  e.wheel_y = {v[kWheelYL], v[kWheelYR]};
  e.rail_y = {v[kRailYL], v[kRailYR]};
  e.lateral = {v[kLatL], v[kLatR]};
  e.longitudinal = {v[kLongL], v[kLongR]};
  return e;
}

double ContactTable::delta_r(double lateral, double yaw) const {
  if (yaw_.size() > 1) return lookup(lateral, yaw).delta_r;
  const std::size_t n = lateral_.size();
  double u = std::clamp((lateral - lat0_) * inv_dlat_, 0.0, static_cast<double>(n - 1) - 1e-12);
  const auto i = static_cast<std::size_t>(u);
  const double t = u - static_cast<double>(i);
  const std::vector<double>& d = data_[kDeltaR];
  return numerics::lerp(d[i], d[i + 1], t);
}

void ContactTable::save_hdf5(const std::string& path) const {
  io::H5File file = io::H5File::create(path);
  const auto write = [&](const std::string& name, const std::vector<double>& v,
                         const io::Dims& dims, const char* units) {
    file.write_array(name, v, dims);
    file.set_attribute(name, "units", units);
  };
  write("/lateral", lateral_, {lateral_.size()}, "m");
  write("/yaw", yaw_, {yaw_.size()}, "rad");
  static const std::array<const char*, kColumns> units{
      "m",   "rad", "m", "1", "m", "m", "rad", "rad", "1/m", "1/m", "1/m",
      "1/m", "m",   "m", "m", "m", "m", "m",   "m",   "m",   "1"};
  for (int c = 0; c < kColumns; ++c) {
    const std::string name = std::string("/") + column_names()[static_cast<std::size_t>(c)];
    write(name, data_[static_cast<std::size_t>(c)], {yaw_.size(), lateral_.size()},
          units[static_cast<std::size_t>(c)]);
  }
  file.close();
}

ContactTable ContactTable::load_hdf5(const std::string& path) {
  const io::H5File file = io::H5File::open_input(path, "contact table");
  const auto read = [&](const std::string& name, std::size_t expected) {
    if (!file.exists(name))
      throw std::invalid_argument(fmt::format("{}: dataset '{}' missing", path, name));
    std::vector<double> v = file.read_array(name);
    if (expected != 0 && v.size() != expected) {
      throw std::invalid_argument(fmt::format("{}: dataset '{}' has {} values, expected {}", path,
                                              name, v.size(), expected));
    }
    return v;
  };
  ContactTable t;
  t.lateral_ = read("/lateral", 0);
  t.yaw_ = read("/yaw", 0);
  if (t.lateral_.size() < 2 || t.yaw_.empty())
    throw std::invalid_argument(fmt::format("{}: table needs >= 2 lateral values", path));
  for (int c = 0; c < kColumns; ++c) {
    const std::string name = std::string("/") + column_names()[static_cast<std::size_t>(c)];
    t.data_[static_cast<std::size_t>(c)] = read(name, t.lateral_.size() * t.yaw_.size());
  }
  t.finish_grid();
  return t;
}

std::vector<double> rolling_radius_difference(const WheelRailPair& pair,
                                              const std::vector<double>& lateral,
                                              RollTreatment roll) {
  std::vector<double> out;
  out.reserve(lateral.size());
  for (double y : lateral) {
    if (roll == RollTreatment::zero) {
      WheelsetPose pose;
      pose.lateral = y;
      double radius[2] = {0.0, 0.0};
      for (Side side : {Side::left, Side::right}) {
        double best = 1.0;
        for (const ContactPoint& p : candidate_points(pair, pose, side)) {
          if (p.vertical_gap < best) {
            best = p.vertical_gap;
            radius[static_cast<int>(side)] = p.rolling_radius;
          }
        }
      }
      out.push_back(radius[1] - radius[0]);
      continue;
    }
    const RigidContact rc = solve_rigid_contact(pair, y, 0.0);
    out.push_back(rc.main[1].rolling_radius - rc.main[0].rolling_radius);
  }
  return out;
}

double equivalent_conicity(const std::vector<double>& lateral, const std::vector<double>& delta_r,
                           double amplitude) {
  if (!(amplitude > 0.0) || lateral.size() != delta_r.size() || lateral.size() < 2) {
    throw std::invalid_argument(
        "equivalent_conicity: need amplitude > 0 and matching lateral / delta_r of size >= 2");
  }
  // Midpoint rule over one period (spectrally accurate for a periodic smooth integrand; 4096
  // points resolve a delta_r jump to 0.1 %).
  constexpr int kN = 4096;
  double sum = 0.0;
  for (int k = 0; k < kN; ++k) {
    const double t = 2.0 * std::numbers::pi * (k + 0.5) / kN;
    sum += numerics::interpolate_linear(lateral, delta_r, amplitude * std::sin(t)) * std::sin(t);
  }
  const double integral = sum * 2.0 * std::numbers::pi / kN;
  return integral / (2.0 * std::numbers::pi * amplitude);
}

}  // namespace ferro::contact
