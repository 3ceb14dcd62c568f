#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <exception>
#include <iostream>

#include "ferro/scenarios/cli.hpp"

namespace ferro::cli {

int run_main(int argc, char** argv) {
  CLI::App app{"ferrodyn: railway vehicle dynamics with a research-grade wheel-rail contact layer"};
  app.set_version_flag("--version", std::string("ferrodyn ") + FERRO_VERSION);
  app.require_subcommand(1);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return 0;
}

}  // namespace ferro::cli
