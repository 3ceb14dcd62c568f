// Cost of evaluating the design track frame and the irregularities at one arc length.
// Figures go to docs/PERFORMANCE.md. Run:
//   ./build/bench/ferro_bench_track --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <vector>

#include "ferro/track/alignment.hpp"
#include "ferro/track/irregularity.hpp"
#include "ferro/track/kinematics.hpp"
#include "ferro/track/measured_irregularity.hpp"
#include "ferro/track/stochastic_irregularity.hpp"

namespace {

using namespace ferro::track;

TrackDesign bench_design() {
  // Toumi Fig. 4.4-like layout repeated: straights, transitions and curves.
  TrackDesign d;
  for (int i = 0; i < 10; ++i) {
    const double sign = (i % 2 == 0) ? 1.0 : -1.0;
    d.sections.push_back({SectionKind::kStraight, 50.0});
    d.sections.push_back({SectionKind::kTransition, 80.0});
    d.sections.push_back({SectionKind::kCurve, 300.0, sign * 600.0, sign * 0.12, 0.0});
    d.sections.push_back({SectionKind::kTransition, 80.0});
  }
  d.sections.push_back({SectionKind::kStraight, 50.0});
  return d;
}

// Random arc lengths restricted to one section kind (so clothoid and arc costs separate).
std::vector<double> samples_in(const Alignment& a, SectionKind kind, int count) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(a.start_s(), a.end_s());
  std::vector<double> out;
  while (static_cast<int>(out.size()) < count) {
    const double s = u(rng);
    if (a.design().sections[a.frame(s).section].kind == kind) out.push_back(s);
  }
  return out;
}

void BM_frame(benchmark::State& state, SectionKind kind) {
  const Alignment a(bench_design());
  const auto ss = samples_in(a, kind, 1024);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(a.frame(ss[i++ & 1023]));
  }
}
BENCHMARK_CAPTURE(BM_frame, straight, SectionKind::kStraight);
BENCHMARK_CAPTURE(BM_frame, transition_clothoid, SectionKind::kTransition);
BENCHMARK_CAPTURE(BM_frame, curve, SectionKind::kCurve);

void BM_frame_kinematics(benchmark::State& state) {
  const Alignment a(bench_design());
  const auto ss = samples_in(a, SectionKind::kTransition, 1024);
  std::size_t i = 0;
  for (auto _ : state) {
    const TrackFrame f = a.frame(ss[i++ & 1023]);
    benchmark::DoNotOptimize(frame_kinematics(f, 50.0, 0.1));
  }
}
BENCHMARK(BM_frame_kinematics);

StochasticIrregularitySpec stochastic_spec() {
  StochasticIrregularitySpec spec;
  spec.spectrum = TrackSpectrum::kErriLow;
  spec.length = 10000.0;
  spec.wavelength_min = 3.0;
  spec.wavelength_max = 150.0;
  return spec;
}

std::vector<double> uniform_samples(double lo, double hi, int count) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> out(count);
  for (auto& s : out) s = u(rng);
  return out;
}

void BM_stochastic_at(benchmark::State& state) {
  const StochasticIrregularity irr(stochastic_spec());
  const auto ss = uniform_samples(0.0, 10000.0, 4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(irr.at(ss[i++ & 4095]));
  state.counters["components"] = static_cast<double>(irr.component_count());
}
BENCHMARK(BM_stochastic_at);

void BM_stochastic_at_direct(benchmark::State& state) {
  const StochasticIrregularity irr(stochastic_spec());
  const auto ss = uniform_samples(0.0, 10000.0, 4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(irr.at_direct(ss[i++ & 4095]));
  state.counters["components"] = static_cast<double>(irr.component_count());
}
BENCHMARK(BM_stochastic_at_direct)->Unit(benchmark::kMicrosecond);

void BM_stochastic_synthesis_10km(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(StochasticIrregularity(stochastic_spec()));
}
BENCHMARK(BM_stochastic_synthesis_10km)->Unit(benchmark::kMillisecond);

void BM_measured_at(benchmark::State& state) {
  // 10 km sampled every 0.25 m (40001 rows), built from samples (no file I/O in the loop).
  const int n = 40001;
  std::vector<double> s(n), lat(n), ver(n), cl(n), g(n);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 1e-3);
  for (int i = 0; i < n; ++i) {
    s[i] = 0.25 * i;
    lat[i] = noise(rng);
    ver[i] = noise(rng);
    cl[i] = noise(rng);
    g[i] = noise(rng);
  }
  const MeasuredIrregularity m(s, lat, ver, cl, g);
  const auto ss = uniform_samples(0.0, 10000.0, 4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(m.at(ss[i++ & 4095]));
}
BENCHMARK(BM_measured_at);

void BM_sum_defects_and_stochastic(benchmark::State& state) {
  IrregularitySum sum;
  sum.add(std::make_shared<StochasticIrregularity>(stochastic_spec()));
  for (int k = 0; k < 3; ++k) {
    IsolatedDefectSpec d;
    d.amplitude = 0.01;
    d.wavelength = 20.0;
    d.start_s = 1000.0 * (k + 1);
    sum.add(std::make_shared<IsolatedDefect>(d));
  }
  const auto ss = uniform_samples(0.0, 10000.0, 4096);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(sum.at(ss[i++ & 4095]));
}
BENCHMARK(BM_sum_defects_and_stochastic);

}  // namespace

BENCHMARK_MAIN();
