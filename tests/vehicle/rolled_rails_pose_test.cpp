// The wheel-rail coupling sees the wheelset's pose relative to the rails, and a cross-level
// irregularity rolls the rails about their origin at rail level: a wheelset placed at a given
// pose relative to rolled rails (its axle centre rotated with them, its roll added to theirs)
// must get the same normal loads as at that pose on undisturbed rails. Oracle: rigid-body
// invariance (the contact depends on the relative pose only); a centre offset taken in track
// axes instead of the rails' axes is off by r0 sin(rail roll), 6 mm for 20 mm of cross-level.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ferro/track/irregularity.hpp"
#include "ferro/vehicle/vehicle_model.hpp"
#include "manchester_config.hpp"
#include "model_helpers.hpp"

namespace ferro::vehicle {
namespace {

constexpr double kG = 9.81;
constexpr double kProbeS = 106.0;        // arc length of the leading wheelset [m]
constexpr double kCrossLevel = -0.020;   // defect amplitude, as in the derailment scene [m]
constexpr double kLeadingX = 10.78;      // leading wheelset's rest x in Manchester vehicle 1 [m]

VehicleModelInputs wheelset_on(bool rolled_rails) {
  VehicleModelInputs in;
  in.config = testing::manchester_vehicle1(kG);
  WheelRailSpec& wr = in.config.wheel_rail;
  testing::use_thesis_cone(wr);  // a true cone: the penetrations depend on the lateral shift
  in.geometry = make_geometry_source(wr, FERRO_DATA_DIR);
  in.selection.scope = "wheelset";
  auto irr = std::make_shared<track::IrregularitySum>();
  if (rolled_rails) {
    track::IsolatedDefectSpec d;
    d.channel = track::IrregularityChannel::kCrossLevel;
    d.amplitude = kCrossLevel;
    d.wavelength = 12.0;
    d.start_s = kProbeS - 6.0;  // the probe at the defect's crest (zero slope)
    irr->add(std::make_shared<track::IsolatedDefect>(d));
  }
  track::TrackDesign design;
  design.sections.push_back({track::SectionKind::kStraight, 500.0});
  in.track = std::make_shared<track::Track>(track::Alignment(design), irr);
  in.start_position = kProbeS - kLeadingX;
  in.speed.initial = 10.0;
  return in;
}

std::size_t signal_index(const std::vector<SignalInfo>& info, const std::string& name) {
  for (std::size_t i = 0; i < info.size(); ++i) {
    if (info[i].name == name) return i;
  }
  ADD_FAILURE() << "no signal " << name;
  return 0;
}

TEST(Frames, a_pose_relative_to_rolled_rails_gives_the_flat_rail_contact) {
  // Rounding of the rotation (offsets ~0.5 m, penetrations ~1e-4 m) stays far below this.
  constexpr double kRelTol = 1e-8;
  const VehicleModel flat(wheelset_on(false));
  const VehicleModel rolled(wheelset_on(true));
  const auto iy = static_cast<std::size_t>(flat.state_index("wheelset_1", Dof::y));
  const auto iz = static_cast<std::size_t>(flat.state_index("wheelset_1", Dof::z));
  const auto iroll = static_cast<std::size_t>(flat.state_index("wheelset_1", Dof::roll));

  // A pose relative to the rails with both wheels loaded: the static state on flat rails,
  // shifted 0.2 mm and rolled 0.02 mrad (the cone's 0.1 turns the shift into 0.02 mm of
  // penetration, against ~0.1 mm at rest).
  std::vector<double> x_flat = static_equilibrium(flat);
  x_flat[iy] += 2e-4;
  x_flat[iroll] += 2e-5;

  // The same pose relative to rails rolled by theta about their origin at rail level.
  const double spacing = track::TrackDesign{}.rail_spacing;
  const track::IrregularitySample irr = rolled.inputs().track->at(kProbeS).irregularity;
  ASSERT_NEAR(irr.cross_level, kCrossLevel, 1e-12);
  const double theta = -std::asin(irr.cross_level / spacing);
  double r0 = NAN;  // the wheelset's rest height: its centre over the rails' origin
  for (const auto& b : flat.inputs().config.bodies) {
    if (b.name == "wheelset_1") r0 = b.position.z();
  }
  ASSERT_TRUE(std::isfinite(r0));
  const double off_y = x_flat[iy], off_z = r0 + x_flat[iz];  // centre in the rails' axes
  std::vector<double> x_rolled = x_flat;
  x_rolled[iy] = irr.lateral + std::cos(theta) * off_y - std::sin(theta) * off_z;
  x_rolled[iz] = irr.vertical + std::sin(theta) * off_y + std::cos(theta) * off_z - r0;
  x_rolled[iroll] = x_flat[iroll] + theta;

  const auto info = flat.signal_info();
  std::vector<double> s_flat(info.size()), s_rolled(info.size());
  flat.signals(0.0, x_flat, s_flat);
  rolled.signals(0.0, x_rolled, s_rolled);
  for (const char* side : {"left", "right"}) {
    const std::size_t i = signal_index(info, std::string("wheelset_1.") + side + ".normal_force");
    ASSERT_GT(s_flat[i], 10e3) << side;
    EXPECT_NEAR(s_rolled[i] / s_flat[i], 1.0, kRelTol)
        << side << ": " << s_rolled[i] << " N on rolled rails, " << s_flat[i] << " N on flat";
  }
}

}  // namespace
}  // namespace ferro::vehicle
