// `ferrodyn bench contact`: the case set has the breadth the accuracy figures need, and a quick
// run orders the models as the theory says and keeps every saturating model within Coulomb.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>

#include "ferro/scenarios/contact_bench.hpp"

namespace fs = ferro::scenarios;

// a/b from 0.2 to 5, normalised spin 0 to 2, seven creepage directions, magnitudes from
// micro-slip (0.2) to full slip (4), pure spin.
TEST(contact_bench, case_set_breadth) {
  const auto cases = fs::contact_bench_cases();
  EXPECT_EQ(cases.size(), 855u);
  std::set<std::string> kinds;
  std::set<double> spins, ratios;
  std::set<long> directions;
  double smallest = 1e9, largest = 0.0;
  for (const auto& c : cases) {
    kinds.insert(c.kind);
    spins.insert(c.spin);
    ratios.insert(c.ratio);
    const double m = std::hypot(c.xi_x, c.xi_y);
    if (m > 0.0) {
      directions.insert(std::lround(std::atan2(c.xi_y, c.xi_x) * 180.0 / std::numbers::pi));
      smallest = std::min(smallest, m);
      largest = std::max(largest, m);
    }
  }
  EXPECT_EQ(*ratios.begin(), 0.2);
  EXPECT_EQ(*ratios.rbegin(), 5.0);
  EXPECT_EQ(*spins.rbegin(), 2.0);
  EXPECT_EQ(directions.size(), 7u);
  for (const char* k : {"x", "y", "spin", "x+y", "y+spin", "x+y+spin"}) EXPECT_TRUE(kinds.count(k));
  EXPECT_LE(smallest, 0.2);  // micro-slip (linear range)
  EXPECT_GE(largest, 4.0);   // full slip
}

// Quick run (15 cases, reference MIM 12 / 24 over the patch with Richardson):
// - MIM 25 x 25 over the patch within kTolCoarseMim = 0.02 mu F_n of the reference (second-order
//   spin term; the reference itself is coarse here);
// - FASTSIM, the simplified theory, within its published ~0.2 mu F_n worst case;
// - the linear theory without saturation exceeds mu F_n; every other model stays at or below
//   mu F_n within kCoulombSlack = 1e-3 (Coulomb bound; the slack is MIM's active-set tolerance,
//   stick elements may exceed mu p by a fraction of it);
// - every row has a positive time.
TEST(contact_bench, quick_run_orders_models) {
  constexpr double kTolCoarseMim = 0.02;
  constexpr double kCoulombSlack = 1e-3;
  fs::ContactBenchOptions o;
  o.quick = true;
  o.min_time_s = 0.01;
  const fs::ContactBenchResult r = fs::run_contact_bench(o);
  EXPECT_EQ(r.cases.size(), 15u);
  const auto row = [&](const std::string& label) {
    for (const auto& x : r.rows)
      if (x.label == label) return x;
    ADD_FAILURE() << "no row " << label;
    return fs::ContactBenchRow{};
  };
  EXPECT_LT(row("mim 25 patch").max_error, kTolCoarseMim);
  EXPECT_LT(row("fastsim 20x20").max_error, 0.2);
  EXPECT_LT(row("fastsim 20x20 adaptive").max_error, 0.2);
  EXPECT_GT(row("kalker_linear").max_error, 1.0);
  for (const auto& x : r.rows) {
    EXPECT_GT(x.us_per_eval, 0.0) << x.label;
    if (x.label != "kalker_linear") EXPECT_LE(x.max_force, 1.0 + kCoulombSlack) << x.label;
  }
}
