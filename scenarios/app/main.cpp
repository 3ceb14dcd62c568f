// ferrodyn: the command-line program. Each verb group is one file in this folder.
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
  InterruptGuard interrupt;
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  if (!handler) return kExitOk;
  if (!InterruptGuard::claimed()) interrupt.release();
  try {
    return handler();
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "ferrodyn: error: {}\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ferrodyn: failure: {}\n", e.what());
    return kExitRunFailure;
  }
}

}  // namespace ferro::cli

int main(int argc, char** argv) { return ferro::cli::run_main(argc, argv); }
