// `ferrodyn bench contact`: the case set has the breadth the accuracy figures need, and a quick
// run orders the models as the theory says and keeps every saturating model within Coulomb.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "ferro/contact/tangential_model.hpp"
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

// FaStrip against the converged-MIM reference of the whole case set
// (tests/data/contact_bench_reference.csv: MIM 40 x 40 and 80 x 80 over the patch, Richardson):
// mean |F_t - F_t,ref| <= kGoalMean = 0.02 mu F_n (the accuracy goal for the fast models; the
// classic FASTSIM 20 x 20 is 0.036 on this set), 95th percentile <= kGoalP95 = 0.05, never above
// Coulomb (kTolCoulomb = 1e-12 relative, round-off).
TEST(contact_bench, fastrip_against_converged_mim) {
  constexpr double kGoalMean = 0.02, kGoalP95 = 0.05, kTolCoulomb = 1e-12;
  const auto cases = fs::contact_bench_cases();
  std::vector<fs::ContactBenchReference> ref;
  int elements = 0;
  ASSERT_TRUE(fs::read_contact_bench_reference(
      std::string(FERRO_SOURCE_DIR) + "/tests/data/contact_bench_reference.csv", cases, ref,
      elements));
  const auto model = ferro::contact::make_tangential_model("fastrip");
  std::vector<double> err;
  double sum = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const ferro::contact::ContactPatch patch = fs::contact_bench_patch(cases[k]);
    const ferro::contact::TangentialProblem p = fs::contact_bench_problem(cases[k], patch);
    const ferro::contact::TangentialSolution f = model->solve(p);
    const double s = p.friction * patch.normal_force;
    const double e = std::hypot(f.force_x / s - ref[k].fx, f.force_y / s - ref[k].fy);
    err.push_back(e);
    sum += e;
    largest = std::max(largest, std::hypot(f.force_x, f.force_y) / s);
  }
  std::sort(err.begin(), err.end());
  const double mean = sum / static_cast<double>(err.size());
  const double p95 = err[static_cast<std::size_t>(std::ceil(0.95 * err.size())) - 1];
  std::printf("fastrip 12 x 12 against converged MIM: mean %.4f, p95 %.4f, max %.4f mu F_n\n",
              mean, p95, err.back());
  EXPECT_LE(mean, kGoalMean);
  EXPECT_LE(p95, kGoalP95);
  EXPECT_LE(largest, 1.0 + kTolCoulomb);
}
