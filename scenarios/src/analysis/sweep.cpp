// Sweeps of independent runs over threads, with a durable per-point journal (see the header).
#include "ferro/scenarios/analysis/sweep.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "ferro/io/csv.hpp"
#include "ferro/scenarios/h5_output.hpp"
#include "ferro/scenarios/model_factory.hpp"
#include "ferro/scenarios/run.hpp"

namespace ferro::scenarios::analysis {

namespace fs = std::filesystem;

namespace {

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

Oscillation outcome_from(const std::string& s, const std::string& where) {
  for (auto o : {Oscillation::kDecayed, Oscillation::kSteady, Oscillation::kDiverged,
                 Oscillation::kGrowing, Oscillation::kDecaying, Oscillation::kApproaching})
    if (to_string(o) == s) return o;
  throw std::invalid_argument(fmt::format("{}: unknown outcome '{}'", where, s));
}

void write_durably(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw std::runtime_error(fmt::format("cannot write '{}'", tmp.string()));
  const bool ok = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) &&
                  ::fsync(fd) == 0;
  ::close(fd);
  if (!ok) throw std::runtime_error(fmt::format("cannot write '{}' (disk full?)", tmp.string()));
  fs::rename(tmp, path);
  const int dir = ::open(path.parent_path().c_str(), O_RDONLY | O_DIRECTORY);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

}  // namespace

std::string serialize(const SweepPointResult& r) {
  std::string s = fmt::format("{} {:.17g} {:.17g} {:.17g} {} {} {:.17g} {:.17g} {} {:.17g} {}",
                              r.index, r.point.speed, r.point.k.k11, r.point.k.k22,
                              to_string(r.outcome), r.holder, r.period, r.time, r.rhs_evaluations,
                              r.cpu_seconds, r.amplitude.size());
  for (double a : r.amplitude) s += fmt::format(" {:.17g}", a);
  return s;
}

SweepPointResult deserialize(const std::string& line, const std::string& where) {
  const std::vector<std::string> cells = io::split_cells(line, io::CsvFormat::blanks());
  const auto malformed = [&](const char* what) {
    return std::invalid_argument(fmt::format("{}: {} sweep record", where, what));
  };
  const auto number = [&](std::size_t i) {
    const std::optional<double> v = io::parse_number(cells[i]);
    if (!v) throw malformed("malformed");
    return *v;
  };
  const auto count = [&](std::size_t i) {
    const double v = number(i);
    if (!(v >= 0.0 && v <= 1e15 && v == std::floor(v))) throw malformed("malformed");
    return static_cast<std::size_t>(v);
  };
  if (cells.size() < 11) throw malformed("malformed");
  SweepPointResult r;
  r.index = count(0);
  r.point.speed = number(1);
  r.point.k = contact::ReductionFactors::following_k22(number(2), number(3));
  r.outcome = outcome_from(cells[4], where);
  r.holder = count(5);
  r.period = number(6);
  r.time = number(7);
  r.rhs_evaluations = static_cast<long>(count(8));
  r.cpu_seconds = number(9);
  const std::size_t n = count(10);
  if (n > 1000 || (n > 0 && r.holder >= n)) throw malformed("malformed");
  if (cells.size() != 11 + n) throw malformed("truncated");
  r.amplitude.resize(n);
  for (std::size_t i = 0; i < n; ++i) r.amplitude[i] = number(11 + i);
  return r;
}

SweepPointResult run_sweep_point(const Scene& scene, const ModelResources& resources,
                                 std::size_t index, const SweepPoint& point, double lateral_offset,
                                 SettleOptions options) {
  const double cpu0 = thread_cpu_seconds();
  Scene s = with_reduction(scene, point.k);
  s.simulation.acceleration = 0.0;
  const auto system = build_system(s, point.speed, resources);
  const auto lateral = lateral_states(*system);
  options.observed = lateral.index;
  const auto x0 = disturbed_state(s, *system, lateral_offset);
  const auto run = run_until_settled(*system, x0, options);
  SweepPointResult r;
  r.index = index;
  r.point = point;
  r.outcome = run.outcome;
  r.holder = run.holder;
  r.amplitude = run.amplitude;
  r.period = run.period;
  r.time = run.time;
  r.rhs_evaluations = run.rhs_evaluations;
  r.cpu_seconds = thread_cpu_seconds() - cpu0;
  return r;
}

SweepJournal::SweepJournal(std::string folder, const std::string& signature)
    : folder_(std::move(folder)) {
  fs::create_directories(folder_);
  const fs::path sig = fs::path(folder_) / "signature";
  const std::string digest = fmt::format("{:016x}\n", std::hash<std::string>{}(signature));
  if (fs::exists(sig)) {
    std::ifstream in(sig);
    const std::string old((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (old != digest)
      throw std::invalid_argument(fmt::format(
          "resume folder '{}' belongs to a different sweep (scene or options changed); remove "
          "it or choose another output",
          folder_));
  } else {
    write_durably(sig, digest);
  }
}

std::map<std::size_t, SweepPointResult> SweepJournal::load() const {
  std::map<std::size_t, SweepPointResult> out;
  for (const auto& e : fs::directory_iterator(folder_)) {
    const auto name = e.path().filename().string();
    if (name.rfind("point_", 0) != 0 || e.path().extension() != ".txt") continue;
    io::CsvReader record =
        io::CsvReader::open(e.path().string(), io::CsvFormat::blanks(), "sweep record");
    std::string line;
    if (!record.next_line(line)) throw std::invalid_argument(record.located("empty sweep record"));
    auto r = deserialize(line, e.path().string());
    out[r.index] = std::move(r);
  }
  return out;
}

void SweepJournal::record(const SweepPointResult& r) const {
  write_durably(fs::path(folder_) / fmt::format("point_{:06d}.txt", r.index), serialize(r) + "\n");
}

void parallel_for(std::size_t n, const std::function<void(std::size_t)>& body, int jobs,
                  const std::function<bool()>& should_stop) {
  if (jobs < 1) throw std::invalid_argument("--jobs: must be >= 1");
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::mutex error_mutex;
  std::exception_ptr error;
  const auto worker = [&] {
    while (!stop) {
      if (should_stop && should_stop()) {
        stop = true;
        break;
      }
      const std::size_t k = next++;
      if (k >= n) break;
      try {
        body(k);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        stop = true;
      }
    }
  };
  const auto threads_wanted = std::min<std::size_t>(static_cast<std::size_t>(jobs), std::max<std::size_t>(1, n));
  std::vector<std::thread> threads;
  for (std::size_t i = 1; i < threads_wanted; ++i) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}

std::vector<SweepPointResult> run_pool(const std::vector<std::size_t>& todo,
                                       const std::function<SweepPointResult(std::size_t)>& run,
                                       const PoolOptions& options) {
  std::vector<std::optional<SweepPointResult>> slots(todo.size());
  std::mutex done_mutex;
  parallel_for(
      todo.size(),
      [&](std::size_t k) {
        auto r = run(todo[k]);
        std::lock_guard lock(done_mutex);
        if (options.on_done) options.on_done(r);
        slots[k] = std::move(r);
      },
      options.jobs, options.should_stop);
  std::vector<SweepPointResult> out;
  for (auto& s : slots)
    if (s) out.push_back(std::move(*s));
  return out;
}

void write_sweep(const Scene& scene, const std::vector<std::string>& wheelset_names,
                 const std::vector<SweepPointResult>& results, const std::string& path) {
  H5File file = H5File::create(path);
  file.set_attribute("/", "program", std::string("ferrodyn"));
  file.set_attribute("/", "created_utc", utc_timestamp());
  file.set_attribute("/", "kind", std::string("sweep"));
  file.set_attribute("/", "scene_file", scene.path);
  file.set_attribute("/", "scene_name", scene.name);
  file.write_text("/scene/text", scene.text);
  std::vector<double> v, k11, k22, outcome, holder, period, time, cpu, amp;
  const std::size_t m = wheelset_names.size();
  for (const auto& r : results) {
    v.push_back(r.point.speed);
    k11.push_back(r.point.k.k11);
    k22.push_back(r.point.k.k22);
    outcome.push_back(static_cast<double>(r.outcome));
    holder.push_back(static_cast<double>(r.holder));
    period.push_back(r.period);
    time.push_back(r.time);
    cpu.push_back(r.cpu_seconds);
    for (std::size_t j = 0; j < m; ++j) amp.push_back(j < r.amplitude.size() ? r.amplitude[j] : NAN);
  }
  file.write_vector("/sweep/speed", v, "m/s", "forward speed");
  file.write_vector("/sweep/k11", k11, "-", "reduction factor on C11");
  file.write_vector("/sweep/k22", k22, "-", "reduction factor on C22");
  file.write_vector("/sweep/outcome", outcome, "-", "see attribute outcome_codes");
  file.write_vector("/sweep/holder", holder, "-",
                    "index (0-based, attribute wheelsets) of the wheelset holding the outcome");
  file.write_vector("/sweep/period", period, "s", "limit-cycle period of the holding wheelset");
  file.write_vector("/sweep/time", time, "s", "simulated time");
  file.write_vector("/sweep/cpu_time", cpu, "s", "CPU time of the point");
  file.write_matrix("/sweep/amplitude", amp, results.size(), m, "m",
                    "steady lateral amplitude (peak-to-peak/2), points x wheelsets");
  std::string names;
  for (const auto& n : wheelset_names) names += (names.empty() ? "" : ",") + n;
  file.set_attribute("/sweep", "wheelsets", names);
  file.set_attribute(
      "/sweep", "outcome_codes",
      std::string("0 decayed, 1 steady, 2 diverged, 3 growing, 4 decaying, 5 approaching"));
  file.set_attribute("/", "status", std::string("completed"));
}

}  // namespace ferro::scenarios::analysis
