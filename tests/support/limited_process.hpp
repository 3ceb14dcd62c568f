#pragma once
// A child process started with resource limits (setrlimit in the child before exec) and,
// optionally, SIGINT and SIGTERM blocked from the start: how the tests put ferrodyn on a "full
// disk" (RLIMIT_FSIZE), give it little memory (RLIMIT_AS), or deliver a signal before it could
// possibly have installed a handler. Its stdout and stderr go to one pipe.
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace ferro::test {

struct Limit {
  int resource;      // RLIMIT_FSIZE, RLIMIT_AS, ...
  rlim_t bytes;
};

class LimitedProcess {
 public:
  LimitedProcess(const std::vector<std::string>& args, const std::vector<Limit>& limits,
                 bool block_stop_signals = false) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    // Closed by the exec: the constructor returns once the child runs the program (a signal sent
    // right after reaches the program, not the forked test process before its exec).
    int started[2];
    if (pipe2(started, O_CLOEXEC) != 0) throw std::runtime_error("pipe2 failed");
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    // Blocked before fork, so the child is born with the mask: no window in which a signal could
    // reach it unblocked. The parent restores its own mask right after.
    sigset_t stop, previous;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    if (block_stop_signals) pthread_sigmask(SIG_BLOCK, &stop, &previous);
    pid_ = fork();
    if (pid_ != 0 && block_stop_signals) pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      close(started[0]);
      dup2(fds[1], 1);
      dup2(fds[1], 2);
      close(fds[0]);
      close(fds[1]);
      for (const Limit& l : limits) {
        const rlimit r{l.bytes, l.bytes};
        if (setrlimit(l.resource, &r) != 0) _exit(120);
      }
      execv(argv[0], argv.data());
      _exit(127);
    }
    close(fds[1]);
    close(started[1]);
    char byte = 0;
    while (read(started[0], &byte, 1) < 0 && errno == EINTR) {
    }
    close(started[0]);
    out_ = fdopen(fds[0], "r");
  }
  ~LimitedProcess() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (out_ != nullptr) fclose(out_);
  }
  LimitedProcess(const LimitedProcess&) = delete;
  LimitedProcess& operator=(const LimitedProcess&) = delete;

  /// Next output line, or false at end of stream.
  bool read_line(std::string& line) {
    std::array<char, 4096> buf{};
    if (std::fgets(buf.data(), buf.size(), out_) == nullptr) return false;
    line = buf.data();
    output_ += line;
    return true;
  }
  void signal(int sig) const { kill(pid_, sig); }
  /// Waits (up to `seconds`) until the program has SIGINT and SIGTERM blocked or caught by a
  /// handler, as read from /proc/PID/status (SigBlk, SigCgt): from then on a stop signal can no
  /// longer end it by the default action. False if that did not happen in time or the process
  /// is gone.
  [[nodiscard]] bool wait_until_stop_signals_blocked(double seconds) const {
    const unsigned long long mask = (1ULL << (SIGINT - 1)) | (1ULL << (SIGTERM - 1));
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    const std::string status = "/proc/" + std::to_string(pid_) + "/status";
    while (std::chrono::steady_clock::now() < until) {
      FILE* f = std::fopen(status.c_str(), "r");
      if (f == nullptr) return false;
      std::array<char, 256> line{};
      unsigned long long blocked = 0, caught = 0, value = 0;
      while (std::fgets(line.data(), line.size(), f) != nullptr) {
        if (std::sscanf(line.data(), "SigBlk: %llx", &value) == 1) blocked = value;
        if (std::sscanf(line.data(), "SigCgt: %llx", &value) == 1) caught = value;
      }
      std::fclose(f);
      if ((blocked & mask) == mask || (caught & mask) == mask) return true;
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    return false;
  }
  /// Reads the rest of the output, waits; returns the exit code (128 + signal when killed).
  int wait() {
    std::string line;
    while (read_line(line)) {
    }
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    killed_ = WIFSIGNALED(status);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  /// wait(), but a program still running after `seconds` is killed (SIGKILL: 137).
  int wait_for(double seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    int status = 0;
    while (waitpid(pid_, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > until) {
        kill(pid_, SIGKILL);
        waitpid(pid_, &status, 0);
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    pid_ = -1;
    killed_ = WIFSIGNALED(status);
    std::string line;
    while (read_line(line)) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  /// After wait() or wait_for(): the program was ended by a signal's default action (it did not
  /// exit by itself, e.g. through a handler's _exit(128 + signal)).
  [[nodiscard]] bool killed_by_signal() const { return killed_; }
  /// Everything read so far.
  [[nodiscard]] const std::string& output() const { return output_; }

 private:
  pid_t pid_ = -1;
  bool killed_ = false;
  FILE* out_ = nullptr;
  std::string output_;
};

}  // namespace ferro::test
