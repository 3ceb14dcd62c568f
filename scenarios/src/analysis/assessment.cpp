// Assessment of a run: running safety, track loading, stability (see the header for references
// and known deviations). Ride: assessment_ride.cpp; output: assessment_output.cpp.
#include "ferro/scenarios/analysis/assessment.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "assessment_detail.hpp"
#include "ferro/scenarios/analysis/ride_comfort.hpp"

namespace ferro::scenarios::analysis {

double nadal_limit(double flange_angle, double mu) {
  if (!(flange_angle > 0.0 && flange_angle < M_PI / 2))
    throw std::invalid_argument(fmt::format("flange angle must be in (0, 90) deg, got {} deg",
                                            flange_angle * 180.0 / M_PI));
  if (!(mu >= 0.0)) throw std::invalid_argument(fmt::format("mu must be >= 0, got {}", mu));
  const double t = std::tan(flange_angle);
  return (t - mu) / (1.0 + mu * t);
}

double prudhomme_limit(double axle_load, double alpha) {
  return alpha * (10.0e3 + axle_load / 3.0);
}

double q_max_limit(double speed, double static_wheel_load) {
  const double kmh = speed * 3.6;
  const double cap = kmh <= 160.0   ? 200.0e3
                     : kmh <= 200.0 ? 190.0e3
                     : kmh <= 250.0 ? 180.0e3
                     : kmh <= 300.0 ? 170.0e3
                                    : 160.0e3;
  return std::min(90.0e3 + static_wheel_load, cap);
}

double bogie_acceleration_limit(double bogie_mass) {
  return 0.5 * (12.0 - bogie_mass / 1000.0 / 5.0);
}

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::pass:
      return "pass";
    case Verdict::fail:
      return "FAIL";
    case Verdict::info:
      return "info";
  }
  return "info";
}

namespace detail {

RunSignals::RunSignals(const std::string& p) : path(p), file_(io::H5File::open_read(p)) {
  const auto need = [&](const std::string& ds) {
    if (!file_.exists(ds))
      throw std::invalid_argument(
          fmt::format("{}: no '{}': not the output of `ferrodyn run` for a vehicle scene", path, ds));
    return file_.read_vector(ds);
  };
  time = need("/time");
  position = need("/signals/position");
  speed = need("/signals/speed");
  if (time.size() < 8)
    throw std::invalid_argument(fmt::format("{}: {} samples; the assessment needs at least 8",
                                            path, time.size()));
  const double dt = time[1] - time[0];
  if (!(dt > 0.0)) throw std::invalid_argument(fmt::format("{}: time does not increase", path));
  std::size_t n = time.size();
  for (std::size_t i = 1; i < n; ++i) {
    const double d = time[i] - time[i - 1];
    if (std::abs(d - dt) <= 1e-6 * dt) continue;
    if (i == n - 1 && d < dt) {  // the run's end time off the output grid
      n -= 1;
      break;
    }
    throw std::invalid_argument(fmt::format(
        "{}: output times are not evenly spaced ({} s after {} s at sample {}); the filters "
        "need a uniform grid",
        path, d, dt, i));
  }
  time.resize(n);
  position.resize(n);
  speed.resize(n);
  sample_rate = 1.0 / dt;
}

bool RunSignals::has(const std::string& name) const { return file_.exists("/signals/" + name); }

std::vector<double> RunSignals::get(const std::string& name) const {
  if (!has(name))
    throw std::invalid_argument(fmt::format("{}: no signal '{}'", path, name));
  auto v = file_.read_vector("/signals/" + name);
  v.resize(n());
  return v;
}

std::vector<double> RunSignals::get_or_zero(const std::string& name) const {
  return has(name) ? get(name) : std::vector<double>(n(), 0.0);
}

std::vector<double> RunSignals::position_before(double delay) const {
  std::vector<double> out(n());
  for (std::size_t i = 0; i < n(); ++i) {
    const double t = time[i] - delay;
    if (t <= time.front()) {
      out[i] = position.front() + speed.front() * (t - time.front());
      continue;
    }
    const auto it = std::upper_bound(time.begin(), time.end(), t);
    const auto k = static_cast<std::size_t>(it - time.begin());
    const double u = (t - time[k - 1]) / (time[k] - time[k - 1]);
    out[i] = position[k - 1] + u * (position[k] - position[k - 1]);
  }
  return out;
}

RunSignals::Located RunSignals::located(const std::string& name, double delay) const {
  if (has(name + "_filtered")) return {get(name + "_filtered"), position_before(delay), true};
  return {get(name), position, false};
}

std::vector<double> ZeroPhase::operator()(const std::vector<double>& x) const {
  return filtfilt(digital, x, padding);
}

ZeroPhase zero_phase_lowpass(int order, double fc, double sample_rate) {
  const auto analog = analysis::zero_phase_lowpass(order, fc);
  return {bilinear(analog, sample_rate), edge_padding(analog, sample_rate)};
}

ZeroPhase zero_phase_bandpass(int order, double f_low, double f_high, double sample_rate) {
  const auto analog = analysis::zero_phase_bandpass(order, f_low, f_high);
  return {bilinear(analog, sample_rate), edge_padding(analog, sample_rate)};
}

std::vector<double> derivative(const std::vector<double>& t, const std::vector<double>& x) {
  const std::size_t n = x.size();
  std::vector<double> d(n, 0.0);
  if (n < 2) return d;
  d[0] = (x[1] - x[0]) / (t[1] - t[0]);
  d[n - 1] = (x[n - 1] - x[n - 2]) / (t[n - 1] - t[n - 2]);
  for (std::size_t i = 1; i + 1 < n; ++i) d[i] = (x[i + 1] - x[i - 1]) / (t[i + 1] - t[i - 1]);
  return d;
}

std::vector<double> shifted(const std::vector<double>& position, double offset) {
  std::vector<double> s(position);
  for (double& v : s) v += offset;
  return s;
}

void add_rows(Assessment& a, const std::string& group, const std::string& quantity,
              const std::string& item, const std::string& unit,
              const std::vector<double>& position, const std::vector<double>& value,
              Statistic statistic, const std::function<double(const TrackSection&)>& limit,
              bool only_curves, bool judged) {
  for (const auto& sec : a.sections) {
    if (only_curves && sec.kind != "curve") continue;
    AssessmentRow r;
    r.stats = section_statistics(position, value, sec);
    if (r.stats.samples == 0) continue;
    r.group = group;
    r.quantity = quantity;
    r.item = item;
    r.section = sec.name;
    r.unit = unit;
    switch (statistic) {
      case Statistic::extreme:
        r.value = r.stats.extreme();
        break;
      case Statistic::high:
        r.value = r.stats.p_high;
        break;
      case Statistic::median_abs:
        r.value = std::abs(r.stats.p_median);
        break;
      case Statistic::max_abs:
        r.value = r.stats.max_abs;
        break;
      case Statistic::rms:
        r.value = r.stats.rms;
        break;
    }
    // Where the statistic's extreme is: the largest value for a one-sided statistic, the
    // largest magnitude otherwise.
    r.max_abs = statistic == Statistic::high ? r.stats.max : r.stats.max_abs;
    r.position = statistic == Statistic::high ? r.stats.max_position : r.stats.max_abs_position;
    r.limit = limit ? limit(sec) : std::numeric_limits<double>::quiet_NaN();
    r.verdict = std::isnan(r.limit) || !judged ? Verdict::info
                : r.value <= r.limit ? Verdict::pass
                                     : Verdict::fail;
    if (r.verdict == Verdict::fail) a.pass = false;
    a.rows.push_back(std::move(r));
  }
}

void add_run_row(Assessment& a, const std::string& group, const std::string& quantity,
                 const std::string& item, const std::string& unit, double value) {
  AssessmentRow r;
  r.group = group;
  r.quantity = quantity;
  r.item = item;
  r.section = "run";
  r.unit = unit;
  r.value = value;
  r.max_abs = std::abs(value);
  r.position = std::numeric_limits<double>::quiet_NaN();
  r.stats.p_low = r.stats.p_median = r.stats.p_high = r.stats.max_abs_position = r.position;
  r.stats.max_abs = r.stats.rms = std::abs(value);
  r.verdict = Verdict::info;
  a.rows.push_back(std::move(r));
}

DesignPoint design_point(const std::vector<TrackSection>& sections, double rail_spacing,
                         double s) {
  const auto kappa = [](const TrackSection& t) {
    return t.kind == "curve" && t.radius != 0.0 ? 1.0 / t.radius : 0.0;
  };
  const auto cant = [](const TrackSection& t) { return t.kind == "curve" ? t.cant : 0.0; };
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const auto& t = sections[i];
    if (s < t.start || s >= t.end) continue;
    double k = kappa(t), c = cant(t), dc = 0.0;
    if (t.kind == "transition") {
      const double len = t.end - t.start, u = (s - t.start) / len;
      const double k0 = i > 0 ? kappa(sections[i - 1]) : 0.0;
      const double k1 = i + 1 < sections.size() ? kappa(sections[i + 1]) : 0.0;
      const double c0 = i > 0 ? cant(sections[i - 1]) : 0.0;
      const double c1 = i + 1 < sections.size() ? cant(sections[i + 1]) : 0.0;
      k = k0 + u * (k1 - k0);
      c = c0 + u * (c1 - c0);
      dc = (c1 - c0) / len;
    }
    const double phi = std::asin(std::clamp(c / rail_spacing, -1.0, 1.0));
    return {k, phi, dc / (rail_spacing * std::cos(phi))};
  }
  return {};
}

}  // namespace detail

namespace {

using detail::Statistic;

// Sections the statistics are taken over: the scene's, or windows of a given length over the
// stretch the vehicle's bodies cover.
std::vector<TrackSection> make_sections(const RunContext& c, const detail::RunSignals& run,
                                        const AssessmentOptions& o) {
  double lo = run.position.front(), hi = run.position.back();
  for (const auto& b : c.bodies) {
    lo = std::min(lo, run.position.front() + b.rest_x);
    hi = std::max(hi, run.position.back() + b.rest_x);
  }
  std::vector<TrackSection> out;
  if (o.section_length > 0.0) {
    const double first = std::floor(lo / o.section_length) * o.section_length;
    int k = 0;
    for (double s = first; s < hi; s += o.section_length) {
      ++k;
      out.push_back({fmt::format("window {} [{:g}, {:g}) m", k, s, s + o.section_length),
                     "window", s, s + o.section_length, 0.0, 0.0});
    }
    return out;
  }
  if (!c.sections.empty()) {
    out = c.sections;
    // The bodies may stand beyond the designed sections at the ends (track margins).
    out.front().start = std::min(out.front().start, lo);
    out.back().end = std::max(out.back().end, hi + 1e-9);
    return out;
  }
  out.push_back({"run (straight track)", "straight", lo, hi + 1e-9, 0.0, 0.0});
  return out;
}

// Largest speed at the samples whose position lies in the section [m/s].
double section_speed(const std::vector<double>& position, const std::vector<double>& speed,
                     const TrackSection& sec) {
  double v = 0.0;
  for (std::size_t i = 0; i < position.size(); ++i)
    if (position[i] >= sec.start && position[i] < sec.end) v = std::max(v, speed[i]);
  return v;
}

struct Wheelset {
  const RunBody* body = nullptr;
  std::vector<double> position;  // at the wheelset, of its (possibly delayed) forces [m]
  std::vector<double> y_left, y_right, q_left, q_right;  // 20 Hz low-passed [N]
  std::vector<double> angle_left, angle_right;           // contact angle [rad]
  std::vector<double> sum_y;                             // -Y_L + Y_R, low-passed [N]
};

AssessedSignal signal_of(const std::string& quantity, const std::string& item,
                         const std::string& unit, const std::string& description,
                         std::vector<double> position, std::vector<double> value, double limit) {
  return {quantity, item, unit, description, std::move(position), std::move(value), limit};
}

void assess_wheels(Assessment& a, const detail::RunSignals& run, const RunContext& c,
                   const AssessmentOptions& o, std::vector<Wheelset>& wheelsets) {
  const auto lp = detail::zero_phase_lowpass(o.filter_order, o.lowpass, run.sample_rate);
  for (auto& w : wheelsets) {
    const std::string& name = w.body->name;
    const double q0 = 0.5 * w.body->static_load;
    for (const char* side : {"left", "right"}) {
      const std::string item = fmt::format("{}.{}", name, side);
      const auto y_in = run.located(item + ".Y", c.anti_alias_delay());
      const auto q_in = run.located(item + ".Q", c.anti_alias_delay());
      a.forces_filtered_in_run = y_in.filtered && q_in.filtered;
      w.position = detail::shifted(y_in.position, w.body->rest_x);
      const auto y = lp(y_in.value);
      const auto q = lp(q_in.value);
      const auto angle = run.get(item + ".contact_angle");
      // Y/Q of the filtered forces, 2 m sliding mean.
      std::vector<double> ratio(y.size());
      for (std::size_t i = 0; i < y.size(); ++i) ratio[i] = y[i] / std::max(q[i], 0.01 * q0);
      const auto ratio_2m = sliding_mean(w.position, ratio, o.window, o.step);
      const double lim = o.y_over_q_limit;
      detail::add_rows(a, "running safety", "Y/Q 2 m", item, "-", ratio_2m.position,
                       ratio_2m.mean, Statistic::extreme, [&](const TrackSection&) { return lim; });
      // Nadal's limit for the flange angle reached, as information (flange contact only).
      double flange = o.flange_angle;
      if (!(flange > 0.0))
        for (double g : angle) flange = std::max(flange, std::abs(g));
      if (flange >= o.nadal_min_angle && flange < M_PI / 2 && std::tan(flange) > a.mu) {
        const double nadal = nadal_limit(flange, a.mu);
        detail::add_rows(a, "running safety", "Y/Q 2 m against Nadal", item, "-",
                         ratio_2m.position, ratio_2m.mean, Statistic::extreme,
                         [&](const TrackSection&) { return nadal; }, false, false);
        a.notes.push_back(fmt::format("Nadal: {} reaches a contact angle of {:.1f} deg: limit "
                                      "{:.3f} at mu = {:g}",
                                      item, flange * 180.0 / M_PI, nadal, a.mu));
      }
      a.signals.push_back(signal_of("Y/Q 2 m", item, "-",
                                    "2 m sliding mean of Y/Q (20 Hz low-passed Y and Q)",
                                    ratio_2m.position, ratio_2m.mean, lim));
      // Track loading: Q max (99.85 %), quasi-static Q and Y in curves (50 %).
      detail::add_rows(a, "track loading", "Q max", item, "N", w.position, q, Statistic::high,
                       [&](const TrackSection& s) {
                         return q_max_limit(section_speed(w.position, run.speed, s), q0);
                       });
      detail::add_rows(a, "track loading", "Q qst", item, "N", w.position, q,
                       Statistic::median_abs, [](const TrackSection&) { return kQqstLimit; },
                       true);
      detail::add_rows(a, "track loading", "Y qst", item, "N", w.position, y,
                       Statistic::median_abs, [](const TrackSection&) { return kYqstLimit; },
                       true);
      a.signals.push_back(signal_of("Q", item, "N", "wheel force Q, 20 Hz low-pass", w.position, q,
                                    std::numeric_limits<double>::quiet_NaN()));
      if (a.twist_test) {
        std::vector<double> unloading(q.size());
        for (std::size_t i = 0; i < q.size(); ++i) unloading[i] = (q0 - q[i]) / q0;
        const double ul = o.unloading_limit;
        detail::add_rows(a, "twist test", "dQ/Q0", item, "-", w.position, unloading,
                         Statistic::high, [&](const TrackSection&) { return ul; });
        a.signals.push_back(signal_of("dQ/Q0", item, "-",
                                      "wheel unloading (Q0 - Q)/Q0, Q 20 Hz low-passed",
                                      w.position, unloading, ul));
      }
      if (std::string(side) == "left") {
        w.y_left = y;
        w.q_left = q;
        w.angle_left = angle;
      } else {
        w.y_right = y;
        w.q_right = q;
        w.angle_right = angle;
      }
    }
    // Track-shift force: the lateral force of the rails on the wheelset, + left:
    // each wheel's Y points towards the track centre (-y on the left wheel, +y on the right).
    w.sum_y.resize(w.y_left.size());
    for (std::size_t i = 0; i < w.sum_y.size(); ++i) w.sum_y[i] = -w.y_left[i] + w.y_right[i];
    const auto sum_2m = sliding_mean(w.position, w.sum_y, o.window, o.step);
    const double lim = prudhomme_limit(w.body->static_load, a.alpha);
    detail::add_rows(a, "running safety", "sum Y 2 m", name, "N", sum_2m.position, sum_2m.mean,
                     Statistic::extreme, [&](const TrackSection&) { return lim; });
    detail::add_rows(a, "track loading", "sum Y max", name, "N", sum_2m.position, sum_2m.mean,
                     Statistic::extreme, [&](const TrackSection&) { return lim; });
    a.signals.push_back(signal_of("sum Y 2 m", name, "N",
                                  "2 m sliding mean of -Y_left + Y_right (20 Hz low-pass), + left",
                                  sum_2m.position, sum_2m.mean, lim));
  }
}

void assess_stability(Assessment& a, const detail::RunSignals& run, const RunContext& c,
                      const AssessmentOptions& o, const std::vector<Wheelset>& wheelsets) {
  const double covered = run.position.back() - run.position.front();
  if (covered < o.stability_window) {
    a.notes.push_back(fmt::format(
        "stability: the run covers {:.1f} m, less than the {:g} m sliding-rms window: not assessed",
        covered, o.stability_window));
    return;
  }
  // f0: the peak of the track-shift forces' spectrum (summed over the axles) in the search band.
  if (std::isnan(o.f0)) {
    const auto hp = detail::zero_phase_bandpass(o.filter_order, 0.5 * o.f0_min,
                                                std::min(2.0 * o.f0_max, 0.4 * run.sample_rate),
                                                run.sample_rate);
    const auto segment = static_cast<std::size_t>(std::llround(5.0 * run.sample_rate));
    Spectrum total;
    for (const auto& w : wheelsets) {
      const auto s = welch_psd(hp(w.sum_y), run.sample_rate, segment);
      if (total.density.empty()) {
        total = s;
      } else {
        for (std::size_t k = 0; k < s.density.size(); ++k) total.density[k] += s.density[k];
      }
    }
    a.f0 = dominant_frequency(total, o.f0_min, o.f0_max);
    a.f0_from_spectrum = true;
    if (std::isnan(a.f0))
      throw std::invalid_argument(fmt::format(
          "{}: the spectrum has no bin in {:g}-{:g} Hz (run too short): give --f0", run.path,
          o.f0_min, o.f0_max));
    if (a.f0 <= o.f0_min + total.df || a.f0 >= o.f0_max - total.df)
      a.notes.push_back(fmt::format(
          "stability: the sum-Y spectrum has no peak inside {:g}-{:g} Hz (largest at the band's "
          "edge, {:.2f} Hz): no hunting; the band around it is assessed all the same",
          o.f0_min, o.f0_max, a.f0));
  } else {
    a.f0 = o.f0;
    a.f0_from_spectrum = false;
  }
  const double f_low = std::max(a.f0 - o.stability_half_band, 0.25 * a.f0);
  const double f_high = a.f0 + o.stability_half_band;
  const auto band = detail::zero_phase_bandpass(o.filter_order, f_low, f_high, run.sample_rate);
  for (const auto& w : wheelsets) {
    const auto rms = sliding_rms(w.position, band(w.sum_y), o.stability_window, o.stability_step);
    const double lim = 0.5 * prudhomme_limit(w.body->static_load, a.alpha);
    detail::add_rows(a, "stability", fmt::format("sum Y rms {:g} m, f0 +- {:g} Hz",
                                                 o.stability_window, o.stability_half_band),
                     w.body->name, "N", rms.position, rms.mean, Statistic::max_abs,
                     [&](const TrackSection&) { return lim; });
    a.signals.push_back(signal_of("sum Y rms", w.body->name, "N",
                                  fmt::format("sliding rms over {:g} m of sum Y in {:.2f}-{:.2f} Hz",
                                              o.stability_window, f_low, f_high),
                                  rms.position, rms.mean, lim));
  }
  // Bogie frames: lateral acceleration above each of their wheelsets.
  for (const auto& b : c.bodies) {
    if (b.kind != "bogie_frame") continue;
    std::vector<const RunBody*> own;
    for (const auto& w : c.bodies) {
      if (w.kind != "wheelset") continue;
      const RunBody* nearest = nullptr;
      for (const auto& bb : c.bodies)
        if (bb.kind == "bogie_frame" &&
            (nearest == nullptr || std::abs(bb.rest_x - w.rest_x) < std::abs(nearest->rest_x - w.rest_x)))
          nearest = &bb;
      if (nearest == &b) own.push_back(&w);
    }
    std::sort(own.begin(), own.end(),
              [](const RunBody* l, const RunBody* r) { return l->rest_x > r->rest_x; });
    double mass = b.mass;
    for (const auto* w : own) mass += w->mass;
    const double lim = bogie_acceleration_limit(mass);
    std::vector<double> ydd, psidd;  // the rigid-body fallback
    for (std::size_t j = 0; j < own.size(); ++j) {
      const RunBody* w = own[j];
      const std::string sensor =
          fmt::format("{}_{}", b.name, j == 0 ? "front" : j + 1 == own.size() ? "rear" : "middle");
      const std::string item = fmt::format("{} above {}", b.name, w->name);
      std::vector<double> acc, place;
      if (run.has(sensor + ".ay")) {
        auto s = run.located(sensor + ".ay", c.anti_alias_delay());
        acc = std::move(s.value);
        place = std::move(s.position);
      } else {
        if (!run.has(b.name + ".y_dot")) continue;
        if (ydd.empty()) {
          ydd = detail::derivative(run.time, run.get_or_zero(b.name + ".y_dot"));
          psidd = detail::derivative(run.time, run.get_or_zero(b.name + ".yaw_dot"));
        }
        a.accelerations_derived = true;
        const double dx = w->rest_x - b.rest_x;
        acc.resize(run.n());
        for (std::size_t i = 0; i < acc.size(); ++i) acc[i] = ydd[i] + dx * psidd[i];
        place = run.position;
      }
      const auto filtered = band(acc);
      const auto pos = detail::shifted(place, w->rest_x);
      const auto rms = sliding_rms(pos, filtered, o.stability_window, o.stability_step);
      detail::add_rows(a, "stability", fmt::format("bogie frame lateral acc. rms {:g} m",
                                                   o.stability_window),
                       item, "m/s^2", rms.position, rms.mean, Statistic::max_abs,
                       [&](const TrackSection&) { return lim; });
      detail::add_rows(a, "stability", "bogie frame lateral acc. peak", item, "m/s^2", pos,
                       filtered, Statistic::max_abs, nullptr);
      a.signals.push_back(signal_of("bogie frame lateral acc. rms", item, "m/s^2",
                                    fmt::format("sliding rms over {:g} m, {:.2f}-{:.2f} Hz",
                                                o.stability_window, f_low, f_high),
                                    rms.position, rms.mean, lim));
    }
  }
}

}  // namespace

Assessment assess_run(const std::string& h5_path, const AssessmentOptions& o) {
  const detail::RunSignals run(h5_path);
  RunContext c = read_run_context(run.file());
  if (c.bodies.empty())
    throw std::invalid_argument(fmt::format(
        "{}: no /vehicle group: the assessment reads runs of vehicle scenes written by this "
        "version of `ferrodyn run` (run the scene again)",
        h5_path));
  Assessment a;
  a.vehicle = c.vehicle;
  a.category = o.category.empty() ? c.category : o.category;
  if (a.category.empty())
    throw std::invalid_argument(fmt::format(
        "{}: the vehicle '{}' has no category (key `category` of the vehicle file: coach, "
        "locomotive, power_car or wagon); give it with --category",
        h5_path, c.vehicle));
  a.alpha = track_shift_alpha(a.category);
  a.mu = std::isnan(o.mu) ? c.friction : o.mu;
  a.sample_rate = run.sample_rate;
  a.twist_test = o.twist_test.value_or(c.twist_test);
  a.sections = make_sections(c, run, o);
  if (run.file().has_attribute("/", "status")) {
    const auto status = run.file().string_attribute("/", "status");
    if (status != "completed")
      a.notes.push_back(fmt::format("the run's status is '{}': assessed up to t = {:.6g} s",
                                    status, run.time.back()));
  }
  std::vector<Wheelset> wheelsets;
  for (const auto& b : c.bodies) {
    if (b.kind != "wheelset" || !run.has(b.name + ".left.Y")) continue;
    Wheelset w;
    w.body = &b;
    w.position = detail::shifted(run.position, b.rest_x);
    wheelsets.push_back(std::move(w));
  }
  if (wheelsets.empty())
    throw std::invalid_argument(fmt::format(
        "{}: no wheel forces (signals wheelset_<i>.<left|right>.Y, .Q, .contact_angle)", h5_path));
  assess_wheels(a, run, c, o, wheelsets);
  if (!a.forces_filtered_in_run)
    a.notes.push_back(
        "the run has no anti-alias filtered wheel forces (Y_filtered, Q_filtered): content above "
        "the Nyquist frequency of its output aliases into the assessed values (run with "
        "output.anti_alias_frequency, or a finer output.interval)");
  assess_stability(a, run, c, o, wheelsets);
  detail::assess_ride(a, run, c, o);
  return a;
}

}  // namespace ferro::scenarios::analysis
