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

/// `<stem><suffix>` in the folder of `file` (e.g. out/run.h5, "_plots" -> out/run_plots).
[[nodiscard]] std::string sibling(const std::string& file, const std::string& suffix);

/// Draws the pictures of a ferrodyn HDF5 file with ferroplot.py (mode timeseries, eigen or
/// auto; `signals` empty: the script's choice) into `dir` (empty: <stem>_plots beside the file);
/// returns the script's exit status.
int plot_file(const std::string& mode, const std::string& h5,
              const std::vector<std::string>& signals = {}, std::string dir = {},
              const std::string& format = "png,svg");

/// After a verb's report: plot_file, then "  plots     DIR/" on stdout, or a warning on stderr
/// (the results in the file are complete either way).
void plot_after_report(const std::string& mode, const std::string& h5,
                       const std::vector<std::string>& signals = {}, const std::string& dir = {});

/// Runs tools/plot_contact.py (mode "curves" or "patch"). Throws std::runtime_error naming the
/// interpreter when it fails.
void run_plot_script(const std::string& mode, const std::string& csv, const std::string& png,
                     const std::string& title);

}  // namespace ferro::cli
