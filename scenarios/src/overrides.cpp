#include "ferro/scenarios/overrides.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "ferro/scenarios/run.hpp"

namespace ferro::scenarios {
namespace {

void apply_simulation(Scene& scene, const RunOverrides& o, Spelling sp) {
  if (!std::isnan(o.t_end)) {
    if (!(o.t_end > 0.0) || !std::isfinite(o.t_end))
      throw std::invalid_argument(fmt::format("{}: must be a finite number > 0 s, got {}",
                                              spelled("t_end", sp), o.t_end));
    scene.simulation.t_end = o.t_end;
    (void)output_sample_count(o.t_end, scene.output.interval, spelled("t_end", sp));
  }
  if (!std::isnan(o.speed)) {
    // A vehicle may stand still (the creep forces then vanish); the linear wheelset's
    // equations divide by the speed.
    const bool vehicle = scene.model.type == "vehicle";
    if (!std::isfinite(o.speed) || (vehicle ? !(o.speed >= 0.0) : !(o.speed > 0.0))) {
      throw std::invalid_argument(fmt::format("{}: must be a finite number {} m/s for {} scenes, "
                                              "got {}",
                                              spelled("speed", sp), vehicle ? ">= 0" : "> 0",
                                              scene.model.type, o.speed));
    }
    scene.simulation.speed = o.speed;
  }
  if (!o.tangential.empty()) {
    override_tangential(scene, o.tangential, spelled("tangential", sp),
                        with_environment_options(o.tangential));
  }
  if (!std::isnan(o.t_end) || !std::isnan(o.speed)) {
    const std::string problem = track_extent_problem(scene, scene.simulation.t_end);
    if (!problem.empty()) {
      throw std::invalid_argument(
          fmt::format("{}: {}", spelled(!std::isnan(o.t_end) ? "t_end" : "speed", sp), problem));
    }
  }
  if (!o.normal.empty()) override_normal(scene, o.normal, spelled("normal", sp));
}

void apply_solver(Scene& scene, const RunOverrides& o, Spelling sp) {
  auto& solver = scene.solver;
  if (!o.integrator.empty()) {
    solver.method = o.integrator;
    // A scene's fixed step belongs to its explicit or implicit Runge-Kutta method: another
    // method given here runs with its error control (fixed_step sets a step explicitly).
    if (std::isnan(o.fixed_step) && !vehicle::takes_fixed_step(o.integrator))
      solver.fixed_step = 0.0;
  }
  if (!std::isnan(o.fixed_step)) {
    const std::string name = spelled("fixed_step", sp);
    if (!(o.fixed_step >= 0.0) || !std::isfinite(o.fixed_step))
      throw std::invalid_argument(
          fmt::format("{}: must be >= 0 s (0: adaptive steps), got {}", name, o.fixed_step));
    if (o.fixed_step > 0.0 && !vehicle::takes_fixed_step(solver.method))
      throw std::invalid_argument(fmt::format(
          "{}: only arkode_erk, arkode_dirk, odeint_bs3 and bdf2 take a fixed step; {} needs 0, "
          "got {}",
          name, solver.method, o.fixed_step));
    solver.fixed_step = o.fixed_step;
  }
  if (!o.integrator.empty() || !std::isnan(o.fixed_step))
    solver.validate(spelled(!o.integrator.empty() ? "integrator" : "fixed_step", sp));
  if (!std::isnan(o.rtol)) {
    if (!(o.rtol > 0.0 && o.rtol < 1.0))
      throw std::invalid_argument(
          fmt::format("{}: must lie in (0, 1), got {}", spelled("rtol", sp), o.rtol));
    solver.rtol = o.rtol;
  }
  if (!std::isnan(o.atol)) {
    if (!(o.atol > 0.0) || !std::isfinite(o.atol))
      throw std::invalid_argument(
          fmt::format("{}: must be finite and > 0, got {}", spelled("atol", sp), o.atol));
    solver.atol = o.atol;
  }
}

void apply_eigen_range(Scene& scene, const RunOverrides& o, Spelling sp) {
  if (std::isnan(o.speed_min) && std::isnan(o.speed_max) && o.points == 0) return;
  auto& e = scene.eigen;
  if (!std::isnan(o.speed_min)) e.speed_min = o.speed_min;
  if (!std::isnan(o.speed_max)) e.speed_max = o.speed_max;
  if (o.points != 0) e.points = o.points;
  if (!(e.speed_min > 0.0 && e.speed_max > e.speed_min)) {
    throw std::invalid_argument(fmt::format("{}/{}: need 0 < min < max, got {} and {}",
                                            spelled("speed_min", sp), spelled("speed_max", sp),
                                            e.speed_min, e.speed_max));
  }
  if (e.points < 2 || e.points > kMaxEigenPoints)
    throw std::invalid_argument(
        fmt::format("{}: must lie in 2..{}, got {}", spelled("points", sp), kMaxEigenPoints,
                    e.points));
}

}  // namespace

contact::ModelOptions with_environment_options(const std::string& model,
                                               contact::ModelOptions options) {
  if (model == "mim_table" && options.count("table") == 0) {
    const char* table = std::getenv("FERRO_MIM_TABLE");
    if (table != nullptr && *table != '\0') options["table"] = table;
  }
  return options;
}

Parameters parameters(RunOverrides& o) {
  return {
      Parameter{"t_end", "s", "end time (simulation.t_end)", &o.t_end, false}.within(
          {0.0, kNoBound, true, true, "s"}),
      Parameter{"speed", "m/s", "forward speed (simulation.speed)", &o.speed, false}.within(
          {0.0, kNoBound, false, true, "m/s"}),
      {"integrator", "", "integration method (solver.integrator)", &o.integrator, false},
      Parameter{"fixed_step", "s",
                "fixed step of arkode_erk, arkode_dirk, odeint_bs3, bdf2; 0: adaptive steps "
                "(solver.fixed_step)",
                &o.fixed_step, false}
          .within({0.0, kNoBound, false, true, "s"}),
      Parameter{"rtol", "-", "relative tolerance (solver.rtol)", &o.rtol, false}.within(
          {0.0, 1.0, true, true, ""}),
      Parameter{"atol", "SI state units", "absolute tolerance (solver.atol)", &o.atol, false}
          .within({0.0, kNoBound, true, true, ""}),
      {"tangential", "", "tangential contact model (vehicle scenes)", &o.tangential, false},
      {"normal", "", "normal contact model: hertz, semi_hertz (vehicle scenes)", &o.normal,
       false},
      Parameter{"speed_min", "m/s", "lowest speed of the eigenvalue sweep", &o.speed_min, false}
          .within({0.0, kNoBound, true, true, "m/s"}),
      Parameter{"speed_max", "m/s", "highest speed of the eigenvalue sweep", &o.speed_max,
                false}
          .within({0.0, kNoBound, true, true, "m/s"}),
      Parameter{"points", "", "speeds in the eigenvalue sweep", &o.points, false}.counting(
          {2, kMaxEigenPoints}),
  };
}

void apply_overrides(Scene& scene, const RunOverrides& overrides, Spelling spelling) {
  apply_simulation(scene, overrides, spelling);
  apply_solver(scene, overrides, spelling);
  apply_eigen_range(scene, overrides, spelling);
}

}  // namespace ferro::scenarios
