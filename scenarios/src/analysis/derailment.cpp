// Derailment assessment (see the header for references and known deviations).
#include "ferro/scenarios/analysis/derailment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ferro/scenarios/h5_output.hpp"
#include "ferro/scenarios/run.hpp"

namespace ferro::scenarios::analysis {

double nadal_limit(double flange_angle, double mu) {
  if (!(flange_angle > 0.0 && flange_angle < M_PI / 2))
    throw std::invalid_argument(fmt::format("flange angle must be in (0, 90) deg, got {} deg",
                                            flange_angle * 180.0 / M_PI));
  if (!(mu >= 0.0)) throw std::invalid_argument(fmt::format("mu must be >= 0, got {}", mu));
  const double t = std::tan(flange_angle);
  return (t - mu) / (1.0 + mu * t);
}

double prudhomme_limit(double axle_load) { return 0.85 * (10.0e3 + axle_load / 3.0); }

namespace {

// Integral of the piecewise-linear interpolant of (s, f) from s.front() to x, for all x at once
// is not needed: we integrate over [lo, hi] by walking the intervals that overlap it.
double window_integral(const std::vector<double>& s, const std::vector<double>& f, double lo,
                       double hi, std::size_t& first) {
  while (first + 1 < s.size() && s[first + 1] <= lo) ++first;
  double sum = 0.0;
  for (std::size_t i = first; i + 1 < s.size() && s[i] < hi; ++i) {
    const double a = s[i], b = s[i + 1];
    if (b <= a) continue;  // vehicle at rest: no length
    const double x0 = std::max(a, lo), x1 = std::min(b, hi);
    if (x1 <= x0) continue;
    const double slope = (f[i + 1] - f[i]) / (b - a);
    const double f0 = f[i] + slope * (x0 - a), f1 = f[i] + slope * (x1 - a);
    sum += 0.5 * (f0 + f1) * (x1 - x0);
  }
  return sum;
}

}  // namespace

SlidingMean sliding_mean(const std::vector<double>& position, const std::vector<double>& values,
                         double window, double step) {
  if (position.size() != values.size())
    throw std::invalid_argument(fmt::format("sliding mean: {} positions but {} values",
                                            position.size(), values.size()));
  if (!(window > 0.0)) throw std::invalid_argument("sliding mean: window must be > 0 m");
  if (!(step > 0.0)) throw std::invalid_argument("sliding mean: step must be > 0 m");
  for (std::size_t i = 1; i < position.size(); ++i) {
    if (position[i] < position[i - 1])
      throw std::invalid_argument(
          fmt::format("sliding mean: position decreases at sample {} ({} m after {} m)", i,
                      position[i], position[i - 1]));
  }
  if (position.size() < 2 || position.back() - position.front() < window)
    throw std::invalid_argument(fmt::format(
        "sliding mean: the run covers {} m of track, less than the {} m window",
        position.empty() ? 0.0 : position.back() - position.front(), window));
  SlidingMean out;
  const double first_centre = position.front() + 0.5 * window;
  const double last_centre = position.back() - 0.5 * window;
  // Work bounded up front: one mean per step along the track.
  const double points = (last_centre - first_centre) / step + 1.0;
  if (!(points <= kMaxSlidingMeanPoints)) {
    throw std::invalid_argument(fmt::format(
        "sliding mean: a step of {} m over the {:.6g} m the run covers makes {:.3g} means; at "
        "most {:.0e} (--step of at least {:.3g} m)",
        step, position.back() - position.front(), points, kMaxSlidingMeanPoints,
        (last_centre - first_centre) / (kMaxSlidingMeanPoints - 1.0)));
  }
  // Tolerance on the last centre: a run ending exactly on a step keeps that point.
  const double slack = 1e-9 * std::max(1.0, std::abs(last_centre));
  std::size_t first = 0;
  for (long k = 0;; ++k) {
    const double c = first_centre + static_cast<double>(k) * step;
    if (c > last_centre + slack) break;
    out.position.push_back(c);
    out.mean.push_back(window_integral(position, values, c - 0.5 * window, c + 0.5 * window,
                                       first) /
                       window);
  }
  return out;
}

namespace {

std::pair<double, double> peak_abs(const SlidingMean& m) {
  double best = 0.0, where = m.position.empty() ? 0.0 : m.position.front();
  for (std::size_t i = 0; i < m.mean.size(); ++i) {
    if (std::abs(m.mean[i]) > best) {
      best = std::abs(m.mean[i]);
      where = m.position[i];
    }
  }
  return {best, where};
}

}  // namespace

DerailmentReport assess_derailment(const std::vector<double>& position,
                                   const std::vector<WheelSeries>& wheels,
                                   const DerailmentOptions& options) {
  if (wheels.empty() || wheels.size() % 2 != 0)
    throw std::invalid_argument("derailment: wheels must come in (left, right) pairs");
  DerailmentReport report;
  report.mu = options.mu;
  for (const auto& w : wheels) {
    if (w.lateral.size() != position.size() || w.vertical.size() != position.size() ||
        w.contact_angle.size() != position.size())
      throw std::invalid_argument(fmt::format("derailment: {}: series lengths differ from the "
                                              "position's {}",
                                              w.name, position.size()));
    WheelAssessment a;
    a.name = w.name;
    a.q0 = options.wheel_load_static > 0.0 ? options.wheel_load_static : w.vertical.front();
    if (!(a.q0 > 0.0))
      throw std::invalid_argument(
          fmt::format("derailment: {}: static wheel load Q0 = {} N must be > 0", w.name, a.q0));
    std::vector<double> ratio(position.size());
    for (std::size_t i = 0; i < position.size(); ++i) {
      // An unloaded wheel (Q <= 0) has lifted: Y/Q is unbounded there; count it at the limit
      // of a tiny load so that the peak shows it.
      const double q = std::max(w.vertical[i], 1e-6 * a.q0);
      ratio[i] = std::abs(w.lateral[i]) / q;
      a.max_y_over_q_raw = std::max(a.max_y_over_q_raw, ratio[i]);
      const double unloading = (a.q0 - w.vertical[i]) / a.q0;
      if (unloading > a.max_unloading) {
        a.max_unloading = unloading;
        a.max_unloading_position = position[i];
      }
    }
    a.y_over_q_mean = sliding_mean(position, ratio, options.window, options.step);
    std::tie(a.max_y_over_q, a.max_y_over_q_position) = peak_abs(a.y_over_q_mean);
    if (options.flange_angle > 0.0) {
      a.flange_angle = options.flange_angle;
    } else {
      for (double g : w.contact_angle) a.flange_angle = std::max(a.flange_angle, std::abs(g));
    }
    // Nadal applies to a wheel in flange contact: with tan(angle) <= mu the contact cannot
    // climb (the limit would be <= 0), so no limit is set for it.
    a.nadal = a.flange_angle > 0.0 && std::tan(a.flange_angle) > options.mu
                  ? nadal_limit(a.flange_angle, options.mu)
                  : NAN;
    a.pass_nadal = std::isnan(a.nadal) || a.max_y_over_q <= a.nadal;
    a.pass_unloading = a.max_unloading <= options.unloading_limit;
    report.pass = report.pass && a.pass_nadal && a.pass_unloading;
    report.wheels.push_back(std::move(a));
  }
  for (std::size_t k = 0; k + 1 < wheels.size(); k += 2) {
    AxleAssessment ax;
    const auto& l = wheels[k];
    const auto& r = wheels[k + 1];
    ax.name = l.name.substr(0, l.name.rfind('.'));
    ax.axle_load = report.wheels[k].q0 + report.wheels[k + 1].q0;
    ax.limit = prudhomme_limit(ax.axle_load);
    std::vector<double> sum(position.size());
    for (std::size_t i = 0; i < position.size(); ++i) sum[i] = l.lateral[i] + r.lateral[i];
    ax.sum_y_mean = sliding_mean(position, sum, options.window, options.step);
    std::tie(ax.max_sum_y, ax.max_sum_y_position) = peak_abs(ax.sum_y_mean);
    ax.pass = ax.max_sum_y <= ax.limit;
    report.pass = report.pass && ax.pass;
    report.axles.push_back(std::move(ax));
  }
  return report;
}

DerailmentReport assess_derailment_file(const std::string& h5_path,
                                        const DerailmentOptions& options) {
  const H5File file = H5File::open_read(h5_path);
  const auto need = [&](const std::string& signal) {
    const std::string ds = "/signals/" + signal;
    if (!file.exists(ds))
      throw std::invalid_argument(
          fmt::format("{}: no signal '{}' (the derailment assessment needs position and "
                      "wheelset_<i>.<left|right>.Y, .Q, .contact_angle)",
                      h5_path, signal));
    return file.read_vector(ds);
  };
  const auto position = need("position");
  std::vector<WheelSeries> wheels;
  for (int i = 1; file.exists(fmt::format("/signals/wheelset_{}.left.Y", i)); ++i) {
    for (const char* side : {"left", "right"}) {
      const std::string base = fmt::format("wheelset_{}.{}", i, side);
      wheels.push_back(
          {base, need(base + ".Y"), need(base + ".Q"), need(base + ".contact_angle")});
    }
  }
  if (wheels.empty()) need("wheelset_1.left.Y");  // throws the named error
  return assess_derailment(position, wheels, options);
}

void write_derailment_report(const DerailmentReport& report, const std::string& source,
                             const std::string& path) {
  H5File file = H5File::create(path);
  file.set_attribute("/", "program", std::string("ferrodyn"));
  file.set_attribute("/", "created_utc", utc_timestamp());
  file.set_attribute("/", "kind", std::string("derailment_assessment"));
  file.set_attribute("/", "source", source);
  file.set_attribute("/", "mu", report.mu);
  file.set_attribute("/", "pass", std::string(report.pass ? "yes" : "no"));
  for (const auto& w : report.wheels) {
    const std::string g = "/derailment/" + w.name;
    file.write_vector(g + "/position", w.y_over_q_mean.position, "m", "sliding-window centres");
    file.write_vector(g + "/y_over_q_mean", w.y_over_q_mean.mean, "-",
                      "2 m sliding mean of |Y|/Q");
    file.set_attribute(g, "nadal_limit", w.nadal);
    file.set_attribute(g, "flange_angle", w.flange_angle);
    file.set_attribute(g, "max_y_over_q", w.max_y_over_q);
    file.set_attribute(g, "max_y_over_q_position", w.max_y_over_q_position);
    file.set_attribute(g, "max_y_over_q_raw", w.max_y_over_q_raw);
    file.set_attribute(g, "q0", w.q0);
    file.set_attribute(g, "max_unloading", w.max_unloading);
    file.set_attribute(g, "max_unloading_position", w.max_unloading_position);
  }
  for (const auto& a : report.axles) {
    const std::string g = "/derailment/" + a.name;
    file.write_vector(g + "/sum_y_position", a.sum_y_mean.position, "m", "sliding-window centres");
    file.write_vector(g + "/sum_y_mean", a.sum_y_mean.mean, "N", "2 m sliding mean of Y_l + Y_r");
    file.set_attribute(g, "prudhomme_limit", a.limit);
    file.set_attribute(g, "axle_load", a.axle_load);
    file.set_attribute(g, "max_sum_y", a.max_sum_y);
    file.set_attribute(g, "max_sum_y_position", a.max_sum_y_position);
  }
  file.set_attribute("/", "status", std::string("completed"));
}

}  // namespace ferro::scenarios::analysis
