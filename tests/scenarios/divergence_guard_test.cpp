// A run whose state leaves the bounds of its model (OdeSystem::state_bounds: the half gauge of the
// linear wheelset, twice the flangeway of a vehicle's wheelsets) stops as a solver failure with
// exit 1, the time, the state and the cause, its file holding every sample up to then, instead
// of reporting a diverged solution as completed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ferro/scenarios/h5_output.hpp"
#include "process.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;
const std::string kHunting = "scenarios/scenes/wheelset_hunting.yaml";
constexpr double kHalfGauge = 0.7465;  // e of wheelset_hunting.yaml [m]

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ferro_divergence_" + std::to_string(getpid()));
  fs::create_directories(dir);
  fs::remove(dir / name);
  return (dir / name).string();
}

// The hunting scene sampled every 0.1 s: a fixed-step run samples at its steps only, so its
// output interval is a whole multiple of the step (here one step of 0.1 s per sample).
std::string hunting_sampled_every_tenth_of_a_second() {
  std::ifstream in(kHunting);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string fine = "interval: 1.0e-3";
  const auto at = yaml.find(fine);
  if (at == std::string::npos) return {};
  yaml.replace(at, fine.size(), "interval: 0.1");
  const std::string path = scratch("hunting_coarse.yaml");
  std::ofstream(path) << yaml;
  return path;
}

void expect_stopped_as_diverged(const std::vector<std::string>& extra, const std::string& name,
                                const std::string& scene = kHunting) {
  ASSERT_FALSE(scene.empty());
  const std::string out = scratch(name);
  std::vector<std::string> args = {test::ferrodyn_exe(), "run", scene, "--no-plots", "-q",
                                   "-o", out};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = test::run_capture(args, 60);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("the solution diverged"), std::string::npos) << r.output;
  ASSERT_TRUE(fs::exists(out)) << r.output;
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "solver_failure");
  EXPECT_NE(f.string_attribute("/", "status_message").find("beyond its bound"), std::string::npos);
  EXPECT_EQ(f.read_vector("/failure/state").size(), 4u);
  const auto t = f.read_vector("/time");
  const auto y = f.read_vector("/signals/wheelset.y");
  ASSERT_EQ(y.size(), t.size());
  EXPECT_DOUBLE_EQ(f.number_attribute("/", "t_reached"), t.back());
  EXPECT_LT(t.back(), 0.5);  // stopped before the end
  for (double v : y) ASSERT_LE(std::abs(v), kHalfGauge);  // no sample beyond the bound
}

// A step of 0.1 s against creep damping rates of about 200 per second (explicit steps stay
// stable below about ten milliseconds).
TEST(DivergenceGuard, fixed_step_bogacki_shampine_far_beyond_its_stability) {
  expect_stopped_as_diverged(
      {"--integrator", "odeint_bs3", "--fixed-step", "0.1", "--t-end", "0.5"}, "bs3.h5",
      hunting_sampled_every_tenth_of_a_second());
}

TEST(DivergenceGuard, fixed_step_explicit_runge_kutta_far_beyond_its_stability) {
  expect_stopped_as_diverged(
      {"--integrator", "arkode_erk", "--fixed-step", "0.1", "--t-end", "0.5"}, "erk.h5",
      hunting_sampled_every_tenth_of_a_second());
}

TEST(DivergenceGuard, an_absolute_tolerance_of_a_kilometre) {
  expect_stopped_as_diverged({"--integrator", "odeint_dopri5", "--atol", "1e3", "--t-end", "0.5"},
                             "dopri5.h5");
}

TEST(DivergenceGuard, a_speed_of_a_thousand_kilometres_a_second) {
  // Far above the critical speed: hunting grows by orders of magnitude in a fraction of a second.
  expect_stopped_as_diverged({"--speed", "1e6", "--t-end", "0.5"}, "fast.h5");
}

TEST(DivergenceGuard, a_converging_run_is_not_stopped) {
  const std::string out = scratch("ok.h5");
  const auto r = test::run_capture(
      {test::ferrodyn_exe(), "run", kHunting, "--no-plots", "-q", "-o", out, "--t-end", "2"});
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(H5File::open_read(out).string_attribute("/", "status"), "completed");
}

}  // namespace
}  // namespace ferro::scenarios
