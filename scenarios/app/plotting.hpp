#pragma once
// Running the plotting scripts in tools/ (Debian's python3-matplotlib, python3-h5py): the
// program draws its pictures in a child process; the library never starts one.

#include <functional>
#include <string>
#include <vector>

namespace ferro::cli {

/// Python interpreter for the plots: $FERRO_PYTHON, else Debian's /usr/bin/python3 (where
/// python3-matplotlib and python3-h5py install), else python3 from PATH.
[[nodiscard]] std::string python_program();

/// Path of a script shipped in tools/ (e.g. "ferroplot.py"): $FERRO_TOOLS_DIR, beside the
/// installed program (<prefix>/share/ferrodyn for <prefix>/libexec/ferrodyn/ferrodyn-program), or the
/// source tree's tools/. Throws std::runtime_error naming the places looked at when none has it.
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

/// Draws a verb's pictures with run_python_tool. Throws std::runtime_error ("plotting failed
/// (<python> tools/<script> <args>); <written>") unless the script succeeds; `written` says
/// which of the verb's data files are complete.
void draw(const std::string& script, const std::vector<std::string>& args,
          const std::string& written);


/// Draws the pictures of a ferrodyn HDF5 file with ferroplot.py (mode timeseries, eigen or
/// auto; `signals` empty: the script's choice) into the folder `dir`; returns the script's exit
/// status, kProgramStopped when a stop request ended it.
int plot_file(const std::string& mode, const std::string& h5,
              const std::vector<std::string>& signals, const std::string& dir,
              const std::string& format = "png,svg");

/// After a verb's report: plot_file, then "  plots     DIR/" on stdout, or a warning on stderr
/// (the results in the file are complete either way). Returns the verb's exit code: `code`, or
/// 128 + signal when a stop request ended the plotting.
int plot_after_report(const std::string& mode, const std::string& h5,
                      const std::vector<std::string>& signals = {}, const std::string& dir = {},
                      int code = 0);

}  // namespace ferro::cli
