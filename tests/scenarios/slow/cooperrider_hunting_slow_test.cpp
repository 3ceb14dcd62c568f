// The Cooperrider wagon's flange-hunting scene keeps a loose tolerance chosen on its error on the
// settled limit cycle (docs/PERFORMANCE.md, "Work-precision"); this checks that its own run from
// the scene's start reaches the cycle of a converged run. Slow: about 6 s at -O3, minutes under
// the sanitizers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/scene.hpp"
#include "ferro/scenarios/work_precision.hpp"

namespace ferro::scenarios {
namespace {

TEST(CooperriderHuntingSlow, flange_hunting_scene_reaches_the_converged_cycle) {
  // The Cooperrider wagon's flange-hunting scene at its own loose tolerance against the same
  // start at rtol 1e-6 (within 1e-6 of rtol 1e-9 on the settled cycle): over
  // t = 5-10 s both must be on the same limit cycle. Measured against rtol 1e-7: amplitudes
  // and frequencies within 0.26 %. kCycleTol allows the 0.31 % the scene states for its error on the cycle with
  // room; landing on the neighbouring cycle (wheelset 3 swinging to 8.2 mm instead of 7.2 mm,
  // as rtol 1e-4 does) is a 3-14 % change.
  constexpr double kCycleTol = 0.01;
  constexpr double kTight = 1e-6;
  const Scene scene = load_scene(std::string(FERRO_SOURCE_DIR) +
                                 "/scenarios/scenes/cooperrider_flange_hunting.yaml");
  const auto system = build_system(scene, scene.simulation.speed, build_resources(scene));
  const std::vector<double> x0 = initial_state(scene, *system);
  const auto info = system->state_info();
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < info.size(); ++i) {
    const std::string& n = info[i].name;
    if (n.rfind("wheelset", 0) == 0 && n.size() > 2 && n.compare(n.size() - 2, 2, ".y") == 0)
      idx.push_back(i);
  }
  ASSERT_EQ(idx.size(), 4u);
  const auto times = vehicle::output_grid(0.0, 10.0, scene.output.interval);
  const auto settled_cycles = [&](const vehicle::IntegratorSettings& s) {
    std::vector<std::vector<double>> x(idx.size());
    std::vector<double> t;
    auto integ = vehicle::make_integrator(s);
    const auto res = integ->integrate(*system, x0, times, [&](double ti, std::span<const double> v) {
      if (ti < 5.0) return true;
      t.push_back(ti);
      for (std::size_t k = 0; k < idx.size(); ++k) x[k].push_back(v[idx[k]]);
      return true;
    });
    EXPECT_EQ(res.status, vehicle::IntegrationResult::Status::kCompleted) << res.message;
    std::vector<CycleStatistics> out;
    for (const auto& xs : x) out.push_back(cycle_statistics(t, xs));
    return out;
  };
  vehicle::IntegratorSettings tight = scene.solver;
  tight.rtol = kTight;
  tight.atol = kTight * 1e-2;
  const auto ref = settled_cycles(tight);
  const auto run = settled_cycles(scene.solver);
  for (std::size_t k = 0; k < idx.size(); ++k) {
    EXPECT_GT(ref[k].amplitude, 7e-3) << info[idx[k]].name << ": a flange-root cycle";
    EXPECT_NEAR(run[k].amplitude / ref[k].amplitude, 1.0, kCycleTol) << info[idx[k]].name;
    EXPECT_NEAR(run[k].frequency / ref[k].frequency, 1.0, kCycleTol) << info[idx[k]].name;
  }
}

}  // namespace
}  // namespace ferro::scenarios
