// SIGINT and SIGTERM are honoured wherever the program is (scenarios/app/terminal.hpp): between
// two integrator steps however long the solver takes to the next output, in the first
// milliseconds of the program, in an analysis, while plotting. A stopped run keeps every sample
// computed until then in a file whose status and t_reached agree with its samples.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "ferro/scenarios/h5_output.hpp"
#include "limited_process.hpp"
#include "process.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The program ends within InterruptGuard::kStopGrace = 0.4 s of a signal; the tests allow for
// a loaded 2-core machine scheduling it late.
constexpr double kStopSeconds = 1.5;

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ferro_stop_request_" + std::to_string(getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

bool any_part_file(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".part") return true;
  return false;
}

struct Stopped {
  int exit_code = -1;
  double seconds = 0.0;  // from the signal to the exit
  std::string output;
};

// Starts `args`, waits until its output's temporary file exists and `after` has passed, sends
// `sig` and waits for the exit.
Stopped stop_after(const std::vector<std::string>& args, const fs::path& dir, double after,
                   int sig = SIGTERM) {
  test::LimitedProcess p(args, {});
  const auto start = Clock::now();
  while (!any_part_file(dir) && Clock::now() - start < std::chrono::seconds(30))
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::this_thread::sleep_for(std::chrono::duration<double>(after));
  const auto sent = Clock::now();
  p.signal(sig);
  Stopped s;
  s.exit_code = p.wait_for(60.0);  // a program that ignores the signal is killed: 137
  s.seconds = std::chrono::duration<double>(Clock::now() - sent).count();
  s.output = p.output();
  return s;
}

// A stopped run's output: renamed to its name, status interrupted, samples consistent.
void expect_interrupted_output(const std::string& out) {
  ASSERT_TRUE(fs::exists(out));
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "interrupted");
  const auto t = f.read_vector("/time");
  ASSERT_FALSE(t.empty());
  EXPECT_EQ(static_cast<std::size_t>(f.number_attribute("/", "samples")), t.size());
  EXPECT_DOUBLE_EQ(f.number_attribute("/", "t_reached"), t.back());
}

TEST(StopRequest, sigterm_while_the_solver_works_between_two_outputs) {
  // The Manchester vehicle on its flexible track in the 1200 m curve at 150 m/s, bdf2 at a
  // 1 ns step: five million steps between two 5 ms outputs.
  const fs::path dir = scratch("curve");
  const std::string out = (dir / "f150.h5").string();
  const auto s = stop_after({test::ferrodyn_exe(), "run", "scenarios/scenes/manchester_curve_1200.yaml",
                             "--speed", "150", "--t-end", "1", "--fixed-step", "1e-9",
                             "--no-plots", "-q", "-o", out},
                            dir, 1.0);
  EXPECT_EQ(s.exit_code, 143) << s.output;
  EXPECT_LT(s.seconds, kStopSeconds);
  expect_interrupted_output(out);
}

TEST(StopRequest, sigterm_during_a_million_tiny_fixed_steps_per_output) {
  const fs::path dir = scratch("tiny_step");
  const std::string out = (dir / "t.h5").string();
  const auto s = stop_after({test::ferrodyn_exe(), "run", "scenarios/scenes/wheelset_hunting.yaml",
                             "--integrator", "odeint_bs3", "--fixed-step", "1e-9", "--no-plots",
                             "-q", "-o", out},
                            dir, 1.0);
  EXPECT_EQ(s.exit_code, 143) << s.output;
  EXPECT_LT(s.seconds, kStopSeconds);
  expect_interrupted_output(out);
}

TEST(StopRequest, sigint_with_an_absurd_absolute_tolerance) {
  const fs::path dir = scratch("atol");
  const std::string out = (dir / "a.h5").string();
  // The derailment scene under adaptive BDF (cvode_bdf; the scene's bdf2 takes a fixed step,
  // where the tolerance only ends its Newton iterations): an absolute tolerance of 1e-30 on
  // states of order 1e-3 takes steps of tens of nanoseconds.
  const auto s = stop_after({test::ferrodyn_exe(), "run", "scenarios/scenes/thesis_derailment.yaml",
                             "--integrator", "cvode_bdf", "--atol", "1e-30", "--no-plots", "-q",
                             "-o", out},
                            dir, 1.0, SIGINT);
  EXPECT_EQ(s.exit_code, 130) << s.output;
  EXPECT_LT(s.seconds, kStopSeconds);
  expect_interrupted_output(out);
}

TEST(StopRequest, a_signal_in_the_first_milliseconds_leaves_an_interrupted_file) {
  const fs::path dir = scratch("early");
  for (int delay_ms : {1, 3, 6, 10, 15, 20, 30}) {
    std::string name = "e";
    name += std::to_string(delay_ms) + ".h5";
    const std::string out = (dir / name).string();
    // In real time (--pace 1: 0.5 s) so the signal always comes before the end: unpaced, the
    // whole run takes about as long as the longest delay here.
    test::LimitedProcess p({test::ferrodyn_exe(), "run", "tests/scenarios/data/good_minimal.yaml",
                            "--pace", "1", "--no-plots", "-q", "-o", out},
                           {});
    // The delay counts from the launcher's first instructions, where it blocks the stop
    // signals: before them no program can protect itself, and on a loaded machine the exec'd
    // launcher may wait milliseconds for a core.
    ASSERT_TRUE(p.wait_until_stop_signals_blocked(10.0)) << delay_ms << " ms";
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    p.signal(SIGTERM);
    EXPECT_EQ(p.wait_for(60.0), 143) << delay_ms << " ms: " << p.output();
    // The program's handler ends it, never the signal's default action: the launcher starts it
    // with the stop signals blocked.
    EXPECT_FALSE(p.killed_by_signal()) << delay_ms << " ms: " << p.output();
    // Stopped once integrating: the file holds what was computed. Stopped while it still
    // prepares (a loaded machine, a sanitizer build): no file, no temporary file (docs/OUTPUT.md).
    if (fs::exists(out)) {
      expect_interrupted_output(out);
    } else {
      for (const auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().extension(), ".h5") << delay_ms << " ms: " << e.path();
    }
  }
}

TEST(StopRequest, sigterm_while_plotting_ends_the_program_without_a_false_warning) {
  const fs::path dir = scratch("plotting");
  const std::string out = (dir / "p.h5").string();
  test::LimitedProcess p({test::ferrodyn_exe(), "run", "tests/scenarios/data/good_minimal.yaml",
                          "-q", "-o", out, "--plot-dir", (dir / "plots").string()},
                         {});
  // The summary's last line names the output; the plots come after it.
  std::string line;
  bool summary = false;
  while (p.read_line(line)) {
    if (line.find("  output ") != std::string::npos) {
      summary = true;
      break;
    }
  }
  ASSERT_TRUE(summary) << p.output();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const auto sent = Clock::now();
  p.signal(SIGTERM);
  EXPECT_EQ(p.wait_for(60.0), 143) << p.output();
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - sent).count(), kStopSeconds);
  EXPECT_EQ(p.output().find("matplotlib"), std::string::npos) << p.output();
  EXPECT_EQ(H5File::open_read(out).string_attribute("/", "status"), "completed");
}

TEST(StopRequest, sigterm_during_an_analysis_ends_it_and_leaves_no_partial_output) {
  const fs::path dir = scratch("analysis");
  const std::string out = (dir / "eig.h5").string();
  const auto s = stop_after({test::ferrodyn_exe(), "critical-speed", "eigen",
                             "scenarios/scenes/thesis_critical_speed.yaml", "--points", "2000",
                             "--no-plots", "-o", out},
                            dir, 1.0);
  EXPECT_EQ(s.exit_code, 143) << s.output;
  EXPECT_LT(s.seconds, kStopSeconds);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(any_part_file(dir));
}

}  // namespace
}  // namespace ferro::scenarios
