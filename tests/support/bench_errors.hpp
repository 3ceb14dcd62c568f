#pragma once
// Test support: a tangential model's force error over the contact bench's case set against its
// converged-MIM reference (tests/data/contact_bench_reference.csv: MIM 40 x 40 and 80 x 80 over
// the patch, Richardson-extrapolated), shared by the fast MIM accuracy test and the slow MIM
// table test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "ferro/contact/normal/contact_patch.hpp"
#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/scenarios/contact_bench.hpp"

namespace ferro::test {

struct BenchErrors {
  double mean = 0.0;           ///< mean |F_t - F_t,ref| / (mu F_n) over the cases run
  double worst = 0.0;          ///< largest of them
  double largest_force = 0.0;  ///< largest |F_t| / (mu F_n) returned
  std::size_t cases = 0;       ///< cases run
};

/// Runs `model` on every `stride`-th bench case. A missing or stale reference file is a test
/// failure (and every figure returned is infinite, so no bound holds).
inline BenchErrors bench_errors(const contact::TangentialModel& model, std::size_t stride) {
  namespace fs = ferro::scenarios;
  const std::vector<fs::ContactBenchCase> cases = fs::contact_bench_cases();
  std::vector<fs::ContactBenchReference> ref;
  int elements = 0;
  const std::string path = std::string(FERRO_SOURCE_DIR) + "/tests/data/contact_bench_reference.csv";
  if (!fs::read_contact_bench_reference(path, cases, ref, elements)) {
    ADD_FAILURE() << "no reference for the bench cases in " << path;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    return {kInf, kInf, kInf, 0};
  }
  BenchErrors e;
  double sum = 0.0;
  for (std::size_t k = 0; k < cases.size(); k += stride) {
    const contact::ContactPatch patch = fs::contact_bench_patch(cases[k]);
    const contact::TangentialSolution t = model.solve(fs::contact_bench_problem(cases[k], patch));
    const double s = fs::contact_bench_input(cases[k]).friction * patch.normal_force;
    const double err = std::hypot(t.force_x / s - ref[k].fx, t.force_y / s - ref[k].fy);
    sum += err;
    e.worst = std::max(e.worst, err);
    e.largest_force = std::max(e.largest_force, std::hypot(t.force_x, t.force_y) / s);
    ++e.cases;
  }
  e.mean = sum / static_cast<double>(e.cases);
  return e;
}

}  // namespace ferro::test
