// The default MIM table over the bench case set against converged MIM (slow: builds the default
// table, about 20 s CPU).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ferro/contact/contact_patch.hpp"
#include "ferro/contact/mim_table.hpp"
#include "ferro/contact/tangential_model.hpp"
#include "ferro/scenarios/contact_bench.hpp"

namespace fc = ferro::contact;
namespace fs = ferro::scenarios;

// All 855 bench cases (a/b 0.2-5, spin 0-2, seven creepage directions, micro-slip to full slip)
// against the reference (MIM 40 / 80 over the patch, Richardson): mean |F_t - F_t,ref| within
// kGoalMean = 0.005 mu F_n (measured 0.0030), every case within kTolMax = 0.03 (measured 0.018),
// and never above mu F_n (the interpolant's Coulomb bound; kRoundOff = 1e-12 for scaling the
// normalised force back and forth).
TEST(mim_table_bench_slow, default_table_against_converged_mim) {
  constexpr double kGoalMean = 0.005, kTolMax = 0.03, kRoundOff = 1e-12;
  const std::vector<fs::ContactBenchCase> cases = fs::contact_bench_cases();
  std::vector<fs::ContactBenchReference> ref;
  int elements = 0;
  ASSERT_TRUE(fs::read_contact_bench_reference(
      std::string(FERRO_SOURCE_DIR) + "/tests/data/contact_bench_reference.csv", cases, ref,
      elements));
  fc::MimTableSpec spec = fc::MimTableSpec::default_spec();
  spec.threads = 2;
  const fc::MimTableModel model(fc::MimTable::build(spec));
  double sum = 0.0, worst = 0.0, largest_force = 0.0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const fs::ContactBenchInput in = fs::contact_bench_input(cases[k]);
    const fc::ContactPatch patch =
        fc::elliptic_patch(in.semi_axis_x, in.semi_axis_y, in.normal_force);
    fc::TangentialProblem p;
    p.patch = &patch;
    p.friction = in.friction;
    p.body1 = p.body2 = fc::Material::from_young(in.young, in.poisson);
    p.creepage = {in.creepage_x, in.creepage_y, in.spin};
    const fc::TangentialSolution t = model.solve(p);
    const double s = in.friction * in.normal_force;
    const double e = std::hypot(t.force_x / s - ref[k].fx, t.force_y / s - ref[k].fy);
    sum += e;
    worst = std::max(worst, e);
    largest_force = std::max(largest_force, std::hypot(t.force_x, t.force_y) / s);
  }
  const double mean = sum / static_cast<double>(cases.size());
  std::printf("default mim_table: mean %.5f, max %.5f mu F_n, largest |F| %.6f mu F_n\n", mean,
              worst, largest_force);
  EXPECT_LE(mean, kGoalMean);
  EXPECT_LE(worst, kTolMax);
  EXPECT_LE(largest_force, 1.0 + kRoundOff);
}
