#pragma once
// The one reader of delimited text tables in ferrodyn: CSV inputs (batch cases, contact tables,
// measured irregularities, reference results), whitespace tables (profile points, journals).
// A line splits into cells at the format's separators; cells are trimmed of blanks (and a
// trailing carriage return); quoting is not supported (no cell holds a separator). Blank lines
// and comment lines are skipped. Every error is std::invalid_argument located as
// "<source>:<line>: ...", with the column name where there is one.

#include <istream>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace ferro::io {

/// How the lines of a table split into cells.
struct CsvFormat {
  /// Characters that end a cell.
  std::string_view separators = ",";
  /// Runs of blanks (spaces, tabs) separate cells too, and blanks at either end of a line make
  /// no cell (whitespace tables).
  bool blank_separated = false;
  /// A line whose first non-blank character is one of these is a comment; "" for none.
  std::string_view comment_marks = "#";
  /// A comment mark anywhere ends the line's content (the rest of the line is a comment).
  bool trailing_comments = false;
  /// The first line that is not a comment names the columns; every row then has as many cells.
  bool header = true;

  /// Comma-separated with a header, '#' comments.
  [[nodiscard]] static CsvFormat csv() { return {}; }
  /// Cells separated by blanks, no header, no comments.
  [[nodiscard]] static CsvFormat blanks() { return {"", true, "", false, false}; }
};

class CsvReader {
 public:
  /// Reads the header from `in` (when the format has one); `source` names the input in messages
  /// ("stdin", a path). Throws when there is no header or a column name is empty or repeated.
  CsvReader(std::istream& in, std::string source, CsvFormat format = {});
  /// Opens `path` (std::invalid_argument "<path>: cannot open the <what>" when it cannot).
  static CsvReader open(const std::string& path, CsvFormat format = {},
                        std::string_view what = "file");
  CsvReader(CsvReader&&) noexcept;
  CsvReader& operator=(CsvReader&&) = delete;
  CsvReader(const CsvReader&) = delete;
  CsvReader& operator=(const CsvReader&) = delete;
  ~CsvReader();

  [[nodiscard]] const std::vector<std::string>& header() const { return header_; }
  [[nodiscard]] const std::string& source() const { return source_; }
  /// Line number of the header or of the last line read (1-based).
  [[nodiscard]] int line() const { return line_; }
  /// Comment lines met so far, without their mark, trimmed.
  [[nodiscard]] const std::vector<std::string>& comments() const { return comments_; }

  /// Throws naming the first column not in `allowed` (and listing the allowed names).
  void require_known_columns(const std::set<std::string>& allowed) const;
  [[nodiscard]] bool has_column(const std::string& name) const;

  /// Next row: its cells (as many as the header's when there is one). False at the end.
  bool next(std::vector<std::string>& cells);
  /// Next line that is not blank or a comment, trimmed, its trailing comment removed (for
  /// formats whose lines are not all rows). False at the end.
  bool next_line(std::string& text);

  /// The whole cell `cells[column]` as a finite number; throws "<source>:<line>, column '<name>':
  /// not a number: '<cell>'" (column <n> without a header).
  [[nodiscard]] double number(const std::vector<std::string>& cells, std::size_t column) const;

  /// "<source>:<line>: <message>", for errors found while using a row.
  [[nodiscard]] std::string located(const std::string& message) const;

 private:
  [[nodiscard]] std::string column_name(std::size_t column) const;
  std::unique_ptr<std::istream> owned_;
  std::istream* in_;
  std::string source_;
  CsvFormat format_;
  std::vector<std::string> header_;
  std::vector<std::string> comments_;
  int line_ = 0;
};

/// Splits one line into trimmed cells as `format` says (comments are not looked at).
[[nodiscard]] std::vector<std::string> split_cells(std::string_view line,
                                                   const CsvFormat& format = {});

/// `text` without the blanks (spaces, tabs, carriage returns, newlines) at either end.
[[nodiscard]] std::string_view trim(std::string_view text);

/// The whole of `text` (surrounding blanks allowed, a leading '+' too) as a double, or nothing
/// when it is not a number. "nan" and "inf" are numbers here: callers that need a finite value
/// check it.
[[nodiscard]] std::optional<double> parse_number(std::string_view text);

}  // namespace ferro::io
