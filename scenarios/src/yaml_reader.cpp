#include "ferro/scenarios/yaml_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/depthguard.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

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

// Deepest nesting and largest node count an input file may have. Scenes, cases and pair files
// nest a handful of levels and hold a few thousand nodes; the node bound also stops alias
// expansion ("billion laughs") from exhausting memory.
constexpr int kMaxNesting = 64;
constexpr std::size_t kMaxNodes = 1'000'000;

// Rejects what yaml-cpp accepts but a ferrodyn file never means: non-scalar (complex) keys,
// a key given twice in one mapping (yaml-cpp keeps both and lookups see the first), nesting
// beyond kMaxNesting and alias expansion beyond kMaxNodes.
// An alias is the very node of its anchor, so each container is checked once and remembers the
// node count and height of its expansion: the check takes time in the size of the text, not of
// the expansion (a "billion laughs" file is rejected as fast as it is parsed).
class StructureCheck {
 public:
  explicit StructureCheck(const std::string& path) : path_(path) {}

  void run(const YAML::Node& root) { (void)walk(root, 0, ""); }

 private:
  struct Seen {
    YAML::Node node;
    std::size_t count;  // nodes of the expansion, the container included
    int height;         // levels below it
  };

  [[noreturn]] void too_deep(const YAML::Node& node) const {
    const auto [l, c] = position_of(node);
    throw YamlInputError(path_, l, c, "(document)",
                         fmt::format("nested deeper than {} levels; ferrodyn input files "
                                     "nest a few levels",
                                     kMaxNesting));
  }
  void add(std::size_t& count, std::size_t more) const {
    count += more;
    if (count > kMaxNodes) {
      throw YamlInputError(path_, 1, 1, "(document)",
                           fmt::format("more than {} nodes (after expanding aliases); ferrodyn "
                                       "input files are far smaller",
                                       kMaxNodes));
    }
  }

  // Node count and height of the expansion of `node`, met at `depth`.
  std::pair<std::size_t, int> walk(const YAML::Node& node, int depth, const std::string& key_path) {
    if (depth > kMaxNesting) too_deep(node);
    if (!node.IsMap() && !node.IsSequence()) return {1, 0};
    const YAML::Mark mark = node.Mark();
    std::vector<Seen>& same_place = seen_[mark.pos];
    for (const Seen& s : same_place) {
      if (s.node.is(node)) {
        if (depth + s.height > kMaxNesting) too_deep(node);
        return {s.count, s.height};
      }
    }
    std::size_t count = 1;
    int height = 0;
    const auto child = [&](const YAML::Node& n, const std::string& p) {
      const auto [c, h] = walk(n, depth + 1, p);
      add(count, c);
      height = std::max(height, h + 1);
    };
    if (node.IsSequence()) {
      long i = 0;
      for (const auto& item : node) {
        child(item, (item.IsMap() || item.IsSequence()) ? fmt::format("{}[{}]", key_path, i) : "");
        ++i;
      }
    } else {
      std::map<std::string, int> first_line;
      for (const auto& kv : node) {
        const auto [l, c] = position_of(kv.first);
        if (!kv.first.IsScalar()) {
          throw YamlInputError(path_, l, c, key_path.empty() ? "(key)" : key_path,
                               fmt::format("a key must be a plain word, got {} (complex keys "
                                           "written with '? ' are not supported)",
                                           describe(kv.first)));
        }
        const std::string child_path =
            key_path.empty() ? kv.first.Scalar() : key_path + "." + kv.first.Scalar();
        const auto [it, inserted] = first_line.emplace(kv.first.Scalar(), l);
        if (!inserted) {
          throw YamlInputError(path_, l, c, child_path,
                               fmt::format("duplicate key '{}' (first given at line {}, again at "
                                           "line {}); keep one",
                                           kv.first.Scalar(), it->second, l));
        }
        child(kv.second, child_path);
      }
    }
    seen_[mark.pos].push_back({node, count, height});
    return {count, height};
  }

  const std::string& path_;
  std::unordered_map<int, std::vector<Seen>> seen_;  // by position in the text
};

void check_structure(const YAML::Node& root, const std::string& path) {
  StructureCheck(path).run(root);
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

namespace {

// Inputs on which yaml-cpp 0.7 loops without end, allocating: a document whose first token is
// ',' (after comments, blank lines, a '---' marker and node properties: tags, anchors), and a document whose root block
// collection starts at column r with a later line starting with ',' left of column r (a mapping)
// or at most at column r (a list). None is a ferrodyn file (whose root is a mapping at column 0).
// Returns the line (1-based) to name, or 0, and the message.
struct HangingInput {
  int line = 0;
  const char* message = "";
};

// Line (1-based) of a ',' that follows only node properties (tags '!...', anchors '&...'),
// blanks and comments from `pos` (a document's first token) on, or 0.
int comma_after_properties(const std::string& text, std::size_t pos, int line_no) {
  while (pos < text.size()) {
    const char c = text[pos];
    if (c == '\n') {
      ++line_no;
      ++pos;
    } else if (c == ' ' || c == '\t' || c == '\r') {
      ++pos;
    } else if (c == '#') {
      pos = std::min(text.find('\n', pos), text.size());
    } else if (c == '!' || c == '&') {
      pos = std::min(text.find_first_of(" \t\r\n,[]{}", pos), text.size());
    } else {
      return c == ',' ? line_no : 0;
    }
  }
  return 0;
}
HangingInput hanging_flow_entry(const std::string& text) {
  bool at_document_start = true;
  // The document's first content line: its line, the column of its first token, and whether
  // that token opens a block list.
  int root_line = 0;
  std::size_t root_column = 0;
  bool root_list = false;
  int line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line(text.data() + pos, end - pos);
    const std::size_t line_start = pos;
    ++line_no;
    pos = end + 1;
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == '#') continue;
    if (line.substr(0, 3) == "---" || line.substr(0, 3) == "...") {
      at_document_start = true;
      root_line = 0;
      root_column = 0;
      root_list = false;
      const std::size_t rest = line.find_first_not_of(" \t\r", 3);
      if (rest == std::string_view::npos || line[rest] == '#') continue;
      if (const int comma = comma_after_properties(text, line_start + rest, line_no);
          comma > 0) {
        return {comma, "malformed YAML: a document cannot start with ','"};
      }
      at_document_start = false;
      continue;
    }
    if (line[0] == '%') continue;  // directive
    if (at_document_start) {
      if (const int comma = comma_after_properties(text, line_start + first, line_no); comma > 0) {
        return {comma, "malformed YAML: a document cannot start with ','"};
      }
      root_line = line_no;
      root_column = first;
      root_list = line[first] == '-' && (first + 1 == line.size() || line[first + 1] == ' ' ||
                                         line[first + 1] == '\t' || line[first + 1] == '\r');
    } else if (line[first] == ',' && (first < root_column || (root_list && first == root_column))) {
      if (root_list) {
        return {root_line, "expected a mapping of keys at the top level, got a list"};
      }
      return {line_no, "malformed YAML: a line cannot start with ',' left of the document's "
                       "first key"};
    }
    at_document_start = false;
  }
  return {};
}

}  // namespace

YamlFile parse_yaml_text(const std::string& text, const std::string& path) {
  if (const HangingInput h = hanging_flow_entry(text); h.line > 0) {
    throw YamlInputError(path, h.line, 1, "(document)", h.message);
  }
  YamlFile f{path, text, {}};
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::DeepRecursion& e) {
    throw YamlInputError(path, e.mark.line + 1, e.mark.column + 1, "(document)",
                         fmt::format("nested deeper than {} levels; ferrodyn input files nest a "
                                     "few levels",
                                     kMaxNesting));
  } catch (const YAML::ParserException& e) {
    throw YamlInputError(path, e.mark.line + 1, e.mark.column + 1, "(document)",
                         fmt::format("malformed YAML: {}", e.msg));
  }
  if (documents.size() > 1) {
    const auto [l, c] = position_of(documents[1]);
    throw YamlInputError(path, l, c, "(document)",
                         fmt::format("{} YAML documents in one file (separated by '---'); a "
                                     "ferrodyn file holds exactly one",
                                     documents.size()));
  }
  if (!documents.empty()) f.root = documents.front();
  if (!f.root.IsMap()) {
    throw YamlInputError(
        path, 1, 1, "(document)",
        fmt::format("expected a mapping of keys at the top level, got {}", describe(f.root)));
  }
  check_structure(f.root, path);
  return f;
}

YamlFile load_yaml_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec) {
    throw YamlInputError(path, 0, 0, "(file)",
                         fmt::format("cannot open the file: {}", ec.message()));
  }
  if (fs::is_directory(st)) {
    throw YamlInputError(path, 0, 0, "(file)", "is a directory; expected a YAML file");
  }
  std::ifstream in(path);
  if (!in) {
    throw YamlInputError(path, 0, 0, "(file)",
                         fmt::format("cannot open the file for reading: {}", std::strerror(errno)));
  }
  std::stringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw YamlInputError(path, 0, 0, "(file)", "read error");
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

bool MapReader::boolean_or(const std::string& key, bool fallback) {
  return string_or(key, fallback ? "true" : "false", {"true", "false"}) == "true";
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
