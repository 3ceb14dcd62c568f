// ferrodyn: the command-line program (run_main; the entry point is ferrodyn_main.cpp). Each verb
// group is one file in this folder.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <exception>
#include <iostream>
#include <stdexcept>

#include "cli.hpp"
#include "terminal.hpp"

namespace ferro::cli {

int run_main(int argc, char** argv) {
  // Signals: caught from the first instant (see InterruptGuard); a file size limit makes writes
  // fail with EFBIG, reported as an error, instead of killing the process.
  const InterruptGuard interrupt;
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"ferrodyn: railway vehicle dynamics with a research-grade wheel-rail contact layer"};
  app.set_version_flag("--version", std::string("ferrodyn ") + FERRO_VERSION);
  app.require_subcommand(1);
  VerbHandler handler;
  add_scene_commands(app, handler);
  add_contact_commands(app, handler);
  add_geometry_commands(app, handler);
  add_mim_commands(app, handler);
  add_mim_table_commands(app, handler);
  add_wheelset_contact_commands(app, handler);
  add_bench_commands(app, handler);
  add_fe_kij_commands(app, handler);
  add_analysis_commands(app, handler);
  strict_values(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  if (!handler) return kExitOk;
  // A verb stopped by a signal exits with 128 + signal whatever its own code.
  const auto code = [](int own) {
    const int sig = InterruptGuard::signal_received();
    return sig != 0 && own != kExitOk ? 128 + sig : own;
  };
  try {
    return code(handler());
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "ferrodyn: error: {}\n", e.what());
    return code(kExitBadInput);
  } catch (const std::bad_alloc&) {
    fmt::print(stderr,
               "ferrodyn: failure: out of memory: the work asked for more memory than this "
               "machine gives the program\n");
    return code(kExitRunFailure);
  } catch (const std::exception& e) {
    fmt::print(stderr, "ferrodyn: failure: {}\n", e.what());
    return code(kExitRunFailure);
  } catch (...) {
    fmt::print(stderr, "ferrodyn: failure: an unexpected error (not a standard exception)\n");
    return code(kExitRunFailure);
  }
}

}  // namespace ferro::cli
