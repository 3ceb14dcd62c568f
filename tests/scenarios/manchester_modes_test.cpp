// Mode classes on Manchester vehicle 1 on its real profiles (S1002 / UIC60 1:40, straight
// track, scenarios/scenes/manchester_critical_speed.yaml). On the rigid track the least damped
// mode of the vehicle below its Hopf speed is a wheelset bouncing on the Hertz contact (about
// 200 Hz, damping ratio 0.002), which could hide the hunting mode:
//  - at every speed of the sweep the hunting mode is found, followed from one speed to the next
//    by its shape, lateral, oscillating at a few Hz, and its damping changes sign at the Hopf
//    speed the bisection finds (two procedures, one answer);
//  - the contact modes are listed apart, and their frequencies are those of one wheelset on its
//    contact stiffness, bouncing and rolling: f = sqrt(k/m) / 2 pi with k the stiffness felt by
//    the wheelset's own vertical (roll) displacement at the equilibrium, by finite differences
//    of the right-hand side, and m its mass (roll inertia).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "ferro/scenarios/analysis/scene_analysis.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/run.hpp"
#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::scenarios {
namespace {

using vehicle::DofGroup;
using vehicle::ModeClass;

/// The scene on the rigid track (the scene's own, flexible, track: the last test).
Scene manchester() {
  Scene s = load_scene(std::string(FERRO_SOURCE_DIR) +
                       "/scenarios/scenes/manchester_critical_speed.yaml");
  s.track.structure.kind = track::TrackStructureSpec::Kind::rigid;
  s.eigen.speed_min = 20.0;
  s.eigen.speed_max = 120.0;
  s.eigen.points = 21;
  return s;
}

std::size_t state(const vehicle::OdeSystem& sys, const std::string& name) {
  const auto info = sys.state_info();
  for (std::size_t i = 0; i < info.size(); ++i)
    if (info[i].name == name) return i;
  ADD_FAILURE() << "no state " << name;
  return 0;
}

/// sqrt(k/m)/(2 pi) of the wheelset's DOF `dof` alone: k = -m d(acceleration)/d(displacement).
double one_dof_frequency(const vehicle::OdeSystem& sys, const std::vector<double>& x_eq,
                         const std::string& dof) {
  const std::size_t q = state(sys, "wheelset_1." + dof);
  const std::size_t a = state(sys, "wheelset_1." + dof + "_dot");
  constexpr double kStep = 1e-8;  // [m, rad], far inside the linear range of a 60 um approach
  std::vector<double> x = x_eq, xd_plus(x.size()), xd_minus(x.size());
  x[q] = x_eq[q] + kStep;
  sys.rhs(0.0, x, xd_plus);
  x[q] = x_eq[q] - kStep;
  sys.rhs(0.0, x, xd_minus);
  const double k_over_m = -(xd_plus[a] - xd_minus[a]) / (2.0 * kStep);
  return std::sqrt(k_over_m) / (2.0 * std::numbers::pi);
}

TEST(ManchesterModes, hunting_mode_at_every_speed_and_contact_modes_apart) {
  const Scene s = manchester();
  const auto report = run_eigen(s);
  ASSERT_TRUE(report.critical_speed.has_value());
  const double hopf = *report.critical_speed;
  std::printf("[ figures  ] Hopf speed %.4f m/s\n", hopf);
  for (std::size_t i = 0; i < report.sweep.size(); ++i) {
    const auto& p = report.sweep[i];
    const auto& h = p.hunting;
    const auto& c = p.of(ModeClass::contact);
    std::printf("[ figures  ] V %6.1f: hunting %+.5f %.3f Hz (%s; followed %.3f); contact %+.5f "
                "%.2f Hz\n",
                p.speed, h.damping_ratio, h.frequency_hz, h.shape().c_str(),
                p.hunting_correlation, c.damping_ratio, c.frequency_hz);
    EXPECT_EQ(h.kind, ModeClass::hunting) << p.speed;
    // Followed by its shape from the speed above (5 m/s apart), never re-identified.
    EXPECT_GE(p.hunting_correlation, vehicle::kShapeTracked) << p.speed;
    // A lateral oscillation of a few Hz: kinematic wavelengths of 10-50 m at these speeds.
    EXPECT_GT(h.frequency_hz, p.speed / 50.0) << p.speed;
    EXPECT_LT(h.frequency_hz, p.speed / 10.0) << p.speed;
    double lateral = 0.0;
    for (const auto g : {DofGroup::wheelset_lateral_yaw, DofGroup::frame_lateral,
                         DofGroup::carbody_lateral})
      lateral += h.participation[static_cast<std::size_t>(g)];
    EXPECT_GT(lateral, 0.9) << p.speed;
    // Its damping changes sign at the bisected Hopf speed.
    if (p.speed < hopf - 1e-6) {
      EXPECT_GT(h.damping_ratio, 0.0) << p.speed;
    }
    if (p.speed > hopf + 1e-6) {
      EXPECT_LT(h.damping_ratio, 0.0) << p.speed;
    }
    // The contact modes apart: on the wheelsets' vertical/roll, and less damped than the
    // hunting mode up to close to the Hopf speed (the least damped mode of the vehicle there).
    EXPECT_GT(c.participation[static_cast<std::size_t>(DofGroup::wheelset_vertical_roll)], 0.9)
        << p.speed;
    if (p.speed < 0.9 * hopf) {
      EXPECT_LT(c.damping_ratio, h.damping_ratio) << p.speed;
      EXPECT_EQ(p.least_damped.kind, ModeClass::contact) << p.speed;
    }
  }
  // The contact modes' frequencies: a wheelset bouncing and rolling on its contact stiffness.
  const auto family = analysis::with_mode_shapes(s, linearisation_family(s));
  const auto lin = family(60.0);
  const double f_bounce = one_dof_frequency(*lin.system, lin.x_eq, "z");
  const double f_roll = one_dof_frequency(*lin.system, lin.x_eq, "roll");
  const auto modes = vehicle::linear_modes(*lin.system, 0.0, lin.x_eq, lin.shapes);
  int bounce = 0, roll = 0;
  // The four wheelsets' modes couple only through the soft primary suspension and the frames:
  // within 2 % of the single-wheelset frequency.
  constexpr double kOneDofTol = 0.02;
  for (const auto& m : modes) {
    if (m.kind != ModeClass::contact || m.eigenvalue.imag() <= 0.0) continue;
    if (std::abs(m.frequency_hz / f_bounce - 1.0) < kOneDofTol) ++bounce;
    if (std::abs(m.frequency_hz / f_roll - 1.0) < kOneDofTol) ++roll;
  }
  std::printf("[ figures  ] one wheelset on its contact: bounce %.2f Hz, roll %.2f Hz; contact "
              "modes there: %d, %d\n",
              f_bounce, f_roll, bounce, roll);
  EXPECT_EQ(bounce, 4);
  EXPECT_EQ(roll, 4);
}

// On the co-running flexible track (track::TrackStructureSpec discrete: a rail body per side and
// a sleeper under every wheelset) the model gains 36 track positions (rails on their pads,
// sleepers on the ballast). Their modes must be classed as track modes and never taken for
// hunting, and a hunting mode must still be found beside them: lateral, carried by the
// wheelsets' lateral/yaw motion with the frames, at a few Hz.
TEST(ManchesterModes, track_modes_are_their_own_class_on_a_flexible_track) {
  const Scene s = manchester();
  const double v = 80.0;
  const auto resources = build_resources(s);
  vehicle::VehicleModelInputs in;
  in.config = s.model.vehicle;
  in.selection = s.model.selection;
  in.track = resources.track;
  in.geometry = resources.geometry;
  in.speed.initial = v;
  in.track_structure.kind = track::TrackStructureSpec::Kind::discrete;
  const vehicle::VehicleModel model(std::move(in));
  const auto x_eq = vehicle::static_equilibrium(model, 0.0);
  const auto shapes = analysis::mode_shapes(s, model);
  const auto modes = vehicle::linear_modes(model, 0.0, x_eq, shapes);
  int track_modes = 0;
  const vehicle::Mode* hunting = nullptr;
  const vehicle::Mode* least_damped_track = nullptr;
  for (const auto& m : modes) {
    const double track_share = m.participation[static_cast<std::size_t>(DofGroup::track)];
    if (track_share >= vehicle::kDominantShare) {
      EXPECT_EQ(m.kind, ModeClass::track) << m.frequency_hz << " Hz";
    }
    if (m.kind == ModeClass::track) {
      ++track_modes;
      if (least_damped_track == nullptr) least_damped_track = &m;
    }
    if (hunting == nullptr && m.kind == ModeClass::hunting && m.frequency_hz > 1.0)
      hunting = &m;
  }
  ASSERT_NE(hunting, nullptr);
  ASSERT_NE(least_damped_track, nullptr);
  std::printf("[ figures  ] V %.0f on the flexible track: least damped hunting mode %+.5f %.3f Hz "
              "(%s); %d track modes, the least damped %+.5f %.1f Hz (%s)\n",
              v, hunting->damping_ratio, hunting->frequency_hz, hunting->shape().c_str(),
              track_modes, least_damped_track->damping_ratio, least_damped_track->frequency_hz,
              least_damped_track->shape().c_str());
  // 4 wheelsets x 9 track positions: at least 36 modes (a complex pair counts twice).
  EXPECT_GE(track_modes, 36);
  EXPECT_LT(hunting->frequency_hz, 10.0);
  EXPECT_GT(hunting->participation[static_cast<std::size_t>(DofGroup::wheelset_lateral_yaw)], 0.3);
  EXPECT_LT(hunting->participation[static_cast<std::size_t>(DofGroup::track)], 0.1);
}

}  // namespace
}  // namespace ferro::scenarios
