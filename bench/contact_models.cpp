// Cost per evaluation of the contact models (targets: linear + CHOPAYA <= 0.2 us,
// Hertz <= 1 us, FASTSIM 20 x 20 and FaStrip <= 5 us). Run: ./build/bench/ferro_bench_contact_models
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "ferro/contact/normal/elliptic.hpp"
#include "ferro/contact/normal/hertz.hpp"
#include "ferro/contact/normal/normal_model.hpp"
#include "ferro/contact/tangential/mim_table.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"

namespace fc = ferro::contact;

namespace {

// Thesis chapter 3 case: 7.5 t wheel, 920 mm, 1/10 cone on a 300 mm rail crown.
fc::NormalProblem thesis_problem() {
  fc::NormalProblem p;
  p.curvature_x = std::cos(std::atan(0.1)) / (2.0 * 0.460);
  p.curvature_y = 1.0 / 0.6;
  p.normal_force = 7.5e3 * 9.81;
  p.body1 = p.body2 = fc::Material::from_young(210e9, 0.28);
  return p;
}

void BM_hertz_solve(benchmark::State& state) {
  const fc::NormalProblem p = thesis_problem();
  const double e_star = fc::combine(p.body1, p.body2).contact_modulus;
  double b = p.curvature_y;
  for (auto _ : state) {
    b = b == p.curvature_y ? 1.01 * p.curvature_y : p.curvature_y;  // defeat caching
    benchmark::DoNotOptimize(fc::hertz_solve(p.curvature_x, b, p.normal_force, e_star));
  }
}
BENCHMARK(BM_hertz_solve);

void BM_hertz_model(benchmark::State& state) {
  const fc::NormalProblem p = thesis_problem();
  const auto model = fc::make_normal_model("hertz");
  for (auto _ : state) benchmark::DoNotOptimize(model->solve(p));
}
BENCHMARK(BM_hertz_model);

// K(k) and E(k) together: the arithmetic-geometric mean the Hertz solution uses, and the
// libstdc++ special functions it replaced (baseline in the same run).
void BM_elliptic_agm(benchmark::State& state) {
  double k = 0.6;
  for (auto _ : state) {
    k = k == 0.6 ? 0.61 : 0.6;
    benchmark::DoNotOptimize(fc::complete_elliptic_integrals(k));
  }
}
BENCHMARK(BM_elliptic_agm);

void BM_elliptic_libstdcxx(benchmark::State& state) {
  double k = 0.6;
  for (auto _ : state) {
    k = k == 0.6 ? 0.61 : 0.6;
    benchmark::DoNotOptimize(std::comp_ellint_1(k));
    benchmark::DoNotOptimize(std::comp_ellint_2(k));
  }
}
BENCHMARK(BM_elliptic_libstdcxx);

void BM_semi_hertz(benchmark::State& state) {
  fc::NormalProblem p = thesis_problem();
  for (int i = 0; i <= 600; ++i) {
    const double y = -0.03 + 0.06 * i / 600;
    p.gap_y.push_back(y);
    p.gap_z.push_back(p.curvature_y * y * y);
  }
  const auto model =
      fc::make_normal_model("semi_hertz", {{"strips", std::to_string(state.range(0))}});
  for (auto _ : state) benchmark::DoNotOptimize(model->solve(p));
}
BENCHMARK(BM_semi_hertz)->Arg(50)->Arg(200);

void run_tangential(benchmark::State& state, const char* name, const fc::ModelOptions& options,
                    bool semi_hertz_patch = false) {
  fc::NormalProblem p = thesis_problem();
  fc::ContactPatch patch;
  if (semi_hertz_patch) {
    for (int i = 0; i <= 600; ++i) {
      const double y = -0.03 + 0.06 * i / 600;
      p.gap_y.push_back(y);
      p.gap_z.push_back(p.curvature_y * y * y);
    }
    patch = fc::make_normal_model("semi_hertz", {{"strips", "20"}})->solve(p).patches.at(0);
  } else {
    patch = fc::make_normal_model("hertz")->solve(p).patches.at(0);
  }
  const auto model = fc::make_tangential_model(name, options);
  fc::TangentialProblem t;
  t.patch = &patch;
  t.friction = 0.3;
  t.body1 = t.body2 = p.body1;
  t.reduction = fc::ReductionFactors{0.72, 0.56, 0.56, 1.0};
  double xi = 1e-3;
  for (auto _ : state) {
    xi = xi > 2e-3 ? 1e-3 : xi * 1.0001;
    t.creepage = fc::Creepage{xi, 0.5 * xi, 0.2};
    benchmark::DoNotOptimize(model->solve(t));
  }
}

void BM_kalker_linear(benchmark::State& s) {
  run_tangential(s, "kalker_linear", {});
}
void BM_linear_saturated(benchmark::State& s) {
  run_tangential(s, "linear_saturated", {});
}
void BM_vermeulen_johnson(benchmark::State& s) {
  run_tangential(s, "vermeulen_johnson", {});
}
void BM_shen_hedrick_elkins(benchmark::State& s) {
  run_tangential(s, "shen_hedrick_elkins", {});
}
void BM_chopaya(benchmark::State& s) {
  run_tangential(s, "chopaya", {});
}
void BM_chopaya_voco_fit(benchmark::State& s) {
  run_tangential(s, "chopaya", {{"coefficients", "voco_fit"}});
}
void BM_polach(benchmark::State& s) {
  run_tangential(s, "polach", {});
}
void BM_fastsim(benchmark::State& s) {
  const std::string n = std::to_string(s.range(0));
  run_tangential(s, "fastsim", {{"mx", n}, {"my", n}});
}
void BM_fastsim_weighted(benchmark::State& s) {
  run_tangential(s, "fastsim", {{"flexibility", "weighted"}});
}
void BM_fastsim_elliptic(benchmark::State& s) {
  const std::string n = std::to_string(s.range(0));
  run_tangential(s, "fastsim", {{"mx", n}, {"my", n}, {"bound", "elliptic"}});
}
void BM_fastsim_semi_hertz_20_strips(benchmark::State& s) {
  run_tangential(s, "fastsim", {}, true);
}
void BM_fastsim_adaptive(benchmark::State& s) {
  const std::string n = std::to_string(s.range(0));
  run_tangential(s, "fastsim", {{"mx", n}, {"my", n}, {"flexibility", "adaptive"}});
}
void BM_fastrip(benchmark::State& s) {
  const std::string n = std::to_string(s.range(0));
  run_tangential(s, "fastrip", {{"mx", n}, {"my", n}});
}
void BM_fastrip_semi_hertz_20_strips(benchmark::State& s) {
  run_tangential(s, "fastrip", {}, true);
}
// mim_table (target <= 0.5 us): the interpolation cost depends on the table's axes, not on its
// node values, so the nodes are solved on a coarse 8-element grid (a few seconds). Arg = spin
// nodes: 29 = the default table, 15 = the earlier spin axis (7 nodes per sign), for comparison.
void BM_mim_table(benchmark::State& s) {
  const int spin_nodes = static_cast<int>(s.range(0));
  fc::MimTableSpec spec = fc::MimTableSpec::default_spec();
  if (spin_nodes == 15) spec.spin = {-9.0, -4.5, -2.6, -1.6, -1.0, -0.6, -0.25, 0.0,
                                     0.25, 0.6,  1.0,  1.6,  2.6,  4.5,  9.0};
  spec.grid = "minor";
  spec.elements = 8;
  spec.threads = 2;
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("ferro_bench_contact_models_table_" + std::to_string(spin_nodes) +
                             ".h5"))
                               .string();
  fc::MimTable::build(spec).write_hdf5(path);
  run_tangential(s, "mim_table", {{"table", path}});
  std::filesystem::remove(path);
}

BENCHMARK(BM_kalker_linear);
BENCHMARK(BM_linear_saturated);
BENCHMARK(BM_vermeulen_johnson);
BENCHMARK(BM_shen_hedrick_elkins);
BENCHMARK(BM_chopaya);
BENCHMARK(BM_chopaya_voco_fit);
BENCHMARK(BM_polach);
BENCHMARK(BM_fastsim)->Arg(10)->Arg(20)->Arg(40);
BENCHMARK(BM_fastsim_weighted);
BENCHMARK(BM_fastsim_elliptic)->Arg(10)->Arg(20);
BENCHMARK(BM_fastsim_semi_hertz_20_strips);
BENCHMARK(BM_fastsim_adaptive)->Arg(10)->Arg(20);
BENCHMARK(BM_fastrip)->Arg(8)->Arg(12)->Arg(16)->Arg(20);
BENCHMARK(BM_fastrip_semi_hertz_20_strips);
BENCHMARK(BM_mim_table)->Arg(15)->Arg(29);

}  // namespace

BENCHMARK_MAIN();
