// Absurd but well-formed numbers on the command line: the program answers with exit code 2 and
// a message naming the option and the allowed range, within a memory cap (RLIMIT_AS set in the
// child shell) and in seconds; it never prints a non-finite force.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "process.hpp"

namespace {

using ferro::test::run_capture;
using ferro::test::shell_quote;

// Address-space cap of the child [KiB]: the 4 GB of the reported crash.
constexpr const char* kAddressSpaceKiB = "4000000";
// Wall-clock bound of a refused request [s]: refusals happen before any grid is built; the
// bound leaves room for a loaded machine.
constexpr double kRefusalSeconds = 20.0;

struct Timed {
  ferro::test::ProcessResult r;
  double seconds;
};

// Runs ferrodyn with `args` under `ulimit -v`, optionally feeding `input` on stdin.
Timed run_capped(const std::vector<std::string>& args, const std::string& input = "") {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of shadow address space at start, which no RLIMIT_AS
  // allows: under the sanitizer the cap is left out and the bounded time still checks that the
  // refusal comes before any large allocation.
  std::string cmd;
#else
  std::string cmd = std::string("ulimit -v ") + kAddressSpaceKiB + "; ";
#endif
  if (!input.empty()) cmd += "printf '%s' " + shell_quote(input) + " | ";
  cmd += shell_quote(FERRODYN_EXE);
  for (const auto& a : args) cmd += " " + shell_quote(a);
  const auto t0 = std::chrono::steady_clock::now();
  Timed t{run_capture({"sh", "-c", cmd}), 0.0};
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return t;
}

void expect_refused(const Timed& t, const std::vector<std::string>& fragments) {
  EXPECT_EQ(t.r.exit_code, 2) << t.r.output;
  EXPECT_LT(t.seconds, kRefusalSeconds) << t.r.output;
  for (const auto& f : fragments) EXPECT_NE(t.r.output.find(f), std::string::npos) << t.r.output;
}

TEST(input_limits, mim_eval_on_an_extreme_ellipse_is_refused_within_the_memory_cap) {
  // a/b = 1e-6: the grid would need 29 GB.
  expect_refused(run_capped({"contact", "eval", "--model", "mim", "--a", "4e-9", "--b", "4e-3",
                             "--fn", "1e4", "--mu", "0.3", "--xi-x", "1e-3"}),
                 {"aspect ratio", "grid elements"});
  // a/b = 1/4000: a grid the default resolution cannot afford (formerly minutes of CPU).
  expect_refused(run_capped({"contact", "eval", "--model", "mim", "--a", "1e-6", "--b", "4e-3",
                             "--fn", "1e4", "--mu", "0.3", "--xi-x", "1e-3"}),
                 {"mim option 'elements'", "must lie in [4,"});
}

TEST(input_limits, mim_elements_beyond_the_grid_cap_name_the_option) {
  expect_refused(
      run_capped({"mim", "--a-mm", "4", "--b-mm", "3", "--fn", "3e4", "--elements", "5000"}),
      {"--elements", "must lie in [4,"});
  const auto small =
      run_capped({"mim", "--a-mm", "4", "--b-mm", "3", "--fn", "3e4", "--elements", "2"});
  expect_refused(small, {"--elements"});
  EXPECT_EQ(small.r.output.find("HertzRollingInput"), std::string::npos) << small.r.output;
  expect_refused(run_capped({"contact", "mim-table", "--out", "/tmp/ferro_unused_table.h5",
                             "--elements", "5000"}),
                 {"--elements", "must lie in [6,"});
}

TEST(input_limits, mim_accepts_zero_friction_like_the_other_models) {
  const auto t = run_capped({"mim", "--a-mm", "4", "--b-mm", "3", "--fn", "3e4", "--xi-x", "0.002",
                             "--mu", "0", "--elements", "16"});
  EXPECT_EQ(t.r.exit_code, 0) << t.r.output;
  // Frictionless: no creep force at all.
  EXPECT_NE(t.r.output.find("Fx = 0 N, Fy = 0 N"), std::string::npos) << t.r.output;
  const auto fastsim =
      run_capped({"contact", "eval", "--model", "mim", "--a", "4e-3", "--b", "3e-3", "--fn", "3e4",
                  "--mu", "0", "--xi-x", "2e-3", "--option", "elements=16"});
  EXPECT_EQ(fastsim.r.exit_code, 0) << fastsim.r.output;
}

TEST(input_limits, overflowing_input_never_prints_a_non_finite_force) {
  const auto t = run_capped({"contact", "eval", "--model", "kalker_linear", "--a", "1e308", "--b",
                             "1e308", "--fn", "1e4", "--mu", "0.3", "--xi-x", "1e-3"});
  EXPECT_NE(t.r.exit_code, 0) << t.r.output;
  EXPECT_EQ(t.r.output.find("null"), std::string::npos) << t.r.output;
  EXPECT_EQ(t.r.output.find("nan"), std::string::npos) << t.r.output;
  EXPECT_EQ(t.r.exit_code, 2) << t.r.output;
  const auto batch = run_capped({"contact", "eval", "--batch", "--model", "fastsim", "--a", "6e-3",
                                 "--b", "4e-3", "--fn", "1e4", "--mu", "0.3"},
                                "xi_x,k11\n1e-3,1\n1e-3,1e300\n");
  EXPECT_EQ(batch.r.exit_code, 2) << batch.r.output;
  EXPECT_EQ(batch.r.output.find("nan"), std::string::npos) << batch.r.output;
  EXPECT_NE(batch.r.output.find("stdin:3"), std::string::npos) << batch.r.output;
}

// An extreme curvature ratio is bounded by the Hertz layer's one documented treatment: the
// evaluation succeeds with finite forces and never reports an elliptic modulus.
TEST(input_limits, extreme_curvature_ratio_is_bounded_not_an_internal_error) {
  const auto t = run_capped({"contact", "eval", "--model", "kalker_linear", "--curvature-x", "1",
                             "--curvature-y", "1e13", "--fn", "1e4", "--mu", "0.3",
                             "--xi-x", "1e-3"});
  EXPECT_EQ(t.r.exit_code, 0) << t.r.output;
  EXPECT_EQ(t.r.output.find("modulus"), std::string::npos) << t.r.output;
  for (const char* force : {"\"force_x\": null", "\"force_y\": null", "\"moment_z\": null"}) {
    EXPECT_EQ(t.r.output.find(force), std::string::npos) << t.r.output;
  }
}

}  // namespace
