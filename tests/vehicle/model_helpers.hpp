#pragma once
// Helpers shared by the vehicle tests: a model's derived signal by name, and the analytic 1/10
// cone the tests run on when they need no profiles.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ferro/vehicle/vehicle_model.hpp"

namespace ferro::vehicle::testing {

/// The value of signal `name` among `values` (m.signals() order); a test failure and NaN when
/// the model has no such signal.
inline double signal(const VehicleModel& m, const std::vector<double>& values,
                     const std::string& name) {
  const auto info = m.signal_info();
  for (std::size_t i = 0; i < info.size(); ++i) {
    if (info[i].name == name) return values[i];
  }
  ADD_FAILURE() << "no signal " << name;
  return NAN;
}

/// Geometry "conical": a 1/10 cone of 0.46 m nominal radius touching 0.75 m from the track
/// centre, relative curvatures those of that wheel (A = 1 / (2 r0)) on the R300 rail crown
/// (B = 1 / (2 * 0.3)).
inline void use_thesis_cone(WheelRailSpec& wr) {
  wr.geometry = "conical";
  wr.nominal_radius = 0.46;
  wr.conicity = 0.1;
  wr.contact_half_distance = 0.75;
  wr.conical_curvature_a = 1.0 / (2.0 * 0.46);
  wr.conical_curvature_b = 1.0 / (2.0 * 0.3);
}

}  // namespace ferro::vehicle::testing
