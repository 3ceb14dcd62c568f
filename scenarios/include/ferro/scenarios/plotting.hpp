#pragma once
// Running the plotting scripts in tools/ (Debian's python3-matplotlib, python3-h5py).

#include <functional>
#include <string>
#include <vector>

namespace ferro::scenarios {

/// Python interpreter for the plots: $FERRO_PYTHON, else Debian's /usr/bin/python3 (where
/// python3-matplotlib and python3-h5py install), else python3 from PATH.
[[nodiscard]] std::string python_program();

/// Path of a script shipped in tools/ (e.g. "ferroplot.py"): $FERRO_TOOLS_DIR, beside the
/// installed program (<prefix>/share/ferrodyn for <prefix>/libexec/ferrodyn/ferrodyn), or the
/// source tree's tools/. Throws std::runtime_error
/// naming the places looked at when none has it.
[[nodiscard]] std::string tool_script(const std::string& name);

/// run_program() when `should_stop` fired: the program was ended (SIGTERM).
inline constexpr int kProgramStopped = -2;

/// Runs a program with arguments (no shell); returns its exit status, or -1 when it could not
/// be started or did not exit normally. With `should_stop`, polled every 20 ms while it runs:
/// true ends the program and returns kProgramStopped.
int run_program(const std::vector<std::string>& argv,
                const std::function<bool()>& should_stop = {});

/// Runs `python_program() tool_script(script) args...`; returns the exit status. Exit status 3
/// of the scripts: python3-matplotlib or python3-h5py is missing.
int run_python_tool(const std::string& script, const std::vector<std::string>& args,
                    const std::function<bool()>& should_stop = {});

}  // namespace ferro::scenarios
