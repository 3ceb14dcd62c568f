#pragma once
// Test support: the Manchester contact benchmark as a full contact case (the shipped
// data/manchester_contact_benchmark_a22.yaml), our solutions cached per set of cases, and the
// comparison with the published reference solution of the CONTACT program
// (tests/data/manchester_a22_contact_reference.csv).
//
// Reference conventions (see the CSV header): forces on the rail in a frame with y to the right
// and n into the rail, creepages as rail-relative slip, left-wheel profile coordinates mirrored.
// Ours: forces by the rail on the wheel in (t1, t2 = n x t1, n out of the rail), creepages as
// wheel-relative slip. With s = +1 on the right wheel and -1 on the left: y_r = s Y_r,
// y_w = s Y_w, contact angle = -s delta; xi_x = -cksi, xi_y = ceta, phi = cphi; F_x = -fx,
// F_y = fs, M_z = mn.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "ferro/io/csv.hpp"
#include "ferro/scenarios/pair_file.hpp"
#include "ferro/scenarios/wheelset_contact_file.hpp"

namespace ferro::test {

inline const scenarios::WheelsetContactInput& a22_input() {
  static const scenarios::WheelsetContactInput in = scenarios::load_wheelset_contact_file(
      std::string(FERRO_DATA_DIR) + "/manchester_contact_benchmark_a22.yaml");
  return in;
}

inline const contact::WheelRailPair& a22_pair_model() {
  static const contact::WheelRailPair pair = scenarios::make_wheel_rail_pair(a22_input().pair);
  return pair;
}

/// Our solution of the given case ids (every case when empty), computed once per set.
inline const std::vector<contact::WheelsetContact>& a22_results(std::vector<int> ids = {}) {
  static std::map<std::vector<int>, std::vector<contact::WheelsetContact>> cache;
  std::sort(ids.begin(), ids.end());
  auto it = cache.find(ids);
  if (it != cache.end()) return it->second;
  scenarios::WheelsetContactInput in = a22_input();
  if (!ids.empty()) {
    std::vector<contact::WheelsetCase> kept;
    for (const auto& c : in.cases) {
      if (std::binary_search(ids.begin(), ids.end(), c.id)) kept.push_back(c);
    }
    in.cases = kept;
  }
  return cache[ids] = contact::solve_wheelset_contacts(a22_pair_model(), in.spec, in.cases);
}

/// One row of the reference solution.
struct A22Reference {
  int id = 0;
  bool right = false;
  double z_ws = 0, xcp = 0, ycp_rail = 0, ycp_wheel = 0, deltcp = 0;
  double cksi = 0, ceta = 0, cphi = 0, fn = 0, fx = 0, fs = 0, mn = 0, approach = 0, pmax = 0;
};

inline const std::vector<A22Reference>& a22_reference() {
  static const std::vector<A22Reference> rows = [] {
    const std::string path =
        std::string(FERRO_SOURCE_DIR) + "/tests/data/manchester_a22_contact_reference.csv";
    std::ifstream f(path);
    io::CsvReader csv(f, path);
    std::vector<A22Reference> out;
    std::vector<std::string> cells;
    const auto& h = csv.header();
    auto col = [&](const std::string& name) {
      return static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin());
    };
    while (csv.next(cells)) {
      A22Reference r;
      r.id = static_cast<int>(csv.number(cells, col("case")));
      r.right = cells[col("wheel")] == "right";
      r.z_ws = csv.number(cells, col("z_ws_mm")) * 1e-3;
      r.xcp = csv.number(cells, col("xcp_tr_mm")) * 1e-3;
      r.ycp_rail = csv.number(cells, col("ycp_rail_mm")) * 1e-3;
      r.ycp_wheel = csv.number(cells, col("ycp_wheel_mm")) * 1e-3;
      r.deltcp = csv.number(cells, col("deltcp_rad"));
      r.cksi = csv.number(cells, col("cksi"));
      r.ceta = csv.number(cells, col("ceta"));
      r.cphi = csv.number(cells, col("cphi_per_mm")) * 1e3;
      r.fn = csv.number(cells, col("fn_n"));
      r.fx = csv.number(cells, col("fx_n"));
      r.fs = csv.number(cells, col("fs_n"));
      r.mn = csv.number(cells, col("mn_nmm")) * 1e-3;
      r.approach = csv.number(cells, col("approach_mm")) * 1e-3;
      r.pmax = csv.number(cells, col("pmax_mpa")) * 1e6;
      out.push_back(r);
    }
    return out;
  }();
  return rows;
}

inline const A22Reference& a22_reference_row(int id, contact::Side side) {
  for (const A22Reference& r : a22_reference()) {
    if (r.id == id && r.right == (side == contact::Side::right)) return r;
  }
  throw std::runtime_error("no reference row");
}

// Tolerances against the reference solution (an independent boundary-element code on the same
// 0.2 mm grid; differences come from the profile interpolation, the plane of the sampled gap and
// the element placement). Measured worst cases are in docs/VALIDATION.md.
/// Contact reference point on rail and wheel [m] (the benchmark comparison's requirement).
inline constexpr double kPositionTol = 0.5e-3;
/// Axle height [m]: a tenth of the smallest approach (20 um); on the flange the load changes by
/// only 0.16 N per nm of height, 6 times less than on the tread.
inline constexpr double kHeightTol = 5.0e-6;
/// Contact angle [rad]: the rail inclination changes by ds / R over a reference-point shift ds;
/// 0.1 mm on the R13 gauge corner gives 8 mrad (flange), on the R300 crown 0.3 mrad (tread; 1
/// mrad allowed for the lateral weighting in the contact plane instead of across the track).
inline constexpr double kAngleTolFlange = 8.0e-3, kAngleTolTread = 1.0e-3;
/// Normal force, relative: 1 % (the same half-space problem on the same grid).
inline constexpr double kNormalForceTol = 0.01;
/// Approach and peak pressure, relative: 5 % (both follow the element placement on the 0.2 mm
/// grid; the peak is one element's value).
inline constexpr double kApproachTol = 0.05, kPeakPressureTol = 0.05;
/// Creepages: 2 % of the largest creepage of the case plus 2e-5 (the rolling-speed
/// normalisation differs: V here, the local rolling speed there, up to 1 %).
inline constexpr double kCreepageRel = 0.02, kCreepageAbs = 2.0e-5;
/// Spin [1/m]: 2 % plus 0.02 1/m (the same normalisation).
inline constexpr double kSpinRel = 0.02, kSpinAbs = 0.02;
/// Creep forces, as a fraction of mu F_n: 3 % (the traction bound is reached on most of these
/// patches, so the force direction follows the creepages above).
inline constexpr double kCreepForceTol = 0.03;

inline void expect_matches_reference(int id, const contact::WheelContact& w) {
  const A22Reference& ref = a22_reference_row(id, w.side);
  const double s = w.side == contact::Side::right ? 1.0 : -1.0;
  const std::string where =
      "case " + std::to_string(id) + (w.side == contact::Side::right ? " right" : " left");
  ASSERT_EQ(w.patches.size(), 1u) << where;  // the reference has one patch on every wheel
  const contact::PatchContact& p = w.patches[0];
  EXPECT_NEAR(p.rail_y, s * ref.ycp_rail, kPositionTol) << where;
  EXPECT_NEAR(p.wheel_y, s * ref.ycp_wheel, kPositionTol) << where;
  EXPECT_NEAR(w.vertical, ref.z_ws, kHeightTol) << where;
  const bool flange = std::abs(ref.deltcp) > 0.2;
  EXPECT_NEAR(p.contact_angle, -s * ref.deltcp, flange ? kAngleTolFlange : kAngleTolTread) << where;
  EXPECT_NEAR(p.normal_force / ref.fn, 1.0, kNormalForceTol) << where;
  EXPECT_NEAR(p.approach / ref.approach, 1.0, kApproachTol) << where;
  EXPECT_NEAR(p.peak_pressure / ref.pmax, 1.0, kPeakPressureTol) << where;
  const double cmax = std::max({std::abs(ref.cksi), std::abs(ref.ceta)});
  const double ctol = kCreepageRel * cmax + kCreepageAbs;
  EXPECT_NEAR(p.creepage.longitudinal, -ref.cksi, ctol) << where;
  EXPECT_NEAR(p.creepage.lateral, ref.ceta, ctol) << where;
  EXPECT_NEAR(p.creepage.spin, ref.cphi, kSpinRel * std::abs(ref.cphi) + kSpinAbs) << where;
  const double ftol = kCreepForceTol * a22_input().spec.friction * ref.fn;
  EXPECT_NEAR(p.force_x, -ref.fx, ftol) << where;
  EXPECT_NEAR(p.force_y, ref.fs, ftol) << where;
}

}  // namespace ferro::test
