// Cost of an 8 s suspended-wheelset run (4 states, 8001 outputs, no file I/O) with each
// integrator at rtol 1e-8. Compare the ratios within one run; absolute times on shared 2-core
// machines are noisy.
#include <benchmark/benchmark.h>

#include "ferro/vehicle/integrator.hpp"
#include "ferro/vehicle/suspended_wheelset.hpp"

namespace {
using namespace ferro::vehicle;

SuspendedWheelset make_wheelset(double speed) {
  SuspendedWheelsetParams p;
  p.mass = 1813.0;
  p.half_gauge = 0.7465;
  p.yaw_inertia = p.mass * p.half_gauge * p.half_gauge;
  p.rolling_radius = 0.46;
  p.conicity = 0.2;
  p.primary_stiffness_x = p.primary_stiffness_y = 0.8e6;
  LinearCreepParams c;
  c.semi_axis_a = 6e-3;
  c.semi_axis_b = 4e-3;
  c.coefficients = "equal";
  return SuspendedWheelset(p, creep_coefficients(c), speed);
}

void BM_WheelsetRun(benchmark::State& state, const std::string& method) {
  const auto sys = make_wheelset(36.98);
  IntegratorSettings s;
  s.method = method;
  s.rtol = 1e-8;
  s.atol = 1e-11;
  const auto times = output_grid(0.0, 8.0, 1e-3);
  const std::vector<double> x0{1e-3, 0.0, 0.0, 0.0};
  long rhs = 0;
  for (auto _ : state) {
    auto integ = make_integrator(s);
    double sink = 0.0;
    const auto r = integ->integrate(sys, x0, times, [&](double, std::span<const double> x) {
      sink += x[0];
      return true;
    });
    benchmark::DoNotOptimize(sink);
    rhs = r.rhs_evaluations;
  }
  state.counters["rhs_evals"] = static_cast<double>(rhs);
}

BENCHMARK_CAPTURE(BM_WheelsetRun, cvode_bdf, std::string("cvode_bdf"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WheelsetRun, cvode_adams, std::string("cvode_adams"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WheelsetRun, arkode_erk, std::string("arkode_erk"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WheelsetRun, arkode_dirk, std::string("arkode_dirk"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WheelsetRun, odeint_dopri5, std::string("odeint_dopri5"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_WheelsetRun, odeint_rosenbrock4, std::string("odeint_rosenbrock4"))
    ->Unit(benchmark::kMillisecond);

void BM_WheelsetRhs(benchmark::State& state) {
  const auto sys = make_wheelset(36.98);
  std::vector<double> x{1e-3, 1e-4, 1e-2, 1e-3}, xd(4);
  for (auto _ : state) {
    sys.rhs(0.0, x, xd);
    benchmark::DoNotOptimize(xd.data());
  }
}
BENCHMARK(BM_WheelsetRhs);

}  // namespace

BENCHMARK_MAIN();
