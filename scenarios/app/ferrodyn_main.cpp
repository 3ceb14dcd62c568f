// ferrodyn: the command-line program. Each verb group is one file in this folder.
#include <CLI/CLI.hpp>

#include "cli.hpp"

int main(int argc, char** argv) {
  return ferro::cli::run_main(argc, argv);
}
