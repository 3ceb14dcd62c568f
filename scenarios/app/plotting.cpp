#include "plotting.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "cli.hpp"
#include "ferro/scenarios/claimed_output.hpp"
#include "terminal.hpp"

extern char** environ;

namespace ferro::cli {

std::string python_program() {
  if (const char* env = std::getenv("FERRO_PYTHON"); env != nullptr && *env != '\0') return env;
  if (std::filesystem::exists("/usr/bin/python3")) return "/usr/bin/python3";
  return "python3";
}

std::string tool_script(const std::string& name) {
  namespace fs = std::filesystem;
  std::vector<fs::path> places;
  if (const char* env = std::getenv("FERRO_TOOLS_DIR"); env != nullptr && *env != '\0') {
    places.emplace_back(fs::path(env) / name);
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  // The program runs from <prefix>/libexec/ferrodyn/ (the `ferrodyn` command in bin/ starts it).
  if (!ec) {
    places.push_back(exe.parent_path().parent_path().parent_path() / "share" / "ferrodyn" / name);
  }
  places.push_back(fs::path(FERRO_SOURCE_DIR) / "tools" / name);
  places.push_back(fs::path(FERRO_INSTALL_DATADIR) / name);
  std::string looked;
  for (const auto& p : places) {
    if (fs::exists(p)) return p.string();
    looked += (looked.empty() ? "" : ", ") + p.string();
  }
  throw std::runtime_error(fmt::format("plotting script {} not found (looked in {})", name, looked));
}

int run_program(const std::vector<std::string>& argv, const std::function<bool()>& should_stop) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, args[0], nullptr, nullptr, args.data(), environ) != 0) return -1;
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, should_stop ? WNOHANG : 0);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return -1;
    if (should_stop && should_stop()) {
      kill(pid, SIGTERM);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      return kProgramStopped;
    }
    if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int run_python_tool(const std::string& script, const std::vector<std::string>& args,
                    const std::function<bool()>& should_stop) {
  std::vector<std::string> argv = {python_program(), tool_script(script)};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_program(argv, should_stop);
}

int plot_file(const std::string& mode, const std::string& h5,
              const std::vector<std::string>& signals, const std::string& dir,
              const std::string& format) {
  std::vector<std::string> args = {mode, h5, "--out", dir, "--format", format};
  if (!signals.empty()) {
    args.emplace_back("--signals");
    args.insert(args.end(), signals.begin(), signals.end());
  }
  return run_python_tool("ferroplot.py", args, [] { return InterruptGuard::stop_now(); });
}

int plot_after_report(const std::string& mode, const std::string& h5,
                      const std::vector<std::string>& signals, const std::string& dir, int code) {
  std::fflush(stdout);  // the report before the script's list of files
  const std::string folder = dir.empty() ? scenarios::sibling(h5, "_plots") : dir;
  const int rc = plot_file(mode, h5, signals, folder);
  if (rc == kProgramStopped) return 128 + InterruptGuard::signal_received();
  if (rc == 0) {
    fmt::print("  plots     {}/\n", folder);
  } else if (rc == kPlotsNeedPython) {
    fmt::print(stderr,
               "ferrodyn: warning: no plots: python3 with matplotlib and h5py needed; the "
               "results in {} are complete\n",
               h5);
  } else {
    fmt::print(stderr,
               "ferrodyn: warning: plotting failed (exit status {}, see above); the results in {} "
               "are complete\n",
               rc, h5);
  }
  return code;
}

void draw(const std::string& script, const std::vector<std::string>& args,
          const std::string& written) {
  if (run_python_tool(script, args) == 0) return;
  throw std::runtime_error(fmt::format("plotting failed ({} tools/{} {}); {}", python_program(),
                                       script, fmt::join(args, " "), written));
}

}  // namespace ferro::cli
