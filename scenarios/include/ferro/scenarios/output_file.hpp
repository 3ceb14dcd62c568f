#pragma once
// Output files that cannot lose data. Each output of a verb is claimed before anything is
// computed: a path that is one of the verb's inputs or another of its outputs is refused, and
// so is an existing file unless the verb may overwrite (--overwrite). A claimed output is
// written under a temporary name in its own folder (<name>.<pid>.part) and renamed to its name
// once complete, so the name holds either what was there before or a whole new file, never a
// truncated or half-written one; two programs writing one name cannot corrupt it. Devices
// (e.g. /dev/null) are written in place.
//
// Library code: errors are exceptions (std::invalid_argument for a refused path, naming the
// option; std::runtime_error for a folder that cannot be written).

#include <memory>
#include <string>
#include <vector>

namespace ferro::scenarios {

/// What one invocation of a verb may write.
struct OutputRules {
  bool overwrite = false;           ///< replace existing files (--overwrite)
  std::vector<std::string> inputs;  ///< files the verb reads: never written
};

class OutputFile {
 public:
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// Removes the temporary file unless it was committed.
  ~OutputFile();

  /// The name the output gets.
  [[nodiscard]] const std::string& path() const { return path_; }
  /// Where to write it now (the temporary file, or path() for a device).
  [[nodiscard]] const std::string& write_path() const { return write_path_; }
  /// Renames the temporary file to path(). Without overwrite, a file created at path() while
  /// this one was being written is kept: the call then throws std::runtime_error naming the
  /// temporary file, which is kept too. Idempotent.
  void commit();

 private:
  friend class OutputSet;
  OutputFile(std::string path, std::string write_path, bool overwrite);
  std::string path_, write_path_;
  bool overwrite_ = false;
  bool committed_ = false;
  int slot_ = -1;  // pending-output registry slot
};

/// The outputs of one invocation.
class OutputSet {
 public:
  explicit OutputSet(OutputRules rules);
  /// Claims `path` and creates its temporary file (making the folder). `what` names the output
  /// in messages (e.g. "-o", "--csv", "output.file"). Throws std::invalid_argument for an empty
  /// path, a folder, an input, another output of this set, or an existing file without
  /// overwrite; std::runtime_error when the folder cannot be written.
  OutputFile& claim(const std::string& path, const std::string& what);
  /// The checks of claim() without creating anything.
  void check(const std::string& path, const std::string& what) const;
  /// Commits every claimed output.
  void commit_all();
  [[nodiscard]] const OutputRules& rules() const { return rules_; }

 private:
  OutputRules rules_;
  std::vector<std::unique_ptr<OutputFile>> files_;
};

/// True when `a` and `b` name the same file (the same inode when both exist, else the same
/// normalised absolute path).
[[nodiscard]] bool same_file(const std::string& a, const std::string& b);

/// Removes the temporary files of every output of this process that is not committed. Only
/// unlink(2): async-signal-safe, for a program ending on a signal.
void remove_pending_outputs() noexcept;

}  // namespace ferro::scenarios
