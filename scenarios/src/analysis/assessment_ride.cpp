// Ride part of the assessment: car-body floor accelerations (0.4-10 Hz running-behaviour values,
// quasi-static lateral acceleration), EN 12299 N_MV and Sperling's Wz at the standard floor
// positions (above each bogie centre and mid-body). See assessment.hpp.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "assessment_detail.hpp"
#include "ferro/scenarios/analysis/ride_comfort.hpp"
#include "ferro/scenarios/sensors.hpp"

namespace ferro::scenarios::analysis::detail {

namespace {

struct FloorPoint {
  std::string name;  // floor_front, floor_centre, floor_rear (the sensors' names)
  double dx = 0.0;   // from the car body's centre of mass, along the car [m]
};

// Floor accelerations (accelerometer readings, gravity removed) at (dx, dy) of the car body,
// from its rigid motion: the measured lateral specific force at the centre of mass plus the
// lever-arm terms of the absolute angular accelerations (the rates relative to the track frame
// plus the frame's, V (-dphi/ds, -kappa sin phi, kappa cos phi), differentiated).
struct FloorMotion {
  std::vector<double> ay_cg, z_acc, x_acc, roll_acc, pitch_acc, yaw_acc;
};

FloorMotion floor_motion(const RunSignals& run, const RunContext& c, const RunBody& car) {
  FloorMotion m;
  m.ay_cg = run.get("car_body.ay");
  m.z_acc = derivative(run.time, run.get_or_zero("car_body.z_dot"));
  auto x_rate = run.get_or_zero("car_body.x_dot");
  auto roll = run.get_or_zero("car_body.roll_dot");
  auto pitch = run.get_or_zero("car_body.pitch_dot");
  auto yaw = run.get_or_zero("car_body.yaw_dot");
  for (std::size_t i = 0; i < run.n(); ++i) {
    const auto d = design_point(c.sections, c.rail_spacing, run.position[i] + car.rest_x);
    const double v = run.speed[i];
    roll[i] -= v * d.d_cant_angle;
    pitch[i] -= v * d.curvature * std::sin(d.cant_angle);
    yaw[i] += v * d.curvature * std::cos(d.cant_angle);
    x_rate[i] += v;
  }
  m.x_acc = derivative(run.time, x_rate);
  m.roll_acc = derivative(run.time, roll);
  m.pitch_acc = derivative(run.time, pitch);
  m.yaw_acc = derivative(run.time, yaw);
  return m;
}

}  // namespace

void assess_ride(Assessment& a, const RunSignals& run, const RunContext& c,
                 const AssessmentOptions& o) {
  const RunBody* car = nullptr;
  for (const auto& b : c.bodies)
    if (b.kind == "car_body") car = &b;
  if (car == nullptr || !run.has("car_body.ay")) {
    a.notes.push_back("ride: the run has no car body (model scope bogie or wheelset): not assessed");
    return;
  }
  std::vector<const RunBody*> bogies;
  for (const auto& b : c.bodies)
    if (b.kind == "bogie_frame") bogies.push_back(&b);
  std::sort(bogies.begin(), bogies.end(),
            [](const RunBody* l, const RunBody* r) { return l->rest_x > r->rest_x; });
  // The standard floor points: above each bogie centre and mid-body.
  std::vector<FloorPoint> points;
  if (!bogies.empty()) points.push_back({"floor_front", bogies.front()->rest_x - car->rest_x});
  points.push_back({"floor_centre", 0.0});
  if (bogies.size() > 1) points.push_back({"floor_rear", bogies.back()->rest_x - car->rest_x});

  std::optional<FloorMotion> motion;  // the rigid-body fallback, computed when needed
  const double delay = c.anti_alias_delay();
  const auto band = zero_phase_bandpass(o.filter_order, o.ride_low, o.ride_high, run.sample_rate);
  const auto lp = zero_phase_lowpass(o.filter_order, o.lowpass, run.sample_rate);
  const std::string group = "ride";
  const std::string band_text = fmt::format("{:g}-{:g} Hz", o.ride_low, o.ride_high);
  const std::size_t n = run.n();
  for (const auto& p : points) {
    std::vector<double> ax, ay, az, place;
    // Vertical floor accelerations at lateral offsets: (label suffix, values).
    std::vector<std::pair<double, std::vector<double>>> vertical;
    if (run.has(p.name + ".ay")) {
      // Accelerometers of the run.
      auto lat = run.located(p.name + ".ay", delay);
      ax = run.located(p.name + ".ax", delay).value;
      az = run.located(p.name + ".az", delay).value;
      ay = std::move(lat.value);
      place = std::move(lat.position);
      vertical.push_back({0.0, az});
      for (const auto& [side, dy] : {std::pair{"_left", 1.0}, std::pair{"_right", -1.0}})
        if (run.has(p.name + side + ".az"))
          vertical.push_back({dy * kFloorSideOffset, run.located(p.name + side + ".az", delay).value});
    } else {
      if (!motion) motion = floor_motion(run, c, *car);
      a.accelerations_derived = true;
      const FloorMotion& m = *motion;
      ax = m.x_acc;
      ay.resize(n);
      for (std::size_t i = 0; i < n; ++i) ay[i] = m.ay_cg[i] + p.dx * m.yaw_acc[i];
      for (double dy : {0.0, o.floor_offset, -o.floor_offset}) {
        if (dy != 0.0 && !(o.floor_offset > 0.0)) continue;
        std::vector<double> v(n);
        for (std::size_t i = 0; i < n; ++i)
          v[i] = m.z_acc[i] + dy * m.roll_acc[i] - p.dx * m.pitch_acc[i];
        vertical.push_back({dy, std::move(v)});
      }
      az = vertical.front().second;
      place = run.position;
    }
    const auto pos = shifted(place, car->rest_x + p.dx);
    const auto ay_band = band(ay);
    add_rows(a, group, fmt::format("lateral acc. {} (0.15/99.85 %)", band_text), p.name, "m/s^2",
             pos, ay_band, Statistic::extreme, nullptr);
    add_rows(a, group, fmt::format("lateral acc. {} rms", band_text), p.name, "m/s^2", pos,
             ay_band, Statistic::rms, nullptr);
    add_rows(a, group, "lateral acc. qst (50 %, 20 Hz)", p.name, "m/s^2", pos, lp(ay),
             Statistic::median_abs, nullptr, true);
    a.signals.push_back({"car body lateral acc.", p.name, "m/s^2",
                         fmt::format("floor lateral acceleration, {}", band_text), pos, ay_band,
                         std::numeric_limits<double>::quiet_NaN()});
    for (const auto& [dy, values] : vertical) {
      const std::string item = dy == 0.0 ? p.name : fmt::format("{}, y {:+g} m", p.name, dy);
      const auto az_band = band(values);
      add_rows(a, group, fmt::format("vertical acc. {} (0.15/99.85 %)", band_text), item,
               "m/s^2", pos, az_band, Statistic::extreme, nullptr);
      add_rows(a, group, fmt::format("vertical acc. {} rms", band_text), item, "m/s^2", pos,
               az_band, Statistic::rms, nullptr);
      a.signals.push_back({"car body vertical acc.", item, "m/s^2",
                           fmt::format("floor vertical acceleration, {}", band_text), pos,
                           az_band, std::numeric_limits<double>::quiet_NaN()});
    }
    // Comfort over the whole run.
    const ComfortIndex ci = comfort_index(ax, ay, az, run.sample_rate);
    add_run_row(a, group, fmt::format("N_MV ({}{})", comfort_class(ci.n_mv),
                                      ci.short_record
                                          ? fmt::format(", {} blocks of 5 s", ci.block_rms_x.size())
                                          : ""),
                p.name, "-", ci.n_mv);
    add_run_row(a, group, "Sperling Wz lateral", p.name, "-",
                sperling_index(ay, run.sample_rate, true));
    add_run_row(a, group, "Sperling Wz vertical", p.name, "-",
                sperling_index(az, run.sample_rate, false));
  }
}

}  // namespace ferro::scenarios::analysis::detail
