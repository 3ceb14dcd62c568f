#include <CLI/CLI.hpp>

#include "ferro/scenarios/cli.hpp"

namespace ferro::cli {

void add_scene_commands(CLI::App& app, VerbHandler& handler) {
  // Filled in by the foundation work (run, eig, plot, validate).
  (void)app;
  (void)handler;
}

}  // namespace ferro::cli
