// Sweeps: the journal records points exactly and refuses another sweep's folder; the same short
// sweep run serially, on 2 threads, under `mpirun -n 2` and resumed after a stop gives identical
// numbers (every point is an independent run with the same inputs).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "ferro/scenarios/analysis/sweep.hpp"
#include "ferro/scenarios/h5_output.hpp"

namespace ferro::scenarios::analysis {
namespace {

namespace fs = std::filesystem;

int run(const std::string& args, const std::string& log) {
  const std::string cmd = args + " > " + log + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

#ifdef FERRO_WITH_MPI
/// `command` under `mpirun -n 2`.
int run_mpi(const std::string& command, const std::string& log) {
#if defined(__SANITIZE_ADDRESS__)
  // OpenMPI unloads its plugins before exit, so LeakSanitizer can neither attribute nor
  // suppress their allocations: leak checking is off for the mpirun children only.
  const std::string mpi_env = "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 ";
#else
  const std::string mpi_env;
#endif
  return run(mpi_env + "mpirun --allow-run-as-root --oversubscribe -n 2 " + command, log);
}
#endif

std::string slurp(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "r");
  std::string s;
  if (f == nullptr) return s;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) s.append(buf, n);
  std::fclose(f);
  return s;
}

TEST(SweepJournal, RecordsExactlyAndRefusesAnotherSweep) {
  const auto dir = (fs::temp_directory_path() / "ferro_sweep_journal_test").string();
  fs::remove_all(dir);
  SweepPointResult r;
  r.index = 7;
  r.point = {38.123456789012345, contact::ReductionFactors::following_k22(0.9, 0.7)};
  r.outcome = Oscillation::kSteady;
  r.amplitude = {1.0 / 3.0, 2e-7, NAN};
  r.period = 0.4567891234567891;
  r.time = 20.0;
  r.rhs_evaluations = 12345;
  {
    SweepJournal j(dir, "sweep A");
    j.record(r);
  }
  const auto loaded = SweepJournal(dir, "sweep A").load();
  ASSERT_EQ(loaded.size(), 1u);
  const auto& l = loaded.at(7);
  EXPECT_EQ(l.point.speed, r.point.speed);  // exact: 17 significant digits
  EXPECT_EQ(l.point.k, r.point.k);          // K23 and K33 follow K22 as they did when run
  EXPECT_EQ(l.amplitude[0], r.amplitude[0]);
  EXPECT_TRUE(std::isnan(l.amplitude[2]));
  EXPECT_EQ(l.period, r.period);
  EXPECT_EQ(l.outcome, Oscillation::kSteady);
  EXPECT_THROW(SweepJournal(dir, "sweep B"), std::invalid_argument);
  fs::remove_all(dir);
}

TEST(ParallelFor, EveryIndexOnceAndErrorsPropagate) {
  std::vector<int> hits(100, 0);
  parallel_for(hits.size(), [&](std::size_t i) { hits[i] += 1; }, 3);
  for (int h : hits) EXPECT_EQ(h, 1);
  EXPECT_THROW(parallel_for(10, [](std::size_t i) { if (i == 5) throw std::runtime_error("x"); }, 2),
               std::runtime_error);
}

struct SweepData {
  std::vector<double> speed, outcome, amplitude;
};

SweepData read(const std::string& path) {
  const auto f = H5File::open_read(path);
  return {f.read_vector("/sweep/speed"), f.read_vector("/sweep/outcome"),
          f.read_vector("/sweep/amplitude")};
}

void expect_identical(const SweepData& a, const SweepData& b, const std::string& what) {
  ASSERT_EQ(a.speed.size(), b.speed.size()) << what;
  ASSERT_EQ(a.amplitude.size(), b.amplitude.size()) << what;
  for (std::size_t i = 0; i < a.speed.size(); ++i) {
    EXPECT_EQ(a.speed[i], b.speed[i]) << what << " point " << i;
    EXPECT_EQ(a.outcome[i], b.outcome[i]) << what << " point " << i;
    EXPECT_EQ(a.amplitude[i], b.amplitude[i]) << what << " point " << i;  // bitwise: same runs
  }
}

class SweepCli : public ::testing::Test {
 protected:
  // One directory per test: ctest runs the tests of this fixture as parallel processes, and a
  // shared directory would be cleared by one test's SetUp while another writes into it.
  std::string dir = std::string(FERRO_BINARY_DIR) + "/sweep_cli_test_" +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::string scene = std::string(FERRO_SOURCE_DIR) + "/scenarios/scenes/wheelset_hunting.yaml";
  // Speeds across the linear critical speed 38.93 m/s: decayed, slowly decaying, growing.
  std::string args = " sweep " + scene +
                     " --speed-min 30 --speed-max 48 --points 4 --k 1,0.8 --disturbance 1e-3"
                     " --segment 2 --t-max 4 --no-plots -q";
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string exe() const { return std::string(FERRODYN_EXE); }
};

TEST_F(SweepCli, SerialThreadsResumeAndMpiAgree) {
  ASSERT_EQ(run(exe() + args + " -o " + dir + "/serial.h5", dir + "/serial.log"), 0)
      << slurp(dir + "/serial.log");
  const auto serial = read(dir + "/serial.h5");
  ASSERT_EQ(serial.speed.size(), 8u);
  // The sweep straddles the linear critical speed, eq. (151) 38.93 m/s, which for equal primary
  // stiffnesses does not depend on the creep coefficients (K): sustained (steady 1, diverged 2,
  // growing 3) exactly above it.
  for (std::size_t i = 0; i < serial.speed.size(); ++i) {
    const bool sustained = serial.outcome[i] >= 1.0 && serial.outcome[i] <= 3.0;
    EXPECT_EQ(sustained, serial.speed[i] > 38.93) << serial.speed[i];
  }

  ASSERT_EQ(run(exe() + args + " --jobs 2 -o " + dir + "/threads.h5", dir + "/threads.log"), 0)
      << slurp(dir + "/threads.log");
  expect_identical(serial, read(dir + "/threads.h5"), "2 threads");

  // Stopped after 3 points (exit 1, points kept), then resumed without redoing them.
  EXPECT_EQ(run(exe() + args + " --max-new-points 3 -o " + dir + "/resumed.h5", dir + "/r1.log"),
            1);
  EXPECT_FALSE(fs::exists(dir + "/resumed.h5"));
  ASSERT_EQ(run(exe() + args + " --jobs 2 -o " + dir + "/resumed.h5", dir + "/r2.log"), 0)
      << slurp(dir + "/r2.log");
  EXPECT_NE(slurp(dir + "/r2.log").find("(3 already finished"), std::string::npos)
      << slurp(dir + "/r2.log");
  expect_identical(serial, read(dir + "/resumed.h5"), "resumed");

#ifdef FERRO_WITH_MPI
  ASSERT_EQ(run_mpi(exe() + args + " -o " + dir + "/mpi.h5", dir + "/mpi.log"), 0)
      << slurp(dir + "/mpi.log");
  EXPECT_NE(slurp(dir + "/mpi.log").find("2 rank(s)"), std::string::npos) << slurp(dir + "/mpi.log");
  expect_identical(serial, read(dir + "/mpi.h5"), "mpirun -n 2");
#else
  GTEST_SKIP() << "built without MPI: the mpirun comparison is not run";
#endif
}

TEST_F(SweepCli, ManchesterVehicleThreadsAndMpiAgreeWithSerial) {
  // The whole Manchester vehicle of the thesis setup (bogie frames and wheelsets free
  // lengthwise, wheelsets free to spin, multi-point contact table, chopaya, discrete track, bdf2
  // at 1 ms): a short version of the 60-speed sweep, one speed below the Hopf speed (72.8 m/s)
  // and one well above it (the hunting mode grows slowly near it), each 2 s from the 6 mm
  // offset. Every point is an
  // independent run with the same inputs, so threads and ranks must give the serial numbers
  // bit for bit.
  const std::string vehicle_scene =
      std::string(FERRO_SOURCE_DIR) + "/scenarios/scenes/thesis_critical_speed.yaml";
  const std::string vargs = " sweep " + vehicle_scene +
                            " --speed-min 60 --speed-max 90 --points 2 --disturbance 0.006"
                            " --segment 1 --t-max 2 --zero-amplitude 1e-300 --max-amplitude 1e300"
                            " --rel-tol 1e-15 --no-plots -q";
  ASSERT_EQ(run(exe() + vargs + " -o " + dir + "/serial.h5", dir + "/serial.log"), 0)
      << slurp(dir + "/serial.log");
  const auto serial = read(dir + "/serial.h5");
  ASSERT_EQ(serial.speed.size(), 2u);
  // Below the Hopf speed the leading wheelset's oscillation has shrunk from the 6 mm offset;
  // above it the run is in flange contact (amplitude near the 6-7 mm clearance).
  EXPECT_LT(serial.amplitude[0], 6.0e-3);
  EXPECT_GT(serial.amplitude[4], 5.0e-3);
  ASSERT_EQ(run(exe() + vargs + " --jobs 2 -o " + dir + "/threads.h5", dir + "/threads.log"), 0)
      << slurp(dir + "/threads.log");
  expect_identical(serial, read(dir + "/threads.h5"), "2 threads");
#ifdef FERRO_WITH_MPI
  ASSERT_EQ(run_mpi(exe() + vargs + " -o " + dir + "/mpi.h5", dir + "/mpi.log"), 0)
      << slurp(dir + "/mpi.log");
  expect_identical(serial, read(dir + "/mpi.h5"), "mpirun -n 2");
#else
  GTEST_SKIP() << "built without MPI: the mpirun comparison is not run";
#endif
}

TEST_F(SweepCli, BadInputExits2) {
  EXPECT_EQ(run(exe() + " sweep " + scene + " --speed-min 30 --speed-max 20 -o " + dir + "/x.h5",
                dir + "/bad.log"),
            2);
  EXPECT_EQ(run(exe() + " sweep " + scene + " --speed-min 30 --speed-max 40 --k 0 -o " + dir +
                    "/x.h5",
                dir + "/bad.log"),
            2);
}

}  // namespace
}  // namespace ferro::scenarios::analysis
