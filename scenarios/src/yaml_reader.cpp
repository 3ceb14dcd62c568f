#include "ferro/scenarios/yaml_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <cctype>
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
    // Application tags (`!python/object 1813`) ask for a meaning this reader does not give;
    // the YAML core tags (`!!str`) and none at all are plain values.
    if (const std::string& tag = node.Tag();
        !tag.empty() && tag != "?" && tag != "!" && tag.rfind("tag:yaml.org,2002:", 0) != 0) {
      const auto [l, c] = position_of(node);
      throw YamlInputError(path_, l, c, key_path.empty() ? "(value)" : key_path,
                           fmt::format("the YAML tag '{}' is not supported; write the plain "
                                       "value",
                                       tag));
    }
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
      column_(column),
      key_(key),
      message_(message) {}

std::pair<int, int> position_of(const YAML::Node& node) {
  if (!node.IsDefined()) return {0, 0};
  const YAML::Mark m = node.Mark();
  if (m.is_null()) return {0, 0};
  return {m.line + 1, m.column + 1};
}

namespace {

// A byte YAML does not allow in a stream (C0 controls other than tab, line feed and carriage
// return, and DEL): yaml-cpp 0.7 takes a NUL for a UTF-16/32 marker and reads the rest as other
// characters (looping without end on some). Returns the line and column (1-based) of the first,
// or {0, 0}, and the byte.
struct ControlByte {
  int line = 0;
  int column = 0;
  unsigned char byte = 0;
};

ControlByte first_control_byte(const std::string& text) {
  int line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++line;
      line_start = i + 1;
    } else if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
      return {line, static_cast<int>(i - line_start) + 1, c};
    }
  }
  return {};
}

// yaml-cpp 0.7 loops without end, allocating, on inputs holding a ',' token outside every flow
// collection ([ ] or { }): a document starting with ',', a ',' line after a root list, after an
// anchored, tagged or quoted root scalar, after a root flow collection, ... Such a ',' is never
// valid YAML: it separates entries only inside a flow collection, and a plain scalar cannot begin
// with it. One scan of the text names the first one before yaml-cpp sees the text. It follows
// yaml-cpp's tokens: flow depth, quoted scalars (a quote opens one wherever a token starts, even
// right after another scalar), comments, tags (yaml-cpp's tag characters), anchors, aliases,
// block scalars and the next lines of a multi-line plain scalar (whose quotes and brackets are
// text). Where a line may continue a plain scalar or start a token, it takes the reading that
// sees more commas.
// Known deviation: a ',' or '? ' starting a line of a multi-line plain scalar (valid YAML) is
// refused too; the message says to quote such a value.
struct MisplacedComma {
  int line = 0;  // 1-based; 0: none
  int column = 0;
  const char* message = "";
  const char* key = "(document)";
};

class FlowEntryScan {
 public:
  explicit FlowEntryScan(const std::string& text) : text_(text) {}

  MisplacedComma run() {
    int line_no = 0;
    // A UTF-8 byte order mark is not part of the text (yaml-cpp drops it).
    const std::size_t start = text_.rfind("\xef\xbb\xbf", 0) == 0 ? 3 : 0;
    for (std::size_t pos = start; pos <= text_.size();) {
      const std::size_t end = std::min(text_.find('\n', pos), text_.size());
      const std::string_view line(text_.data() + pos, end - pos);
      pos = end + 1;
      ++line_no;
      if (const MisplacedComma m = scan_line(line, line_no); m.line > 0) return m;
    }
    return {};
  }

 private:
  enum class Expect { kNode, kInPlain, kAfterNode };

  static bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

  MisplacedComma reject(int line_no, std::size_t column) const {
    if (root_list_) {
      return {root_line_, 1, "expected a mapping of keys at the top level, got a list"};
    }
    return {line_no, static_cast<int>(column) + 1,
            "malformed YAML: ',' outside [ ] or { } (a value cannot begin with ','; quote it)"};
  }

  // yaml-cpp 0.7 also loops on a '?' key indicator after a root scalar with a tag or anchor;
  // ferrodyn keys are plain words, so every explicit key is refused where it stands.
  static MisplacedComma reject_explicit_key(int line_no, std::size_t column) {
    return {line_no, static_cast<int>(column) + 1,
            "a key must be a plain word, got '? ' (complex keys written with '? ' are not "
            "supported)",
            "(key)"};
  }

  MisplacedComma scan_line(std::string_view line, int line_no) {
    const std::size_t indent = line.find_first_not_of(" \t\r");
    const bool empty = indent == std::string_view::npos;
    // Content of a block scalar: blank lines and lines indented more than its owner.
    if (block_owner_ >= 0) {
      if (empty || static_cast<long>(indent) > block_owner_) return {};
      block_owner_ = -1;
    }
    if (empty) return {};
    std::size_t i = 0;
    if (quote_ == 0 && depth_ == 0) {
      if (line[indent] == '#') return {};
      if (indent == 0 && line[0] == '%') return {};  // directive
      const std::string_view marker = line.substr(0, 3);
      const long continues = plain_continuation_;
      plain_continuation_ = -1;
      i = indent;
      if (indent == 0 && (marker == "---" || marker == "...") &&
          (line.size() == 3 || blank(line[3]))) {
        at_document_start_ = true;
        root_list_ = false;
        i = 3;
      } else if (continues >= 0 && static_cast<long>(indent) >= continues) {
        // More text of a multi-line plain scalar: quotes and brackets in it are text.
        if (line[indent] == ',') return reject(line_no, indent);
        if (line[indent] == '?' && (indent + 1 >= line.size() || blank(line[indent + 1]))) {
          return reject_explicit_key(line_no, indent);
        }
        expect_ = Expect::kInPlain;
        node_column_ = static_cast<long>(indent);
        return scan_tokens(line, line_no, i);
      }
      expect_ = Expect::kNode;
      owner_ = static_cast<long>(indent);
      owned_ = false;
    } else if (quote_ == 0) {
      i = indent;
    }
    return scan_tokens(line, line_no, i);
  }

  // Scans `line` from `i` on, in the state the previous lines left.
  MisplacedComma scan_tokens(std::string_view line, int line_no, std::size_t i) {
    for (; i < line.size(); ++i) {
      const char c = line[i];
      if (quote_ != 0) {
        if (quote_ == '"' && c == '\\') {
          ++i;
        } else if (c == quote_) {
          if (quote_ == '\'' && i + 1 < line.size() && line[i + 1] == '\'') {
            ++i;
          } else {
            quote_ = 0;
            expect_ = Expect::kAfterNode;
          }
        }
        continue;
      }
      if (blank(c)) continue;
      // A comment: at a token's start (as yaml-cpp's scanner reads it), or after a blank.
      if (c == '#' && (expect_ != Expect::kInPlain || i == 0 || blank(line[i - 1]))) break;
      const bool next_blank = i + 1 >= line.size() || blank(line[i + 1]);
      if (expect_ == Expect::kNode && depth_ == 0 && at_document_start_) {
        at_document_start_ = false;
        root_list_ = c == '-' && next_blank;
        root_line_ = line_no;
      }
      if (c == ',') {
        if (depth_ == 0 && expect_ != Expect::kInPlain) return reject(line_no, i);
        if (depth_ > 0) expect_ = Expect::kNode;
        continue;
      }
      if (depth_ > 0) {
        // Flow context: brackets and ',' are indicators wherever they stand; ':' when a blank
        // or an indicator follows, or right after a quoted scalar ("a":1).
        if (c == '[' || c == '{') {
          ++depth_;
          expect_ = Expect::kNode;
        } else if (c == ']' || c == '}') {
          --depth_;
          expect_ = depth_ == 0 ? Expect::kAfterNode : Expect::kInPlain;
        } else if (c == ':' && (next_blank || expect_ == Expect::kAfterNode ||
                                std::string_view(",[]{}").find(line[i + 1]) !=
                                    std::string_view::npos)) {
          expect_ = Expect::kNode;
        } else if (expect_ != Expect::kInPlain && (c == '\'' || c == '"')) {
          quote_ = c;
        } else if (expect_ == Expect::kNode && !(c == '?' && next_blank)) {
          skip_property(line, i, c);
        }
        continue;
      }
      if (expect_ != Expect::kNode) {
        // Block context, after a scalar: ": " starts the value. Inside a plain scalar the rest
        // of the line is its text; after a quoted scalar, flow collection or alias, the next
        // character starts a token, as it does for yaml-cpp's scanner (invalid YAML, but a ','
        // or a quote there must be seen).
        if (c == ':' && next_blank) {
          expect_ = Expect::kNode;
          owner_ = node_column_;
          owned_ = true;
          continue;
        }
        if (expect_ == Expect::kInPlain) continue;
        expect_ = Expect::kNode;
      }
      if (c == '?' && next_blank) return reject_explicit_key(line_no, i);
      if ((c == '-' || c == ':') && next_blank) {
        owner_ = static_cast<long>(i);  // block list entry or empty key
        owned_ = true;
      } else if (c == '|' || c == '>') {
        block_owner_ = owner_;
        return {};
      } else if (c == '\'' || c == '"') {
        quote_ = c;
        node_column_ = static_cast<long>(i);
      } else if (c == '[' || c == '{') {
        ++depth_;
      } else {
        node_column_ = static_cast<long>(i);
        skip_property(line, i, c);
      }
    }
    // A plain scalar running to the line's end may go on over the next lines: those indented
    // past its key or list entry (any, for a scalar with neither on its line: the cautious side).
    if (quote_ == 0 && depth_ == 0 && expect_ == Expect::kInPlain) {
      plain_continuation_ = owned_ ? owner_ + 1 : 0;
    }
    return {};
  }

  // Characters of a tag after its '!' (yaml-cpp's: word characters, "#;/?:@&=+$_.~*'()",
  // '%' escapes and the '!' ending a handle); a verbatim tag "!<...>" runs to its '>'.
  static bool tag_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
           std::string_view("-#;/?:@&=+$_.~*'()%!").find(c) != std::string_view::npos;
  }

  // At a node's first character `c`: skips an anchor, tag or alias token (the node still
  // starts after an anchor or tag; an alias is the whole node), else a plain scalar begins.
  void skip_property(std::string_view line, std::size_t& i, char c) {
    if (c == '!') {
      if (i + 1 < line.size() && line[i + 1] == '<') {
        while (i + 1 < line.size() && line[i + 1] != '>') ++i;
      } else {
        while (i + 1 < line.size() && tag_char(line[i + 1])) ++i;
      }
    } else if (c == '&' || c == '*') {
      while (i + 1 < line.size() && !blank(line[i + 1]) &&
             std::string_view(",[]{}").find(line[i + 1]) == std::string_view::npos) {
        ++i;
      }
      if (c == '*') expect_ = Expect::kAfterNode;
    } else {
      expect_ = Expect::kInPlain;
    }
  }

  const std::string& text_;
  int depth_ = 0;                 // open flow collections
  char quote_ = 0;                // '\'' or '"' inside a quoted scalar
  Expect expect_ = Expect::kNode;
  long owner_ = 0;                // column of the node owning what follows (key, '-')
  long node_column_ = 0;          // column where the last scalar began
  bool owned_ = false;            // owner_ is a key or '-' of this line (not its indentation)
  long block_owner_ = -1;         // inside a block scalar: its owner's column; else -1
  long plain_continuation_ = -1;  // a plain scalar may go on at lines indented this much; or -1
  bool at_document_start_ = true;
  bool root_list_ = false;        // the document's root is a block list
  int root_line_ = 0;
};

// Counts a stream's documents without building them, up to kMaxDocuments, and keeps where the
// second one starts. yaml-cpp 0.7 reads a token that no node can take (e.g. a stray ',') as the
// start of one more empty document, again and again: YAML::LoadAll then never ends. A bounded
// count ends, and a ferrodyn file holds one document.
constexpr int kMaxDocuments = 16;

class DocumentCounter : public YAML::EventHandler {
 public:
  [[nodiscard]] int count() const { return count_; }
  [[nodiscard]] const YAML::Mark& second() const { return second_; }

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++count_ == 2) second_ = mark;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                const std::string&) override {
    node(mark);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    node(mark);
  }
  void OnMapEnd() override {}

 private:
  // The second document is named by its first node where it has one.
  void node(const YAML::Mark& mark) {
    if (count_ == 2 && !second_node_) {
      second_ = mark;
      second_node_ = true;
    }
  }

  int count_ = 0;
  YAML::Mark second_ = YAML::Mark::null_mark();
  bool second_node_ = false;
};

}  // namespace

YamlFile parse_yaml_text(const std::string& text, const std::string& path) {
  if (const ControlByte b = first_control_byte(text); b.line > 0) {
    throw YamlInputError(path, b.line, b.column, "(document)",
                         fmt::format("byte 0x{:02x} is not text: a ferrodyn file is UTF-8 text, "
                                     "without control characters other than tab and line ends",
                                     b.byte));
  }
  if (const MisplacedComma m = FlowEntryScan(text).run(); m.line > 0) {
    throw YamlInputError(path, m.line, m.column, m.key, m.message);
  }
  YamlFile f{path, text, {}};
  DocumentCounter documents;
  try {
    std::istringstream in(text);
    YAML::Parser parser(in);
    while (documents.count() < kMaxDocuments && parser.HandleNextDocument(documents)) {
    }
    if (documents.count() <= 1) f.root = YAML::Load(text);
  } catch (const YAML::DeepRecursion& e) {
    throw YamlInputError(path, e.mark.line + 1, e.mark.column + 1, "(document)",
                         fmt::format("nested deeper than {} levels; ferrodyn input files nest a "
                                     "few levels",
                                     kMaxNesting));
  } catch (const YAML::ParserException& e) {
    throw YamlInputError(path, e.mark.line + 1, e.mark.column + 1, "(document)",
                         fmt::format("malformed YAML: {}", e.msg));
  }
  if (documents.count() > 1) {
    const YAML::Mark& m = documents.second();
    throw YamlInputError(path, m.line + 1, m.column + 1, "(document)",
                         fmt::format("{}{} YAML documents in one file (separated by '---'); a "
                                     "ferrodyn file holds exactly one",
                                     documents.count() >= kMaxDocuments ? "at least " : "",
                                     documents.count()));
  }
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
