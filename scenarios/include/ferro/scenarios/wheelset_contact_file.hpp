#pragma once
// A wheelset-contact study file (the Manchester contact benchmark format): a pair file that
// also carries wheelset.vertical_load_per_wheel, wheelset.forward_speed,
// material.{shear_modulus, poisson}, friction.mu, discretisation_hint.{dx, dy} and cases
// ({id, y, roll, yaw, pitch_rate}); the solver is contact/geometry/wheelset_contact.hpp.
//
// Units: the file is in mm, N, rad, s; converted to SI at load.

#include <string>
#include <vector>

#include "ferro/contact/geometry/wheelset_contact.hpp"
#include "ferro/scenarios/pair_file.hpp"

namespace ferro::scenarios {

/// A study file as read: the pair, what every case shares, the cases. SI.
struct WheelsetContactInput {
  PairFile pair;
  contact::WheelsetContactSpec spec;
  std::vector<contact::WheelsetCase> cases;
};

/// Reads a study file; YamlInputError names file, line and key.
[[nodiscard]] WheelsetContactInput load_wheelset_contact_file(const std::string& path);

}  // namespace ferro::scenarios
