// MIM speed: normal + steady-rolling tangential solve on the thesis's sphere case
// (R1 = 300 mm, R2 = 460 mm, steel, F_n = 517.9 kN i.e. delta = 0.4 mm, mu = 0.2,
// xi_x = 3 per mille), N x N elements covering the patch with 5 % margin.
// The influence operator (kernels, FFTW plans) is built once per grid outside the timed loop,
// as in a table or dynamics run; BM_MimSetup times that construction separately.
//
// Run: ./build/bench/ferro_bench_mim --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "ferro/contact/mim/normal_solver.hpp"
#include "ferro/contact/mim/tangential_solver.hpp"

using namespace ferro::contact;
using namespace ferro::contact::mim;

namespace {

constexpr double kRrel = 1.0 / (1.0 / 0.300 + 1.0 / 0.460);
constexpr double kNormalForce = 517925.0;  // delta = 0.4 mm for these spheres [N]

Grid sphere_grid(int n) {
  const double a = std::sqrt(kRrel * 0.4e-3);
  const double dx = 2.0 * a * 1.05 / n;
  return Grid::centred(n, n, dx, dx);
}

CombinedMaterial steel_pair() {
  const Material s = Material::from_young(210.0e9, 0.28);
  return combine(s, s);
}

void BM_MimNormalRolling(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Grid grid = sphere_grid(n);
  InfluenceOperator op(grid, steel_pair(), /*measure_plans=*/true);
  const Field gap =
      sample(grid, [](double x, double y) { return (x * x + y * y) / (2.0 * kRrel); });
  TangentialSolverOptions topt;
  topt.tolerance = 1.0e-5;
  NormalSolverOptions nopt;
  nopt.tolerance = 1.0e-8;
  // Coarse operators of the nested iteration are built on first use: do it before timing.
  (void)solve_steady_rolling(op, solve_normal_force(op, gap, kNormalForce, nopt).pressure,
                             RollingInput{3.0e-3, 0.0, 0.0, 0.2}, topt);
  double fx = 0.0;
  int matvecs = 0, normal_it = 0;
  for (auto _ : state) {
    const NormalGridSolution s = solve_normal_force(op, gap, kNormalForce, nopt);
    const TangentialGridSolution t =
        solve_steady_rolling(op, s.pressure, RollingInput{3.0e-3, 0.0, 0.0, 0.2}, topt);
    benchmark::DoNotOptimize(t.force_x);
    fx = t.force_x;
    matvecs = t.matvecs;
    normal_it = s.iterations;
  }
  state.counters["elements"] = static_cast<double>(grid.size());
  state.counters["Fx_over_muFn"] = fx / (0.2 * kNormalForce);
  state.counters["tang_matvecs"] = matvecs;
  state.counters["normal_iter"] = normal_it;
}
BENCHMARK(BM_MimNormalRolling)
    ->Arg(20)
    ->Arg(35)
    ->Arg(50)
    ->Arg(70)
    ->Arg(100)
    ->Arg(140)
    ->Arg(200)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

void BM_MimSetup(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Grid grid = sphere_grid(n);
  for (auto _ : state) {
    InfluenceOperator op(grid, steel_pair());
    benchmark::DoNotOptimize(op.normal_self());
  }
}
BENCHMARK(BM_MimSetup)->Arg(50)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
