#pragma once
// Test support: the Manchester contact benchmark wheel-rail pair (S1002 wheel on UIC60
// rail inclined 1:40 in the profile points, gauge 1435 mm, flange back 1360 mm at -70 mm in
// wheel-profile coordinates, nominal radius 460 mm), from the profiles shipped in data/.
#include <memory>
#include <string>

#include "ferro/contact/geometry/profile.hpp"
#include "ferro/contact/geometry/wheel_rail_geometry.hpp"

namespace ferro::test {

inline std::shared_ptr<const contact::WheelRailPair> a22_pair() {
  const std::string data = FERRO_DATA_DIR;
  contact::WheelRailPairParams p;
  p.track_gauge = 1.435;
  p.flange_back_distance = 1.360;
  p.flange_back_y = -0.070;
  p.nominal_radius = 0.460;
  return std::make_shared<const contact::WheelRailPair>(
      contact::read_simpack_profile(data + "/profiles/MBench_S1002_v3.prw"),
      contact::read_simpack_profile(data + "/profiles/MBench_UIC60_v3.prr"), p);
}

}  // namespace ferro::test
