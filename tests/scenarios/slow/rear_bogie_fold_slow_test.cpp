// The vehicle's nonlinear critical speed is the lowest speed at which any of its wheelsets keeps
// a limit cycle. Thesis setup (Manchester vehicle 1, 1/10 cone, scenarios/scenes/
// thesis_critical_speed.yaml) with a weaker rear bogie: its primary longitudinal stiffness
// doubled (a stiffer primary yaw lowers this vehicle's critical speed, docs/VALIDATION.md, "The
// cone's rolling radius"), so that the rear bogie hunts at speeds where the front one, on its
// own, would come to rest. The branch followed down from the same cycles is judged three times:
//  - on every wheelset (the verb): fold F_all, cycle held by a rear wheelset;
//  - on the front bogie's wheelsets alone: fold F_front;
//  - on the rear bogie's wheelsets alone: fold F_rear.
// The verb's critical speed must be the rear bogie's (F_all = F_rear within the bracket) and not
// above the front bogie's, and at F_all the front wheelsets must carry only the motion the rear
// bogie's cycle forces on them through the car body (per-wheelset amplitude table): 2.7-2.9 % of
// the rear cycle on this vehicle, against a self-excited cycle of the order of the rear one's.
// That forced motion is an oscillation the front bogie sees down to F_all, so its own fold
// coincides with the vehicle's here: the vehicle-wide decision is what names the rear bogie.
// The weakened vehicle's fold must lie below the unmodified vehicle's by more than the bracket.
// Slow: four branches, about 2 CPU-min.
#include <gtest/gtest.h>

#include <cstdio>

#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/scene_analysis.hpp"
#include "ferro/scenarios/model_factory.hpp"

namespace ferro::scenarios::analysis {
namespace {

Scene thesis_scene() {
  return load_scene(std::string(FERRO_SOURCE_DIR) + "/scenarios/scenes/thesis_critical_speed.yaml");
}

Scene weak_rear_bogie() {
  Scene s = thesis_scene();
  int changed = 0;
  for (auto& e : s.model.vehicle.elements) {
    if (e.name.rfind("primary.wheelset_3.", 0) == 0 || e.name.rfind("primary.wheelset_4.", 0) == 0) {
      e.stiffness.x() *= 2.0;
      ++changed;
    }
  }
  EXPECT_EQ(changed, 4) << "the rear bogie's four axlebox springs";
  return s;
}

TEST(RearBogieFold, the_vehicle_fold_is_the_rear_bogies) {
  const Scene s = weak_rear_bogie();
  const auto family = speed_family(s);
  BranchOptions o;
  o.speed_start = 80.0;
  o.speed_stop = 40.0;
  o.speed_step = 5.0;
  o.bracket = 0.25;
  o.settle.solver = s.solver;
  o.settle.segment = 10.0;
  o.settle.max_time = 60.0;
  const auto probe = family(o.speed_start);
  const auto lateral = lateral_states(*probe);
  ASSERT_EQ(lateral.index.size(), 4u);
  const auto x0 = disturbed_state(s, *probe, 6e-3);
  const auto fold = [&](std::vector<std::size_t> observed) {
    o.settle.observed = std::move(observed);
    return follow_periodic_branch(family, x0, o);
  };
  const auto all = fold(lateral.index);
  const auto front = fold({lateral.index[0], lateral.index[1]});
  const auto rear = fold({lateral.index[2], lateral.index[3]});
  ASSERT_TRUE(all.fold_found && front.fold_found && rear.fold_found);
  std::printf("[ figures  ] fold: vehicle [%.3f, %.3f] (held by %s), front bogie [%.3f, %.3f], "
              "rear bogie [%.3f, %.3f] m/s\n",
              all.bracket_low, all.bracket_high, lateral.name[all.holder].c_str(),
              front.bracket_low, front.bracket_high, rear.bracket_low, rear.bracket_high);
  EXPECT_GE(all.holder, 2u) << "a rear wheelset holds the cycle";
  // The rear bogie's fold, to the bracket (the two branches bisect the same interval only while
  // they agree; they may end a bracket apart).
  EXPECT_NEAR(all.bracket_high, rear.bracket_high, o.bracket + 1e-9);
  // Not above the front bogie's fold.
  EXPECT_LE(all.bracket_high, front.bracket_high + 1e-9);
  // Below the fold of the vehicle whose rear bogie is the front one's twin: the weakened rear
  // bogie, not the front one, sets the speed.
  {
    const Scene base = thesis_scene();
    const auto base_family = speed_family(base);
    const auto base_probe = base_family(o.speed_start);
    o.settle.observed = lateral.index;
    const auto twin = follow_periodic_branch(base_family, disturbed_state(base, *base_probe, 6e-3), o);
    ASSERT_TRUE(twin.fold_found);
    std::printf("[ figures  ] fold of the unmodified vehicle [%.3f, %.3f] m/s\n", twin.bracket_low,
                twin.bracket_high);
    EXPECT_LT(all.bracket_high, twin.bracket_low - o.bracket);
  }
  // At the vehicle's lowest cycle the front wheelsets move only as the rear cycle forces them.
  // kForcedShare: 5 %, above the 2.7-2.9 % measured, far below a cycle of the front bogie's own.
  constexpr double kForcedShare = 0.05;
  for (const auto& p : all.points) {
    if (p.speed != *all.lowest_sustained || !sustained(p.run.outcome)) continue;
    std::printf("[ figures  ] at %.3f m/s: %.4f %.4f %.4f %.4f mm\n", p.speed,
                p.run.amplitude[0] * 1e3, p.run.amplitude[1] * 1e3, p.run.amplitude[2] * 1e3,
                p.run.amplitude[3] * 1e3);
    EXPECT_LT(p.run.amplitude[0], kForcedShare * p.run.amplitude[p.run.holder]);
    EXPECT_LT(p.run.amplitude[1], kForcedShare * p.run.amplitude[p.run.holder]);
  }
}

}  // namespace
}  // namespace ferro::scenarios::analysis
