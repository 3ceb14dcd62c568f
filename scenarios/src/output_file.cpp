#include "ferro/scenarios/output_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace ferro::scenarios {
namespace {

namespace fs = std::filesystem;

// Temporary outputs not committed yet, for remove_pending_outputs(): fixed storage, so that a
// signal handler can read it without allocating.
constexpr std::size_t kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
struct PendingSlot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 holds a path
  std::array<char, kPathBytes> path{};
};
std::array<PendingSlot, kSlots> g_pending;

int register_pending(const std::string& path) {
  if (path.size() >= kPathBytes) return -1;
  for (std::size_t i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (g_pending[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(g_pending[i].path.data(), path.c_str(), path.size() + 1);
      g_pending[i].state.store(2);
      return static_cast<int>(i);
    }
  }
  return -1;
}

void unregister_pending(int slot) {
  if (slot >= 0) g_pending[static_cast<std::size_t>(slot)].state.store(0);
}

bool is_device(const std::string& path) {
  std::error_code ec;
  const auto st = fs::status(path, ec);
  return !ec && fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st);
}

// Renames without replacing an existing `to`: false (errno EEXIST) when `to` exists.
bool rename_no_replace(const std::string& from, const std::string& to) {
  if (renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
  if (errno != EINVAL && errno != ENOSYS) return false;
  // File systems without RENAME_NOREPLACE: a hard link fails on an existing name.
  if (link(from.c_str(), to.c_str()) == 0) {
    unlink(from.c_str());
    return true;
  }
  if (errno == EEXIST) return false;
  struct stat st {};
  if (stat(to.c_str(), &st) == 0) {
    errno = EEXIST;
    return false;
  }
  return std::rename(from.c_str(), to.c_str()) == 0;
}

// The process id of a live program writing `path` under a temporary name (<name>.<pid>.part or
// <name>.<pid>-<n>.part beside it), or 0.
long live_writer(const std::string& path) {
  const fs::path target = fs::absolute(path);
  const std::string prefix = target.filename().string() + ".";
  std::error_code ec;
  for (fs::directory_iterator it(target.parent_path(), ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() + 5 || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - 5, 5, ".part") != 0)
      continue;
    char* digits_end = nullptr;
    const long pid = std::strtol(name.c_str() + prefix.size(), &digits_end, 10);
    if (pid <= 0 || pid == getpid() || (*digits_end != '.' && *digits_end != '-')) continue;
    if (kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM) return pid;
  }
  return 0;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec1, ec2;
  if (fs::exists(a, ec1) && fs::exists(b, ec2)) {
    std::error_code ec;
    const bool eq = fs::equivalent(a, b, ec);
    if (!ec) return eq;
  }
  std::error_code ec;
  const fs::path pa = fs::weakly_canonical(fs::absolute(a), ec);
  const fs::path pb = fs::weakly_canonical(fs::absolute(b), ec);
  return pa.lexically_normal() == pb.lexically_normal();
}

void remove_pending_outputs() noexcept {
  for (auto& slot : g_pending) {
    if (slot.state.load() == 2) unlink(slot.path.data());
  }
}

OutputFile::OutputFile(std::string path, std::string write_path, bool overwrite)
    : path_(std::move(path)), write_path_(std::move(write_path)), overwrite_(overwrite) {
  if (write_path_ != path_) slot_ = register_pending(write_path_);
}

OutputFile::~OutputFile() {
  if (!committed_ && write_path_ != path_) unlink(write_path_.c_str());
  unregister_pending(slot_);
}

void OutputFile::commit() {
  if (committed_) return;
  if (write_path_ != path_) {
    const bool ok = overwrite_ ? std::rename(write_path_.c_str(), path_.c_str()) == 0
                               : rename_no_replace(write_path_, path_);
    if (!ok) {
      const int error = errno;
      committed_ = true;  // keep the temporary file: it holds the results
      unregister_pending(slot_);
      slot_ = -1;
      if (error == EEXIST) {
        throw std::runtime_error(fmt::format(
            "'{}' was created by another program while this one was writing it; it is left as "
            "it is and the results of this one are in '{}'",
            path_, write_path_));
      }
      throw std::runtime_error(fmt::format("cannot rename '{}' to '{}': {}; the results are in "
                                           "'{}'",
                                           write_path_, path_, std::strerror(error), write_path_));
    }
  }
  committed_ = true;
  unregister_pending(slot_);
  slot_ = -1;
}

OutputSet::OutputSet(OutputRules rules) : rules_(std::move(rules)) {}

void OutputSet::check(const std::string& path, const std::string& what) const {
  if (path.empty()) throw std::invalid_argument(fmt::format("{}: empty output path", what));
  std::error_code ec;
  const auto st = fs::status(path, ec);
  if (fs::is_directory(st)) {
    throw std::invalid_argument(
        fmt::format("{}: '{}' is a folder; name a file", what, path));
  }
  for (const auto& input : rules_.inputs) {
    if (!input.empty() && same_file(path, input)) {
      throw std::invalid_argument(fmt::format(
          "{}: '{}' is an input of this run ({}); choose another output path", what, path,
          input));
    }
  }
  if (const long pid = live_writer(path); pid != 0) {
    throw std::invalid_argument(fmt::format(
        "{}: '{}' is being written by another program (process {}); wait for it or choose "
        "another path",
        what, path, pid));
  }
  for (const auto& f : files_) {
    if (same_file(path, f->path())) {
      throw std::invalid_argument(fmt::format(
          "{}: '{}' is already another output of this run; choose another path", what, path));
    }
  }
  if (fs::is_regular_file(st) && !rules_.overwrite) {
    throw std::invalid_argument(fmt::format(
        "{}: '{}' exists; pass --overwrite to replace it, or choose another path", what, path));
  }
}

OutputFile& OutputSet::claim(const std::string& path, const std::string& what) {
  check(path, what);
  if (is_device(path)) {
    files_.push_back(std::unique_ptr<OutputFile>(new OutputFile(path, path, true)));
    return *files_.back();
  }
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) {
      throw std::runtime_error(fmt::format("{}: cannot create the folder '{}': {}", what,
                                           target.parent_path().string(), ec.message()));
    }
  }
  // A fresh temporary name beside the target (same file system, so the rename is atomic).
  for (int attempt = 0;; ++attempt) {
    std::string temp = fmt::format("{}.{}{}.part", path, getpid(),
                                   attempt == 0 ? std::string() : fmt::format("-{}", attempt));
    const int fd = open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      close(fd);
      files_.push_back(
          std::unique_ptr<OutputFile>(new OutputFile(path, std::move(temp), rules_.overwrite)));
      return *files_.back();
    }
    if (errno != EEXIST || attempt > 100) {
      throw std::runtime_error(
          fmt::format("{}: cannot write '{}': {}", what, temp, std::strerror(errno)));
    }
  }
}

void OutputSet::commit_all() {
  for (auto& f : files_) f->commit();
}

}  // namespace ferro::scenarios
