#pragma once
// Running the ferrodyn program from tests: capture its output and exit code, or start it in the
// background with its stderr on a pipe.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace ferro::test {

/// The ferrodyn program the tests run: $FERRODYN_TEST_EXE when set (another build of it, e.g.
/// to see a test fail on an older program), else the one built with the tests.
inline std::string ferrodyn_exe() {
  const char* other = std::getenv("FERRODYN_TEST_EXE");
  return other != nullptr && *other != '\0' ? other : FERRODYN_EXE;
}

struct ProcessResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr interleaved
};

inline std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// Runs `args` (args[0] = program) through the shell, capturing stdout+stderr. With
/// `timeout_seconds` > 0 the program is ended (SIGKILL) after that long: exit code 137.
inline ProcessResult run_capture(const std::vector<std::string>& args, double timeout_seconds = 0) {
  std::string cmd;
  if (timeout_seconds > 0) cmd = "timeout -s KILL " + std::to_string(timeout_seconds) + " ";
  for (const auto& a : args) cmd += shell_quote(a) + " ";
  cmd += "2>&1";
  ProcessResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) throw std::runtime_error("popen failed");
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), p) != nullptr) r.output += buf.data();
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// A background process whose stderr is read line by line.
class BackgroundProcess {
 public:
  explicit BackgroundProcess(const std::vector<std::string>& args) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, fds[1], 2);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addclose(&fa, fds[0]);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0], &fa, nullptr, argv.data(), environ) != 0) {
      throw std::runtime_error("posix_spawn failed for " + args[0]);
    }
    posix_spawn_file_actions_destroy(&fa);
    close(fds[1]);
    err_ = fdopen(fds[0], "r");
  }
  ~BackgroundProcess() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (err_ != nullptr) fclose(err_);
  }
  /// Next stderr line, or false at end of stream.
  bool read_line(std::string& line) {
    std::array<char, 4096> buf{};
    if (std::fgets(buf.data(), buf.size(), err_) == nullptr) return false;
    line = buf.data();
    return true;
  }
  void signal(int sig) const { kill(pid_, sig); }
  /// Waits for exit; returns the exit code (128 + signal when killed by one).
  int wait() {
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

 private:
  pid_t pid_ = -1;
  FILE* err_ = nullptr;
};

}  // namespace ferro::test
