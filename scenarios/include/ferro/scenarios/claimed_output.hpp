#pragma once
// The output file of a verb, claimed before anything is computed (so a path that would be
// refused is refused at once), and the folder of its pictures checked for writing.

#include <string>
#include <vector>

#include "ferro/scenarios/output_file.hpp"

namespace ferro::scenarios {

/// `<stem><suffix>` in the folder of `file` (e.g. out/run.h5, "_plots" -> out/run_plots).
[[nodiscard]] std::string sibling(const std::string& file, const std::string& suffix);

/// Throws std::invalid_argument ("<what>: cannot write the plots in '<dir>': <why>") unless files
/// can be created in the folder `dir`; folders missing on the way are made for the test and
/// removed again.
void check_plot_folder(const std::string& dir, const std::string& what);

/// One output written as <file>.part and given its name by file->commit(); the `inputs` are
/// never written, an existing file only with `overwrite`. Unless `no_plots`, the plot folder
/// <stem>_plots beside it is checked (check_plot_folder) when claiming.
struct ClaimedOutput {
  OutputSet set;
  OutputFile* file = nullptr;
  /// `option` names the output in messages ("-o", "output").
  ClaimedOutput(const std::string& path, const char* option, bool overwrite,
                std::vector<std::string> inputs, bool no_plots);
  /// The output a verb's -o names (`given`), or when none `fallback` (named "output").
  [[nodiscard]] static ClaimedOutput given_or(const std::string& given, const std::string& fallback,
                                              bool overwrite, std::vector<std::string> inputs,
                                              bool no_plots);
  /// Commits the file; returns its path.
  const std::string& commit();
  [[nodiscard]] const std::string& path() const { return file->path(); }
  [[nodiscard]] const std::string& write_path() const { return file->write_path(); }
};

}  // namespace ferro::scenarios
