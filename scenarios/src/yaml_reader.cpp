#include "ferro/scenarios/yaml_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ferro::scenarios {
namespace {

std::string describe(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsScalar()) return fmt::format("'{}'", n.Scalar());
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a mapping";
  return "an unknown node";
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

}  // namespace

YamlInputError::YamlInputError(const std::string& file, int line, int column,
                               const std::string& key, const std::string& message)
    : std::invalid_argument(line > 0
                                ? fmt::format("{}:{}:{}: {}: {}", file, line, column, key, message)
                                : fmt::format("{}: {}: {}", file, key, message)),
      file_(file),
      line_(line),
      key_(key) {}

std::pair<int, int> position_of(const YAML::Node& node) {
  if (!node.IsDefined()) return {0, 0};
  const YAML::Mark m = node.Mark();
  if (m.is_null()) return {0, 0};
  return {m.line + 1, m.column + 1};
}

YamlFile parse_yaml_text(const std::string& text, const std::string& path) {
  YamlFile f{path, text, {}};
  try {
    f.root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw YamlInputError(path, e.mark.line + 1, e.mark.column + 1, "(document)",
                         fmt::format("malformed YAML: {}", e.msg));
  }
  if (!f.root.IsMap()) {
    throw YamlInputError(
        path, 1, 1, "(document)",
        fmt::format("expected a mapping of keys at the top level, got {}", describe(f.root)));
  }
  return f;
}

YamlFile load_yaml_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw YamlInputError(path, 0, 0, "(file)", "cannot open the file for reading");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_yaml_text(ss.str(), path);
}

std::string nearest_key(const std::string& word, const std::set<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) {
      best_d = d;
      best = c;
    }
  }
  // Suggest only when the edit is small relative to the word.
  return best_d <= std::max<std::size_t>(2, word.size() / 3) ? best : std::string();
}

MapReader::MapReader(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
    const auto [l, c] = position_of(node_);
    throw YamlInputError(file_, l, c, path_.empty() ? "(document)" : path_,
                         fmt::format("expected a mapping of keys, got {}", describe(node_)));
  }
}

std::string MapReader::key_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

bool MapReader::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

void MapReader::fail(const std::string& key, const std::string& message) const {
  YAML::Node at = has(key) ? node_[key] : node_;
  auto [l, c] = position_of(at);
  throw YamlInputError(file_, l, c, key_path(key), message);
}

YAML::Node MapReader::require(const std::string& key) {
  known_.insert(key);
  if (!has(key)) {
    // A misspelt key is the likelier story than a forgotten one: point at it.
    if (node_.IsMap()) {
      for (const auto& kv : node_) {
        const std::string present = kv.first.as<std::string>();
        if (known_.count(present) == 0 && nearest_key(present, {key}) == key) {
          const auto [l, c] = position_of(kv.first);
          throw YamlInputError(
              file_, l, c, key_path(present),
              fmt::format("unknown key '{}' (did you mean '{}'?); '{}' is required here", present,
                          key, key));
        }
      }
    }
    const auto [l, c] = position_of(node_);
    throw YamlInputError(file_, l, c, key_path(key),
                         fmt::format("missing required key '{}' in {}", key,
                                     path_.empty() ? "the top level" : "'" + path_ + "'"));
  }
  return node_[key];
}

double MapReader::number(const std::string& key) {
  const YAML::Node n = require(key);
  double v = 0.0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, v)) {
    fail(key, fmt::format("expected a number, got {}", describe(n)));
  }
  if (!std::isfinite(v)) fail(key, fmt::format("expected a finite number, got {}", n.Scalar()));
  return v;
}

double MapReader::number_or(const std::string& key, double fallback, bool allow_infinite) {
  known_.insert(key);
  if (!has(key)) return fallback;
  const YAML::Node n = node_[key];
  double v = 0.0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, v)) {
    fail(key, fmt::format("expected a number, got {}", describe(n)));
  }
  if (std::isnan(v) || (!allow_infinite && std::isinf(v))) {
    fail(key, fmt::format("expected a finite number{}, got {}", allow_infinite ? " or .inf" : "",
                          n.Scalar()));
  }
  return v;
}

long MapReader::integer_or(const std::string& key, long fallback) {
  known_.insert(key);
  if (!has(key)) return fallback;
  const YAML::Node n = node_[key];
  long v = 0;
  if (!n.IsScalar() || !YAML::convert<long>::decode(n, v)) {
    fail(key, fmt::format("expected a whole number, got {}", describe(n)));
  }
  return v;
}

std::string MapReader::string(const std::string& key, const std::vector<std::string>& allowed) {
  const YAML::Node n = require(key);
  if (!n.IsScalar()) fail(key, fmt::format("expected a word, got {}", describe(n)));
  const std::string v = n.Scalar();
  if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
    const std::set<std::string> cand(allowed.begin(), allowed.end());
    const std::string near = nearest_key(v, cand);
    fail(key, fmt::format("unknown value '{}'; allowed: {}{}", v, fmt::join(allowed, ", "),
                          near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near)));
  }
  return v;
}

std::string MapReader::string_or(const std::string& key, const std::string& fallback,
                                 const std::vector<std::string>& allowed) {
  known_.insert(key);
  if (!has(key)) return fallback;
  return string(key, allowed);
}

std::vector<std::string> MapReader::string_list_or(const std::string& key,
                                                   const std::vector<std::string>& fallback) {
  known_.insert(key);
  if (!has(key)) return fallback;
  const YAML::Node n = node_[key];
  if (n.IsScalar()) return {n.Scalar()};
  if (!n.IsSequence()) fail(key, fmt::format("expected a list of words, got {}", describe(n)));
  std::vector<std::string> out;
  for (const auto& item : n) {
    if (!item.IsScalar()) fail(key, "expected a list of words, found a nested item");
    out.push_back(item.Scalar());
  }
  return out;
}

MapReader MapReader::map(const std::string& key) {
  return MapReader(require(key), file_, key_path(key));
}

MapReader MapReader::map_or_empty(const std::string& key) {
  known_.insert(key);
  return MapReader(has(key) ? node_[key] : YAML::Node(YAML::NodeType::Map), file_, key_path(key));
}

YAML::Node MapReader::node(const std::string& key) {
  known_.insert(key);
  return has(key) ? node_[key] : YAML::Node();
}

void MapReader::finish() const {
  if (!node_.IsMap()) return;
  for (const auto& kv : node_) {
    const std::string key = kv.first.as<std::string>();
    if (known_.count(key) != 0) continue;
    const auto [l, c] = position_of(kv.first);
    const std::string near = nearest_key(key, known_);
    throw YamlInputError(file_, l, c, key_path(key),
                         fmt::format("unknown key '{}'{}; valid keys here: {}", key,
                                     near.empty() ? "" : fmt::format(" (did you mean '{}'?)", near),
                                     fmt::join(known_, ", ")));
  }
}

}  // namespace ferro::scenarios
