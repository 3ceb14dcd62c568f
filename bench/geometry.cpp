// Wheel-rail geometry kernels: contact-table look-up and the full 3D contact search of one
// wheelset (both wheels), S1002 / UIC60 1:40 (Manchester data).

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "ferro/contact/geometry/conical_source.hpp"
#include "ferro/contact/geometry/contact_table.hpp"
#include "ferro/contact/geometry/imported_contact_table.hpp"
#include "ferro/contact/geometry/multi_point_contact_table.hpp"
#include "ferro/contact/geometry/point_normal_contact.hpp"
#include "ferro/contact/geometry/search_source.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"
#include "ferro/contact/normal/hertz.hpp"

namespace fc = ferro::contact;

namespace {

fc::WheelRailPair make_a22_pair(double section_step) {
  const std::string d = std::string(FERRO_DATA_DIR) + "/profiles/";
  fc::WheelRailPairParams p;
  p.track_gauge = 1.435;
  p.flange_back_distance = 1.360;
  p.flange_back_y = -0.070;
  p.nominal_radius = 0.460;
  p.section_step = section_step;
  return fc::WheelRailPair(fc::read_simpack_profile(d + "MBench_S1002_v3.prw"),
                           fc::read_simpack_profile(d + "MBench_UIC60_v3.prr"), p);
}

const fc::WheelRailPair& a22_pair(bool coarse = false) {
  static const fc::WheelRailPair pair = make_a22_pair(0.5e-3);
  static const fc::WheelRailPair pair_coarse = make_a22_pair(1.0e-3);
  return coarse ? pair_coarse : pair;
}

const fc::ContactTable& a22_table(bool with_yaw) {
  static const fc::ContactTable t0 = [] {
    fc::ContactTableParams tp;
    return fc::ContactTable::build(a22_pair(), tp);
  }();
  static const fc::ContactTable t1 = [] {
    fc::ContactTableParams tp;
    tp.lateral_step = 0.2e-3;
    tp.yaw = {-0.02, -0.01, 0.0, 0.01, 0.02};
    return fc::ContactTable::build(a22_pair(), tp);
  }();
  return with_yaw ? t1 : t0;
}

std::vector<double> random_shifts(std::size_t n) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-0.011, 0.011);
  std::vector<double> v(n);
  for (auto& x : v) x = u(rng);
  return v;
}

void BM_GeometryTableLookupAll(benchmark::State& state) {
  const fc::ContactTable& t = a22_table(false);
  const auto ys = random_shifts(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(t.lookup(ys[i++ & 1023]));
  }
}
BENCHMARK(BM_GeometryTableLookupAll);

void BM_GeometryTableLookupYaw(benchmark::State& state) {
  const fc::ContactTable& t = a22_table(true);
  const auto ys = random_shifts(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    const double y = ys[i++ & 1023];
    benchmark::DoNotOptimize(t.lookup(y, 0.5 * y));
  }
}
BENCHMARK(BM_GeometryTableLookupYaw);

void BM_GeometryTableDeltaR(benchmark::State& state) {
  const fc::ContactTable& t = a22_table(false);
  const auto ys = random_shifts(1024);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(t.delta_r(ys[i++ & 1023]));
  }
}
BENCHMARK(BM_GeometryTableDeltaR);

// Full 3D search, both wheels, every contact point: cases 1 (centred), 11 (two-point)
// and 17 (yawed flange contact), with a penetration so that points exist.
// Arg 0: case; arg 1: 1 for 1 mm wheel sections instead of the default 0.5 mm.
void BM_GeometrySearch3D(benchmark::State& state) {
  const fc::WheelRailPair& pair = a22_pair(state.range(1) != 0);
  static const double cases[3][3] = {
      {0.0, 0.0, 0.0}, {5.0e-3, -0.00035540, 0.0120}, {8.0e-3, -0.00860600, 0.0192}};
  const auto* c = cases[state.range(0)];
  fc::WheelsetPose pose{c[0], 0.0, c[1], c[2]};
  pose = fc::touching_pose(pair, pose);
  pose.vertical += 20e-6;
  std::size_t n = 0;
  for (auto _ : state) {
    const auto pts = fc::search_contacts(pair, pose);
    n += pts.size();
    benchmark::DoNotOptimize(pts.data());
  }
  state.counters["points"] = static_cast<double>(n) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_GeometrySearch3D)->ArgsProduct({{0, 1, 2}, {0, 1}})->Unit(benchmark::kMicrosecond);

void BM_GeometryVerticalLoadSolve(benchmark::State& state) {
  const fc::WheelRailPair& pair = a22_pair();
  const fc::WheelsetPose pose{8.0e-3, 0.0, -0.00860600, 0.0192};
  const double estar = 2.0 * 82e9 * 1.28 / (2.0 * (1.0 - 0.28 * 0.28));
  for (auto _ : state) {
    benchmark::DoNotOptimize(fc::solve_vertical_load(pair, pose, 20000.0, estar));
  }
}
BENCHMARK(BM_GeometryVerticalLoadSolve)->Unit(benchmark::kMicrosecond);

// Normal patch of one contact point from its penetration (the dynamics' Hertz entry point):
// arg 0 = curvatures (tabulated exact Hertz relation), 1 = reference state (imported tables).
// Baseline: the exact load-driven Hertz solve (Newton on the elliptic integrals) in the same run.
void BM_HertzPatchFromPenetration(benchmark::State& state) {
  const double estar = 2.0 * 82e9 * 1.28 / (2.0 * (1.0 - 0.28 * 0.28));
  std::vector<fc::WheelRailContact> pts(1024);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (auto& c : pts) {
    c.curvature_a = 1.0 + u(rng);
    c.curvature_b = std::exp(8.0 * u(rng) - 2.0);
    c.penetration = 10e-6 + 100e-6 * u(rng);
    if (state.range(0) == 1) {
      c.ref_normal_force = 60e3;
      c.ref_penetration = 80e-6;
      c.ref_semi_axis_a = 6e-3;
      c.ref_semi_axis_b = 4e-3;
    }
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fc::hertz_patch_from_penetration(pts[i++ & 1023], estar));
  }
}
BENCHMARK(BM_HertzPatchFromPenetration)->Arg(0)->Arg(1);

void BM_HertzSolveExact(benchmark::State& state) {
  const double estar = 2.0 * 82e9 * 1.28 / (2.0 * (1.0 - 0.28 * 0.28));
  std::vector<double> b(1024);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (auto& v : b) v = std::exp(8.0 * u(rng) - 2.0);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fc::hertz_solve(1.3, b[i++ & 1023], 5e4, estar));
  }
}
BENCHMARK(BM_HertzSolveExact);

// Both wheels of the analytic conical source (allocation-free after the first call).
void BM_ConicalSource(benchmark::State& state) {
  fc::ConicalContactParams q;
  q.conicity = 0.2;
  q.contact_half_distance = 0.7465;
  q.nominal_radius = 0.46;
  q.curvature_a = 1.087;
  q.curvature_b = 1.67;
  const fc::ConicalContactSource src(q);
  const auto ys = random_shifts(1024);
  std::vector<fc::WheelRailContact> out;
  out.reserve(4);
  std::size_t i = 0;
  for (auto _ : state) {
    src.contacts(fc::WheelsetPose{0.1 * ys[i++ & 1023], 1e-4, 0.0, 0.0}, out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_ConicalSource);

// Multi-point table over lateral shift and roll (the default grid: +-12 mm by 0.1 mm, +-12 mrad
// by 1 mrad, 6025 nodes), S1002 / UIC60 1:40: one build, then look-ups of both wheels at random
// off-grid poses with 20-120 um penetration.
const fc::MultiPointContactTable& a22_multi_point_table() {
  static const fc::MultiPointContactTable t =
      fc::MultiPointContactTable::build(a22_pair(), fc::MultiPointTableParams{});
  return t;
}

void BM_MultiPointTableBuild(benchmark::State& state) {
  for (auto _ : state) {
    const fc::MultiPointContactTable t =
        fc::MultiPointContactTable::build(a22_pair(), fc::MultiPointTableParams{});
    state.counters["nodes"] = static_cast<double>(t.node_count());
    state.counters["candidates"] = static_cast<double>(t.candidate_count());
  }
}
BENCHMARK(BM_MultiPointTableBuild)->Iterations(1)->Unit(benchmark::kMillisecond);

// 256 random loaded poses (lateral and roll within the table, 20-120 um interpenetration), the
// same for the table and the search benchmarks.
std::vector<fc::WheelsetPose> loaded_poses() {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> lat(-0.0115, 0.0115), roll(-0.0115, 0.0115),
      depth(20e-6, 120e-6);
  std::vector<fc::WheelsetPose> poses(256);
  for (auto& p : poses) {
    p = fc::touching_pose(a22_pair(), fc::WheelsetPose{lat(rng), 0.0, roll(rng), 0.0});
    p.vertical += depth(rng);
  }
  return poses;
}

void BM_MultiPointTableLookup(benchmark::State& state) {
  const fc::MultiPointContactTable& t = a22_multi_point_table();
  const std::vector<fc::WheelsetPose> poses = loaded_poses();
  std::vector<fc::WheelRailContact> out;
  out.reserve(2 * fc::MultiPointContactTable::kMaxPointsPerWheel);
  std::size_t i = 0, n = 0;
  for (auto _ : state) {
    t.contacts(poses[i++ & 255], out);
    n += out.size();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["points"] = static_cast<double>(n) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_MultiPointTableLookup);

// The same poses through the online search (baseline for the table).
void BM_SearchSourceLookup(benchmark::State& state) {
  const fc::SearchContactSource src(std::make_shared<const fc::WheelRailPair>(a22_pair()));
  const std::vector<fc::WheelsetPose> poses = loaded_poses();
  std::vector<fc::WheelRailContact> out;
  std::size_t i = 0;
  for (auto _ : state) {
    src.contacts(poses[i++ & 255], out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_SearchSourceLookup)->Unit(benchmark::kMicrosecond);

// Imported one-point table (Cooperrider wagon CSV): both wheels, natural splines of 11 columns.
void BM_ImportedTableLookup(benchmark::State& state) {
  static const fc::ImportedContactTable t(std::string(FERRO_DATA_DIR) +
                                          "/cooperrider_wagon/contact_table_s1002_uic60_1in40.csv");
  const auto ys = random_shifts(1024);
  std::vector<fc::WheelRailContact> out;
  out.reserve(2);
  std::size_t i = 0;
  for (auto _ : state) {
    t.contacts(fc::WheelsetPose{ys[i++ & 1023], 5e-6, 1e-3, 0.0}, out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_ImportedTableLookup);

}  // namespace

BENCHMARK_MAIN();
