#pragma once
// Running the plotting scripts in tools/ (Debian's python3-matplotlib, python3-h5py): the
// program draws its pictures in a child process; the library never starts one.

#include <string>
#include <vector>

namespace ferro::cli {

/// Python interpreter for the plots: $FERRO_PYTHON, else Debian's /usr/bin/python3 (where
/// python3-matplotlib and python3-h5py install), else python3 from PATH.
[[nodiscard]] std::string python_program();

/// Path of a script shipped in tools/ (e.g. "ferroplot.py"): $FERRO_TOOLS_DIR, next to the
/// installed program (share/ferrodyn), or the source tree's tools/. Throws std::runtime_error
/// naming the places looked at when none has it.
[[nodiscard]] std::string tool_script(const std::string& name);

/// Runs a program with arguments (no shell); returns its exit status, or -1 when it could not
/// be started or did not exit normally.
int run_program(const std::vector<std::string>& argv);

/// Runs `python_program() tool_script(script) args...`; returns the exit status.
int run_python_tool(const std::string& script, const std::vector<std::string>& args);

/// Runs tools/plot_contact.py (mode "curves" or "patch"). Throws std::runtime_error naming the
/// interpreter when it fails.
void run_plot_script(const std::string& mode, const std::string& csv, const std::string& png,
                     const std::string& title);

}  // namespace ferro::cli
