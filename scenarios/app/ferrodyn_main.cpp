// ferrodyn: the command-line program. Each verb group lives in scenarios/src/cli/.
#include <CLI/CLI.hpp>

#include "ferro/scenarios/cli.hpp"

int main(int argc, char** argv) {
  return ferro::cli::run_main(argc, argv);
}
