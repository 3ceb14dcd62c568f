// `ferrodyn bench contact`: the case set reaches from micro-slip to full slip, and a quick run
// orders the models as the theory says and keeps every saturating model within Coulomb.
#include "ferro/scenarios/contact_bench.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ferro/contact/tangential/tangential_model.hpp"

namespace fs = ferro::scenarios;

// The case set reaches both ends of the creep curve at every a/b, for longitudinal and lateral
// creepage: its smallest magnitude (0.2 in units where Kalker's linear force is mu F_n) lies in
// the linear, micro-slip range and its largest at full slip. Oracle: converged MIM (12 / 24
// elements over the patch, Richardson) against Kalker's linear theory, |F| = m mu F_n, and
// against Coulomb saturation, |F| = mu F_n.
TEST(contact_bench, case_set_spans_micro_slip_to_full_slip) {
  // The creep curve is concave: below the linear force, by m / 3 relative at small m for
  // elliptic patches (Johnson & Vermeulen 1964: 1 - (1 - m / 3)^3 = m (1 - m / 3 + ...)); up to
  // 10 % below counts as the linear range.
  constexpr double kLinearRange = 0.10;
  // Above the linear force or mu F_n only by the coarse reference's discretisation error.
  constexpr double kReferenceError = 0.02;
  // Full slip: the whole patch slides, |F| = mu F_n to the reference's accuracy.
  constexpr double kSaturated = 0.98;
  // Per a/b and axis (positive pure x or pure y creepage, no spin): the smallest and the
  // largest magnitude of the set.
  std::map<std::pair<double, bool>, std::pair<fs::ContactBenchCase, fs::ContactBenchCase>> ends;
  for (const auto& c : fs::contact_bench_cases()) {
    const bool along_x = c.xi_x > 0.0 && c.xi_y == 0.0, along_y = c.xi_y > 0.0 && c.xi_x == 0.0;
    if (c.spin != 0.0 || !(along_x || along_y)) continue;
    const auto key = std::make_pair(c.ratio, along_x);
    const double m = c.xi_x + c.xi_y;
    auto it = ends.find(key);
    if (it == ends.end()) {
      ends.emplace(key, std::make_pair(c, c));
      continue;
    }
    if (m < it->second.first.xi_x + it->second.first.xi_y) it->second.first = c;
    if (m > it->second.second.xi_x + it->second.second.xi_y) it->second.second = c;
  }
  ASSERT_FALSE(ends.empty());
  std::vector<fs::ContactBenchCase> cases;
  for (const auto& [key, pair] : ends) {
    cases.push_back(pair.first);
    cases.push_back(pair.second);
  }
  const auto ref = fs::contact_bench_reference(cases, 12, 1);
  for (std::size_t i = 0; i < cases.size(); i += 2) {
    const double m_small = cases[i].xi_x + cases[i].xi_y;
    const double f_small = std::hypot(ref[i].fx, ref[i].fy);
    const double f_large = std::hypot(ref[i + 1].fx, ref[i + 1].fy);
    const std::string where = "a/b = " + std::to_string(cases[i].ratio) + ", " + cases[i].kind;
    EXPECT_GE(f_small, (1.0 - kLinearRange) * m_small) << where;
    EXPECT_LE(f_small, (1.0 + kReferenceError) * m_small) << where;
    EXPECT_GE(f_large, kSaturated) << where;
    EXPECT_LE(f_large, 1.0 + kReferenceError) << where;
  }
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
    if (x.label != "kalker_linear") {
      EXPECT_LE(x.max_force, 1.0 + kCoulombSlack) << x.label;
    }
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
