#pragma once
// The ferrodyn command line. Each verb group registers its subcommands on the root app.

namespace CLI {
class App;
}

namespace ferro::cli {

/// Parses argv, runs the chosen verb, returns the process exit code.
/// Exit codes: 0 success, 1 run failure (solver, I/O), 2 bad input (scene, options),
/// 130 interrupted by SIGINT/SIGTERM (output kept).
int run_main(int argc, char** argv);

}  // namespace ferro::cli
