// Semi-Hertz normal contact in the dynamics (wheel_rail.normal = semi_hertz) on Manchester
// vehicle 1 with tabulated multi-point geometry:
// - on a locally quadratic gap (the thesis' S1002 with a 1/10 conical tread on the R300 crown
//   of UIC60 inclined 1:10) the static equilibrium sits where the Hertz one does: the same
//   wheel loads at the same approach;
// - on S1002 / UIC60 1:40 (the centred non-Hertzian case) each wheel load equals the weight
//   share within 0.1 % on straight track at rest;
// - a source without profiles is refused naming the key and the allowed values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "ferro/contact/geometry/conical_source.hpp"
#include "ferro/contact/normal/hertz.hpp"
#include "ferro/vehicle/vehicle_model.hpp"
#include "manchester_config.hpp"
#include "model_helpers.hpp"

namespace ferro::vehicle {
namespace {

using testing::signal;

using testing::ManchesterMasses;

constexpr double kG = 9.81;
const std::string kData = FERRO_DATA_DIR;

std::shared_ptr<const contact::ContactGeometrySource> table(bool thesis_cone) {
  WheelRailSpec w;
  w.wheel_profile = kData + "/profiles/MBench_S1002_v3.prw";
  w.rail_profile = kData + "/profiles/MBench_UIC60_v3.prr";
  w.geometry = "table";
  w.track_gauge = 1.435;
  w.flange_back_distance = 1.360;
  w.flange_back_y = -0.070;
  w.nominal_radius = 0.46;
  if (thesis_cone) {
    w.rail_inclination = std::atan(0.1) - std::atan(1.0 / 40.0);  // file is 1:40 already
    w.wheel_tread_conicity = 0.1;
    w.wheel_tread_join_y = -0.015;
  }
  return make_geometry_source(w, "");
}

VehicleModelInputs manchester(std::shared_ptr<const contact::ContactGeometrySource> geometry,
                              const std::string& normal, double speed) {
  VehicleModelInputs in;
  in.config = testing::manchester_vehicle1(kG);
  in.config.wheel_rail.normal_model = normal;
  in.geometry = std::move(geometry);
  in.speed.initial = speed;
  return in;
}

}  // namespace

// Hertz and semi-Hertz carry the same static wheel loads; on a quadratic gap semi-Hertz gives
// Hertz's force at every approach, so the equilibrium approach (the wheelsets' height) is the
// same. tests/contact/semi_hertz_contact_test.cpp holds F_n within kForceTol = 0.5 % of Hertz
// there, and F ~ delta^1.5 turns that into an approach difference <= kForceTol / 1.5 of the
// approach.
TEST(SemiHertzVehicle, quadratic_gap_equilibrium_approach_equals_hertz) {
  constexpr double kForceTol = 5e-3;
  const auto geometry = table(true);
  const VehicleModel hertz(manchester(geometry, "hertz", 0.0));
  const VehicleModel semi(manchester(geometry, "semi_hertz", 0.0));
  const auto xh = static_equilibrium(hertz, 0.0);
  const auto xs = static_equilibrium(semi, 0.0);
  // Approach scale: Hertz at one wheel's share on the 1/10 cone (A = cos(gamma) / (2 r0),
  // B = 1 / (2 * 0.3) of the R300 crown).
  const double share = ManchesterMasses::total() * kG / 8.0;
  const double gamma = std::atan(0.1);
  const double estar = contact::combine(contact::Material{82.0e9, 0.28},
                                        contact::Material{82.0e9, 0.28})
                           .contact_modulus;
  const double delta =
      contact::hertz_solve(std::cos(gamma) / (2.0 * 0.46), 1.0 / 0.6, share / std::cos(gamma),
                           estar)
          .approach;
  double worst = 0.0;
  for (int w = 1; w <= 4; ++w) {
    const std::string name = "wheelset_" + std::to_string(w);
    const int iz = hertz.state_index(name, Dof::z);
    ASSERT_GE(iz, 0);
    const double dz = xs[static_cast<std::size_t>(iz)] - xh[static_cast<std::size_t>(iz)];
    EXPECT_LT(std::abs(dz), kForceTol / 1.5 * delta) << name << ": dz = " << dz;
    worst = std::max(worst, std::abs(dz) / delta);
  }
  std::printf("semi-Hertz - Hertz equilibrium height: largest %.2e of the approach %.1f um\n",
              worst, delta * 1e6);
}

// A required property of the product: each wheel load equals the weight share within 0.1 % on
// straight track, here with semi-Hertz on the real S1002 / UIC60 1:40 profiles (the centred
// non-Hertzian case), at rest.
TEST(SemiHertzVehicle, straight_track_wheel_loads_equal_the_weight_share) {
  constexpr double kLoadTol = 1e-3;
  const double share = ManchesterMasses::total() * kG / 8.0;
  const VehicleModel m(manchester(table(false), "semi_hertz", 0.0));
  const auto x = static_equilibrium(m, 0.0);
  std::vector<double> s(m.signal_info().size());
  m.signals(0.0, x, s);
  double worst = 0.0;
  for (int w = 1; w <= 4; ++w) {
    for (const char* side : {"left", "right"}) {
      const std::string name = "wheelset_" + std::to_string(w) + "." + side + ".Q";
      EXPECT_NEAR(signal(m, s, name) / share, 1.0, kLoadTol) << name;
      worst = std::max(worst, std::abs(signal(m, s, name) / share - 1.0));
    }
  }
  std::printf("largest wheel-load error against the weight share %.2e\n", worst);
}

// Semi-Hertz reads the profiles' gap: a source without profiles (the analytic cone; an imported
// one-point table alike) is refused at construction, naming the key and the allowed values.
TEST(SemiHertzVehicle, source_without_profiles_is_refused) {
  contact::ConicalContactParams g;
  g.conicity = 0.1;
  g.contact_half_distance = 0.75;
  g.nominal_radius = 0.46;
  g.curvature_a = 1.0 / (2.0 * 0.46);
  g.curvature_b = 1.0 / (2.0 * 0.3);
  try {
    const VehicleModel m(
        manchester(std::make_shared<contact::ConicalContactSource>(g), "semi_hertz", 0.0));
    ADD_FAILURE() << "semi_hertz accepted with the conical source";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("wheel_rail.normal"), std::string::npos) << what;
    EXPECT_NE(what.find("geometry 'conical'"), std::string::npos) << what;
    EXPECT_NE(what.find("allowed with it: hertz"), std::string::npos) << what;
  }
}

}  // namespace ferro::vehicle
