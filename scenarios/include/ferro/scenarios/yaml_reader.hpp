#pragma once
// Reading scene YAML into plain structs with errors a user can act on: every message names the
// file, line and column, the key path and what is allowed; unknown keys are errors with the
// nearest valid key suggested.

#include <yaml-cpp/yaml.h>

#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace ferro::scenarios {

/// Bad input in a YAML file. what() = "FILE:LINE:COL: KEY: MESSAGE".
class YamlInputError : public std::invalid_argument {
 public:
  YamlInputError(const std::string& file, int line, int column, const std::string& key,
                 const std::string& message);
  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] const std::string& key() const { return key_; }
  [[nodiscard]] int column() const { return column_; }
  /// The message without its location.
  [[nodiscard]] const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  int column_;
  std::string key_;
  std::string message_;
};

/// A parsed YAML file: its path, its text (kept for the output's metadata) and its root node.
struct YamlFile {
  std::string path;
  std::string text;
  YAML::Node root;
};

/// Reads and parses a file. Throws YamlInputError for a missing file or malformed YAML.
[[nodiscard]] YamlFile load_yaml_file(const std::string& path);
/// Parses text given in memory; `path` is used in messages.
[[nodiscard]] YamlFile parse_yaml_text(const std::string& text, const std::string& path);

/// Smallest edit distance candidate to `word` among `candidates`, or "" when none is close.
[[nodiscard]] std::string nearest_key(const std::string& word,
                                      const std::set<std::string>& candidates);

/// Reads one YAML mapping. Every accessor records the key as known; finish() then rejects keys
/// never asked for. Numbers must be finite unless allowed otherwise.
class MapReader {
 public:
  MapReader(YAML::Node node, std::string file, std::string path);

  [[nodiscard]] bool has(const std::string& key) const;
  /// Required number.
  [[nodiscard]] double number(const std::string& key);
  /// Optional number, `fallback` when absent. allow_infinite accepts .inf (e.g. max_step).
  [[nodiscard]] double number_or(const std::string& key, double fallback,
                                 bool allow_infinite = false);
  [[nodiscard]] long integer_or(const std::string& key, long fallback);
  /// Optional true/false, `fallback` when absent.
  [[nodiscard]] bool boolean_or(const std::string& key, bool fallback);
  [[nodiscard]] std::string string(const std::string& key,
                                   const std::vector<std::string>& allowed = {});
  [[nodiscard]] std::string string_or(const std::string& key, const std::string& fallback,
                                      const std::vector<std::string>& allowed = {});
  [[nodiscard]] std::vector<std::string> string_list_or(const std::string& key,
                                                        const std::vector<std::string>& fallback);
  /// Sub-mapping (required, or empty reader when optional and absent).
  [[nodiscard]] MapReader map(const std::string& key);
  [[nodiscard]] MapReader map_or_empty(const std::string& key);
  /// The raw node of a key (marks it known).
  [[nodiscard]] YAML::Node node(const std::string& key);
  /// Declares a key as valid without reading it.
  void allow(const std::string& key) { known_.insert(key); }

  /// Throws for the first key that no accessor asked for, suggesting the nearest known key.
  void finish() const;

  /// Error at this mapping (or at `key` when present).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] std::string key_path(const std::string& key) const;
  [[nodiscard]] const YAML::Node& yaml() const { return node_; }

 private:
  YAML::Node node_;
  std::string file_;
  std::string path_;
  std::set<std::string> known_;
  [[nodiscard]] YAML::Node require(const std::string& key);
};

/// Line/column (1-based) of a node, or of its parent when the node has no mark.
[[nodiscard]] std::pair<int, int> position_of(const YAML::Node& node);

}  // namespace ferro::scenarios
