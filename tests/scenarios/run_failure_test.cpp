// Runs that cannot finish normally must say why and lose nothing already computed: a full disk
// (a file size limit in a child process, and a small tmpfs when the tests run as root), a CSV that
// cannot be created, signals at any moment (while a run is paced, or before the scene is even
// loaded), absurd output grids, and a device as the output.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <utility>

#include "ferro/scenarios/h5_output.hpp"
#include "limited_process.hpp"
#include "process.hpp"

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;
const std::string kHunting = "scenarios/scenes/wheelset_hunting.yaml";
const std::string kMinimal = "tests/scenarios/data/good_minimal.yaml";
// A file size limit far below what a 200 s run writes (about 12 MB of samples).
constexpr rlim_t kFileLimit = 2 * 1024 * 1024;

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ferro_run_failure_" + std::to_string(getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// What a run stopped by a full output must leave: a file that opens, status "error" with the
// cause, and every sample it holds equal to the same run's samples on an unlimited disk.
void expect_partial_output(const std::string& out, const std::string& cause) {
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "error");
  EXPECT_NE(f.string_attribute("/", "status_message").find(cause), std::string::npos)
      << f.string_attribute("/", "status_message");
  const auto t = f.read_vector("/time");
  const auto y = f.read_vector("/signals/wheelset.y");
  ASSERT_GT(t.size(), 1000u);     // a full disk stops a run late, not at its first sample
  ASSERT_LT(t.size(), 200001u);   // and before its end
  ASSERT_EQ(y.size(), t.size());
  EXPECT_EQ(static_cast<std::size_t>(f.number_attribute("/", "samples")), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) ASSERT_NEAR(t[i], 1e-3 * i, 1e-9) << i;

  const fs::path ref = fs::path(out).parent_path().parent_path() / "reference.h5";
  const auto r = test::run_capture({FERRODYN_EXE, "run", kHunting, "--t-end",
                                    fmt::format("{:.17g}", t.back()), "--no-plots", "-q", "-o",
                                    ref.string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto y_ref = H5File::open_read(ref.string()).read_vector("/signals/wheelset.y");
  ASSERT_EQ(y_ref.size(), y.size());
  for (std::size_t i = 0; i < y.size(); ++i) ASSERT_DOUBLE_EQ(y[i], y_ref[i]) << i;
}

TEST(RunFailure, file_size_limit_stops_the_run_with_the_cause_and_keeps_the_samples) {
  const fs::path dir = scratch("fsize");
  const std::string out = (dir / "full" / "out.h5").string();
  test::LimitedProcess p({FERRODYN_EXE, "run", kHunting, "--t-end", "200", "--no-plots", "-q",
                          "-o", out},
                         {{RLIMIT_FSIZE, kFileLimit}});
  const int code = p.wait();
  EXPECT_EQ(code, 1) << p.output();
  // The HDF5 writer sees the limit coming; the CSV beside it may reach it first.
  const bool named = p.output().find("file size limit") != std::string::npos ||
                     p.output().find("File too large") != std::string::npos;
  EXPECT_TRUE(named) << p.output();
  expect_partial_output(out, p.output().find("File too large") != std::string::npos
                                 ? "File too large"
                                 : "file size limit");
}

TEST(RunFailure, full_tmpfs_stops_the_run_with_the_cause_and_keeps_the_samples) {
  if (geteuid() != 0) GTEST_SKIP() << "mounting a small tmpfs needs root; RLIMIT_FSIZE covers it";
  const fs::path dir = scratch("tmpfs");
  if (mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=2m") != 0)
    GTEST_SKIP() << "cannot mount a tmpfs here: " << std::strerror(errno);
  struct Unmount {
    fs::path dir;
    ~Unmount() { umount2(dir.c_str(), MNT_DETACH); }
  } unmount{dir};
  const std::string out = (dir / "out.h5").string();
  const auto r = test::run_capture(
      {FERRODYN_EXE, "run", kHunting, "--t-end", "200", "--no-plots", "-q", "-o", out});
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const bool named = r.output.find("no space left on device") != std::string::npos ||
                     r.output.find("No space left on device") != std::string::npos;
  EXPECT_TRUE(named) << r.output;
  // Copy out before checking (the reference run writes beside it, outside the tmpfs).
  const fs::path copy = dir.parent_path() / "tmpfs_copy" / "out.h5";
  fs::create_directories(copy.parent_path());
  fs::copy_file(out, copy, fs::copy_options::overwrite_existing);
  expect_partial_output(copy.string(), "o space left on device");
}

TEST(RunFailure, csv_outputs_on_a_full_disk_fail_with_the_cause) {
  const fs::path dir = scratch("csv_full");
  // contact curve writes about 80 kB of CSV; 4 kB do not hold it.
  test::LimitedProcess curve({FERRODYN_EXE, "contact", "curve",
                              "scenarios/cases/contact/thesis_spheres.yaml", "--out",
                              (dir / "c").string(), "--no-png"},
                             {{RLIMIT_FSIZE, 4096}});
  EXPECT_EQ(curve.wait(), 1) << curve.output();
  EXPECT_NE(curve.output().find("File too large"), std::string::npos) << curve.output();

  test::LimitedProcess geometry({FERRODYN_EXE, "geometry",
                                 std::string(FERRO_DATA_DIR) +
                                     "/manchester_contact_benchmark_a22.yaml",
                                 "--no-plot", "--out-dir", (dir / "g").string()},
                                {{RLIMIT_FSIZE, 4096}});
  EXPECT_EQ(geometry.wait(), 1) << geometry.output();
  EXPECT_NE(geometry.output().find("File too large"), std::string::npos) << geometry.output();
}

TEST(RunFailure, a_csv_that_cannot_be_created_leaves_status_error) {
  const fs::path dir = scratch("csv_dir");
  fs::create_directories(dir / "out.csv");  // where the CSV should go: a folder
  const std::string out = (dir / "out.h5").string();
  const auto r = test::run_capture(
      {FERRODYN_EXE, "run", kMinimal, "-o", out, "--csv", "all", "--no-plots", "-q"});
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("out.csv"), std::string::npos) << r.output;
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "error");
  EXPECT_NE(f.string_attribute("/", "status_message").find("out.csv"), std::string::npos);
}

TEST(RunFailure, pace_answers_sigterm_at_once) {
  const fs::path dir = scratch("pace");
  const std::string out = (dir / "out.h5").string();
  // 1e-5 simulated seconds per wall second: 100 s of wall time between two 1 ms samples.
  test::LimitedProcess p(
      {FERRODYN_EXE, "run", kMinimal, "-o", out, "--pace", "1e-5", "--no-plots", "-q"}, {});
  const auto start = std::chrono::steady_clock::now();
  while (!fs::exists(out) && std::chrono::steady_clock::now() - start < std::chrono::seconds(30))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto sent = std::chrono::steady_clock::now();
  p.signal(SIGTERM);
  EXPECT_EQ(p.wait(), 143) << p.output();
  // Polled every 20 ms: well under a second even on a loaded machine.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count(), 5.0);
  EXPECT_EQ(H5File::open_read(out).string_attribute("/", "status"), "interrupted");
}

TEST(RunFailure, a_signal_before_the_scene_is_loaded_still_leaves_a_file) {
  const fs::path dir = scratch("early");
  for (int sig : {SIGINT, SIGTERM}) {
    const std::string out = (dir / fmt::format("out{}.h5", sig)).string();
    // Started with the stop signals blocked, the signal is pending from the first instant and is
    // delivered as soon as the program installs its handler.
    test::LimitedProcess p({FERRODYN_EXE, "run", kMinimal, "-o", out, "--no-plots", "-q"}, {},
                           /*block_stop_signals=*/true);
    p.signal(sig);
    EXPECT_EQ(p.wait(), 128 + sig) << p.output();
    const H5File f = H5File::open_read(out);
    EXPECT_EQ(f.string_attribute("/", "status"), "interrupted");
    EXPECT_EQ(f.read_vector("/time").size(), 1u);  // stopped at its first sample
  }
}

TEST(RunFailure, a_long_run_does_not_allocate_its_time_grid) {
  const fs::path dir = scratch("long");
  const std::string out = (dir / "out.h5").string();
  // 1e6 s every 1 ms is 1e9 output times (8 GB as one vector); 1 GB of address space is plenty
  // for the run itself.
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer's shadow memory cannot live under RLIMIT_AS: no cap under the sanitizer
  // (an up-front 8 GB time grid would still show as the run never writing samples).
  const std::vector<test::Limit> limits;
#else
  const std::vector<test::Limit> limits{{RLIMIT_AS, rlim_t{1} << 30}};
#endif
  test::LimitedProcess p({FERRODYN_EXE, "run", kMinimal, "-o", out, "--t-end", "1e6",
                          "--no-plots", "-q"},
                         limits);
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::seconds(30)) {
    if (fs::exists(out) && fs::file_size(out) > 200000) break;  // samples are being written
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  p.signal(SIGINT);
  EXPECT_EQ(p.wait(), 130) << p.output();
  const H5File f = H5File::open_read(out);
  EXPECT_EQ(f.string_attribute("/", "status"), "interrupted");
  EXPECT_GT(f.read_vector("/time").size(), 1000u);
}

TEST(RunFailure, impossible_output_intervals_are_rejected_with_their_location) {
  const fs::path dir = scratch("interval");
  std::ifstream in(kMinimal);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("output:");
  ASSERT_NE(at, std::string::npos);
  text.insert(text.find('\n', at) + 1, "  interval: 1.0e-300\n");
  const std::string scene = (dir / "tiny_interval.yaml").string();
  std::ofstream(scene) << text;
  for (const char* verb : {"validate", "run"}) {
    const auto r = verb == std::string("run")
                       ? test::run_capture({FERRODYN_EXE, "run", scene, "-o",
                                            (dir / "x.h5").string(), "--no-plots", "-q"})
                       : test::run_capture({FERRODYN_EXE, "validate", scene});
    EXPECT_EQ(r.exit_code, 2) << verb << ": " << r.output;
    EXPECT_NE(r.output.find("tiny_interval.yaml:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("interval"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("at most"), std::string::npos) << r.output;
  }
  const auto t_end = test::run_capture({FERRODYN_EXE, "run", kMinimal, "-o",
                                        (dir / "y.h5").string(), "--t-end", "1e300", "-q"});
  EXPECT_EQ(t_end.exit_code, 2) << t_end.output;
  EXPECT_NE(t_end.output.find("--t-end"), std::string::npos) << t_end.output;
}

TEST(RunFailure, a_duration_or_speed_override_that_leaves_the_track_is_refused) {
  // The ERRI scene's 600 m track holds 10 s at 55 m/s from s = 15 m; 12 s or 70 m/s would run
  // the leading wheelset past its end. Refused before any output is written, naming the flag,
  // the distance and where the track ends.
  const std::string scene = "scenarios/scenes/manchester_straight_erri.yaml";
  const fs::path dir = fs::temp_directory_path() / "ferro_off_track_override";
  fs::create_directories(dir);
  const std::string out = (dir / "o.h5").string();
  fs::remove(out);
  for (const auto& [flag, value] : {std::pair<std::string, std::string>{"--t-end", "12"},
                                    std::pair<std::string, std::string>{"--speed", "70"}}) {
    const auto r = test::run_capture(
        {FERRODYN_EXE, "run", scene, "-o", out, flag, value, "--no-plots", "-q"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(flag + ": the vehicle runs off the track"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("track ends at s = 600.0 m"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
  }
  const auto wp = test::run_capture({FERRODYN_EXE, "bench", "work-precision", scene, "--t-end",
                                     "5", "--settle", "6", "--integrators", "cvode_bdf"});
  EXPECT_EQ(wp.exit_code, 2) << wp.output;
  EXPECT_NE(wp.output.find("--settle: the vehicle runs off the track"), std::string::npos)
      << wp.output;
  fs::remove_all(dir);
}

TEST(RunFailure, tolerance_overrides_are_applied_or_refused_naming_the_flag) {
  const fs::path dir = fs::temp_directory_path() / "ferro_tolerance_override";
  fs::create_directories(dir);
  const std::string out = (dir / "o.h5").string();
  const auto ok = test::run_capture({FERRODYN_EXE, "run", kHunting, "-o", out, "--t-end", "0.5",
                                     "--rtol", "1e-3", "--atol", "1e-6", "--no-plots", "-q"});
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_NE(ok.output.find("(rtol 0.001, atol 1e-06)"), std::string::npos) << ok.output;
  for (const auto& [flag, value] : {std::pair<std::string, std::string>{"--rtol", "2"},
                                    std::pair<std::string, std::string>{"--atol", "-1"}}) {
    const auto r = test::run_capture(
        {FERRODYN_EXE, "run", kHunting, "-o", out, flag, value, "--no-plots", "-q"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(flag + ": must"), std::string::npos) << r.output;
  }
  fs::remove_all(dir);
}

TEST(RunFailure, fixed_step_overrides_are_applied_or_refused_naming_the_flag) {
  // The ERRI scene integrates at a fixed 1 ms step: another method on the command line runs
  // under its own error control, --fixed-step sets or clears the step, a step for a method
  // without one is refused, and so is no step for the method that needs one.
  const std::string scene = "scenarios/scenes/manchester_straight_erri.yaml";
  const fs::path dir = fs::temp_directory_path() / "ferro_fixed_step_override";
  fs::create_directories(dir);
  const std::string out = (dir / "o.h5").string();
  const auto bdf = test::run_capture({FERRODYN_EXE, "run", scene, "-o", out, "--t-end", "0.01",
                                      "--integrator", "cvode_bdf", "--no-plots", "-q"});
  EXPECT_EQ(bdf.exit_code, 0) << bdf.output;
  EXPECT_NE(bdf.output.find("cvode_bdf (rtol"), std::string::npos) << bdf.output;
  const auto half = test::run_capture({FERRODYN_EXE, "run", scene, "-o", out, "--t-end", "0.01",
                                       "--fixed-step", "5e-4", "--no-plots", "-q"});
  EXPECT_EQ(half.exit_code, 0) << half.output;
  EXPECT_NE(half.output.find("fixed step 0.0005 s, no error control): 20 steps"),
            std::string::npos)
      << half.output;
  const auto adaptive =
      test::run_capture({FERRODYN_EXE, "run", scene, "-o", out, "--t-end", "0.01", "--integrator",
                         "arkode_erk", "--fixed-step", "0", "--no-plots", "-q"});
  EXPECT_EQ(adaptive.exit_code, 0) << adaptive.output;
  EXPECT_NE(adaptive.output.find("arkode_erk (rtol"), std::string::npos) << adaptive.output;
  const std::pair<std::vector<std::string>, std::string> refused[] = {
      {{"--fixed-step", "-1"}, "--fixed-step: must be >= 0 s"},
      {{"--fixed-step", "0"}, "bdf2 runs at a fixed step only"},
      {{"--integrator", "cvode_bdf", "--fixed-step", "1e-3"},
       "--fixed-step: only arkode_erk, arkode_dirk, odeint_bs3 and bdf2 take a fixed step; "
       "cvode_bdf needs 0"}};
  fs::remove(out);
  for (const auto& [args, message] : refused) {
    std::vector<std::string> cmd{FERRODYN_EXE, "run", scene, "-o", out, "--no-plots", "-q"};
    cmd.insert(cmd.end(), args.begin(), args.end());
    const auto r = test::run_capture(cmd);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
  }
  fs::remove_all(dir);
}

TEST(RunFailure, a_device_output_creates_no_file_beside_it) {
  if (geteuid() != 0) GTEST_SKIP() << "only root could create files in /dev";
  ASSERT_FALSE(fs::exists("/dev/null.csv")) << "left over by another program; remove it";
  const auto r = test::run_capture({FERRODYN_EXE, "run", kHunting, "-o", "/dev/null", "--t-end",
                                    "0.1", "--no-plots", "-q"});
  const bool created = fs::exists("/dev/null.csv");
  if (created) fs::remove("/dev/null.csv");
  EXPECT_FALSE(created) << r.output;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

}  // namespace
}  // namespace ferro::scenarios
