// The multibody vehicle: one right-hand side and one simulated second of Manchester vehicle 1
// at 55 m/s on straight track (2 mm initial lateral offset of the leading wheelset), CVODE BDF
// with the band solver, rtol 1e-4, atol 1e-6; and one simulated second of the same vehicle with
// damped normal contact (Hunt-Crossley alpha = 3 s/m) by the order-3 Bogacki-Shampine formula
// at a fixed 1 ms step, as Odeint's generic stepper (odeint_bs3) and as ARKODE's order-3 method
// (the same formula; the difference is each package's work per step). The CPU column of
// "second" is the CPU time per simulated second. The vehicle is the shipped vehicle file
// (scenarios/vehicles/manchester_vehicle1.yaml) on conical wheel-rail geometry.
#include <benchmark/benchmark.h>

#include <string>

#include "ferro/scenarios/vehicle_file.hpp"
#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace {

using namespace ferro::vehicle;

std::unique_ptr<VehicleModel> manchester(const std::string& tangential, double alpha = 0.0) {
  VehicleModelInputs in;
  in.config = ferro::scenarios::load_vehicle_file(std::string(FERRO_SOURCE_DIR) +
                                                  "/scenarios/vehicles/manchester_vehicle1.yaml");
  WheelRailSpec& wr = in.config.wheel_rail;
  wr.geometry = "conical";
  wr.nominal_radius = 0.46;
  wr.conicity = 0.1;
  wr.contact_half_distance = 0.75;
  wr.conical_curvature_a = 1.0 / 0.92;
  wr.conical_curvature_b = 1.0 / 0.6;
  wr.tangential_model = tangential;
  wr.hunt_crossley_alpha = alpha;
  in.geometry = make_geometry_source(wr, FERRO_DATA_DIR);
  in.speed.initial = 55.0;
  return std::make_unique<VehicleModel>(std::move(in));
}

void BM_vehicle_rhs(benchmark::State& state, const std::string& tangential) {
  const auto m = manchester(tangential);
  const auto x = static_equilibrium(*m);
  std::vector<double> xdot(x.size());
  for (auto _ : state) {
    benchmark::DoNotOptimize(m->rhs(0.0, x, xdot));
  }
}

// One simulated second from the equilibrium with the leading wheelset 2 mm off, per iteration.
void run_second(benchmark::State& state, const VehicleModel& m, const IntegratorSettings& s,
                double output_interval) {
  auto x0 = static_equilibrium(m);
  x0[static_cast<std::size_t>(m.state_index("wheelset_1", Dof::y))] += 0.002;
  const auto grid = output_grid(0.0, 1.0, output_interval);
  for (auto _ : state) {
    auto integrator = make_integrator(s);
    const auto r = integrator->integrate(m, x0, grid, [](double, auto) { return true; });
    if (r.status != IntegrationResult::Status::kCompleted) state.SkipWithError(r.message.c_str());
    state.counters["steps"] = static_cast<double>(r.steps);
    state.counters["rhs"] = static_cast<double>(r.rhs_evaluations);
  }
}

void BM_vehicle_second(benchmark::State& state, const std::string& tangential) {
  IntegratorSettings s;
  s.method = "cvode_bdf";
  s.linear_solver = "band";
  s.rtol = 1e-4;
  s.atol = 1e-6;
  s.max_step = 0.01;
  run_second(state, *manchester(tangential), s, 0.01);
}

void BM_vehicle_second_fixed_step(benchmark::State& state, const std::string& method) {
  IntegratorSettings s;
  s.method = method;
  s.erk_order = 3;
  s.fixed_step = 1e-3;
  s.rtol = 1e-2;
  s.atol = 1e-5;
  run_second(state, *manchester("chopaya", 3.0), s, 0.005);
}

BENCHMARK_CAPTURE(BM_vehicle_rhs, chopaya, std::string("chopaya"));
BENCHMARK_CAPTURE(BM_vehicle_rhs, fastsim, std::string("fastsim"));
BENCHMARK_CAPTURE(BM_vehicle_second, chopaya, std::string("chopaya"))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_vehicle_second, fastsim, std::string("fastsim"))
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_vehicle_second_fixed_step, odeint_bs3, std::string("odeint_bs3"))
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(BM_vehicle_second_fixed_step, arkode_erk3, std::string("arkode_erk"))
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
