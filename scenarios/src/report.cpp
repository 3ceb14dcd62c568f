// Text reports of runs and eigenvalue sweeps (see the header).
#include "ferro/scenarios/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>
#include <numbers>

#include "ferro/scenarios/model_factory.hpp"

namespace ferro::scenarios {

std::string valid_scene_line(const std::string& path, const Scene& s) {
  return fmt::format(
      "{}: valid scene '{}' (schema {}): model {}, track {}, integrator {}, t_end {} s, V = {} "
      "m/s\n",
      path, s.name, s.schema_version, s.model.type, s.track.type, s.solver.method,
      s.simulation.t_end, s.simulation.speed);
}

std::string run_report(const Scene& scene, const RunSummary& s) {
  std::string text;
  auto out = std::back_inserter(text);
  const double v = scene.simulation.speed;
  fmt::format_to(out, "ferrodyn run: {} ({})\n", scene.name, scene.path);
  fmt::format_to(out, "  model     {}, V = {:.3f} m/s ({:.1f} km/h)\n", scene.model.type, v,
                 v * 3.6);
  if (scene.model.type == "vehicle") {
    fmt::format_to(out, "  vehicle   {} (scope {}), contact {} geometry, {} creep forces\n",
                   scene.model.vehicle.name, scene.model.selection.scope,
                   scene.model.vehicle.wheel_rail.geometry,
                   scene.model.vehicle.wheel_rail.tangential_model);
  } else {
    const auto sys = build_system(scene, v);
    const auto modes = vehicle::linear_modes(*sys, 0.0, equilibrium_state(scene, *sys));
    if (!modes.empty()) {
      fmt::format_to(out,
                     "  linear    least damped mode at V: damping ratio {:+.4f}, {:.3f} Hz ({})\n",
                     modes.front().damping_ratio, modes.front().frequency_hz,
                     modes.front().damping_ratio > 0.0 ? "stable" : "unstable");
    }
  }
  if (scene.solver.fixed_step > 0.0) {
    fmt::format_to(
        out, "  solver    {} (fixed step {:g} s, no error control): {} steps, {} rhs evaluations\n",
        scene.solver.method, scene.solver.fixed_step, s.steps, s.rhs_evaluations);
  } else {
    fmt::format_to(out, "  solver    {} (rtol {:g}, atol {:g}): {} steps, {} rhs evaluations\n",
                   scene.solver.method, scene.solver.rtol, scene.solver.atol, s.steps,
                   s.rhs_evaluations);
  }
  fmt::format_to(
      out, "  status    {} at t = {:.6g} s: {} samples in {:.3f} s wall ({:.1f}x real time)\n",
      s.status_text, s.t_reached, s.samples, s.wall_seconds,
      s.wall_seconds > 0 ? s.t_reached / s.wall_seconds : 0.0);
  if (!s.message.empty()) fmt::format_to(out, "  cause     {}\n", s.message);
  fmt::format_to(out, "  {:<30} {:<6} {:>12} {:>12}\n", "signal", "unit", "peak |x|", "final");
  // A vehicle has many channels: the summary shows wheel forces, wheelset displacements and
  // car-body acceleration (the HDF5 file has them all).
  const auto shown = [&](const std::string& name) {
    if (scene.model.type != "vehicle") return true;
    for (const char* end : {".Y", ".Q", ".points", "ay"}) {
      const std::string e(end);
      if (name.size() >= e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0)
        return true;
    }
    return name.rfind("wheelset_", 0) == 0 &&
           (name.size() > 2 && (name.substr(name.size() - 2) == ".y" ||
                                (name.size() > 4 && name.substr(name.size() - 4) == ".yaw")));
  };
  for (std::size_t i = 0; i < s.channels.size(); ++i) {
    if (!shown(s.channels[i].name)) continue;
    fmt::format_to(out, "  {:<30} {:<6} {:>12.5g} {:>12.5g}\n", s.channels[i].name,
                   s.channels[i].unit, s.peak_abs[i], s.final_values[i]);
  }
  return text;
}

std::string eigen_modes_report(const Scene& scene, const EigenReport& r, std::size_t max_rows) {
  std::string text;
  auto out = std::back_inserter(text);
  using vehicle::ModeClass;
  const auto cell = [](const vehicle::Mode& m) {
    return std::isnan(m.damping_ratio) ? fmt::format("{:>10} {:>8}", "-", "-")
                                       : fmt::format("{:>+10.5f} {:>8.3f}", m.damping_ratio,
                                                     m.frequency_hz);
  };
  const bool classified = !r.sweep.empty() && r.sweep.front().least_damped.kind !=
                                                  ModeClass::unclassified;
  const std::size_t stride = std::max<std::size_t>(1, (r.sweep.size() + max_rows - 1) / max_rows);
  if (classified) {
    // Classes other than hunting and contact only where the model has such modes.
    std::vector<ModeClass> shown = {ModeClass::hunting, ModeClass::contact};
    for (const auto c : {ModeClass::longitudinal, ModeClass::body, ModeClass::track}) {
      for (const auto& p : r.sweep) {
        if (!std::isnan(p.of(c).damping_ratio)) {
          shown.push_back(c);
          break;
        }
      }
    }
    fmt::format_to(out, "  hunting mode (followed down from the highest speed by its shape) and the least "
               "damped mode of each other class: damping ratio, frequency [Hz]; shapes as "
               "kinetic-energy shares\n");
    fmt::format_to(out, "  {:>8} {:>8}", "V [m/s]", "V [km/h]");
    for (const auto c : shown) fmt::format_to(out, " | {:<19}", vehicle::to_string(c));
    fmt::format_to(out, " | hunting mode shape\n");
    for (std::size_t i = 0; i < r.sweep.size(); i += stride) {
      const auto& p = r.sweep[i];
      fmt::format_to(out, "  {:>8.3f} {:>8.2f}", p.speed, p.speed * 3.6);
      for (const auto c : shown) fmt::format_to(out, " | {}", cell(c == ModeClass::hunting ? p.hunting : p.of(c)));
      fmt::format_to(out, " | {}{}\n", p.hunting.shape(),
                 p.hunting_correlation < vehicle::kShapeTracked
                     ? " (branch lost above: least damped hunting-class mode)"
                     : "");
    }
  } else {
    fmt::format_to(out, "  {:>10} {:>10} {:>14} {:>12}\n", "V [m/s]", "V [km/h]", "damping ratio",
               "freq [Hz]");
    for (std::size_t i = 0; i < r.sweep.size(); i += stride) {
      const auto& p = r.sweep[i];
      fmt::format_to(out, "  {:>10.3f} {:>10.2f} {:>+14.5f} {:>12.4f}\n", p.speed, p.speed * 3.6,
                 p.least_damped.damping_ratio, p.least_damped.frequency_hz);
    }
  }
  if (r.critical_speed) {
    fmt::format_to(out, "  Hopf speed ({} mode crosses zero damping): {:.6f} m/s = {:.3f} km/h\n",
               classified ? "a hunting" : "the least damped", *r.critical_speed,
               *r.critical_speed * 3.6);
  } else {
    fmt::format_to(out, "  no {}critical speed in [{:g}, {:g}] m/s\n", classified ? "hunting " : "",
               scene.eigen.speed_min, scene.eigen.speed_max);
  }
  if (classified) {
    // Other classes that are unstable somewhere: reported, not taken for hunting.
    for (const auto c : {ModeClass::contact, ModeClass::longitudinal, ModeClass::body,
                         ModeClass::track}) {
      for (const auto& p : r.sweep) {
        if (p.of(c).damping_ratio <= -vehicle::kNeutralDamping) {
          fmt::format_to(out, "  note      a {} mode is unstable at {:.3f} m/s ({:.3f} Hz, damping {:+.5f}, "
                     "{})\n",
                     vehicle::to_string(c), p.speed, p.of(c).frequency_hz, p.of(c).damping_ratio,
                     p.of(c).shape());
          break;
        }
      }
    }
    if (!r.modes_at_scene_speed.empty()) {
      fmt::format_to(out, "  modes at the scene's speed {:.3f} m/s, least damped first (up to 12):\n",
                 scene.simulation.speed);
      std::size_t shown = 0;
      for (const auto& m : r.modes_at_scene_speed) {
        if (m.eigenvalue.imag() < 0.0) continue;  // one of each complex pair
        fmt::format_to(out, "    {:<12} {:>+10.5f} {:>9.3f} Hz  {}\n", vehicle::to_string(m.kind),
                   m.damping_ratio, m.frequency_hz, m.shape());
        if (++shown == 12) break;
      }
    }
  }
  return text;
}

std::string eigen_sweep_report(const Scene& scene, const EigenReport& r) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(out, "ferrodyn eig: {} ({}), {} speeds in [{:g}, {:g}] m/s\n", scene.name,
                 scene.path, scene.eigen.points, scene.eigen.speed_min, scene.eigen.speed_max);
  text += eigen_modes_report(scene, r, 16);
  if (r.closed_form_critical_speed) {
    fmt::format_to(out, "  closed form eq. (151): {:.6f} m/s", *r.closed_form_critical_speed);
    if (r.critical_speed) {
      fmt::format_to(out, " (relative difference {:.2e})",
                     *r.critical_speed / *r.closed_form_critical_speed - 1.0);
    }
    fmt::format_to(out, "\n");
  } else if (!r.closed_form_note.empty()) {
    fmt::format_to(out, "  {}\n", r.closed_form_note);
  }
  return text;
}

std::string wheelset_contact_report(const std::vector<contact::WheelsetContact>& results) {
  std::string text;
  auto out = std::back_inserter(text);
  fmt::format_to(
      out,
      "{:>4} {:>5} {:>5} {:>2} {:>8} {:>8} {:>8} {:>7} {:>8} {:>10} {:>10} {:>9} {:>8} {:>8} "
      "{:>8} {:>6} {:>7} {:>8}\n",
      "case", "y", "wheel", "np", "height", "rail_y", "wheel_y", "angle", "N", "xi_x", "xi_y",
      "phi", "F_x", "F_y", "M_z", "delta", "p_max", "Q");
  fmt::format_to(
      out,
      "{:>4} {:>5} {:>5} {:>2} {:>8} {:>8} {:>8} {:>7} {:>8} {:>10} {:>10} {:>9} {:>8} {:>8} "
      "{:>8} {:>6} {:>7} {:>8}\n",
      "", "mm", "", "", "mm", "mm", "mm", "deg", "N", "-", "-", "1/m", "N", "N", "N m", "um", "MPa",
      "N");
  for (const auto& r : results) {
    for (const auto& w : r.wheels) {
      for (const auto& p : w.patches) {
        fmt::format_to(
            out,
            "{:>4} {:>5.1f} {:>5} {:>2} {:>8.4f} {:>8.3f} {:>8.3f} {:>7.3f} {:>8.1f} {:>10.3e} "
            "{:>10.3e} {:>9.4f} {:>8.1f} {:>8.1f} {:>8.3f} {:>6.2f} {:>7.1f} {:>8.1f}\n",
            r.input.id, r.input.lateral * 1e3, w.side == contact::Side::left ? "left" : "right",
            w.patches.size(), w.vertical * 1e3, p.rail_y * 1e3, p.wheel_y * 1e3,
            p.contact_angle * 180.0 / std::numbers::pi, p.normal_force, p.creepage.longitudinal,
            p.creepage.lateral, p.creepage.spin, p.force_x, p.force_y, p.moment_z, p.approach * 1e6,
            p.peak_pressure * 1e-6, w.vertical_load);
      }
    }
  }
  return text;
}

}  // namespace ferro::scenarios
