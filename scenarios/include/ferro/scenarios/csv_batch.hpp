#pragma once
// The one reader of CSV batch inputs (`contact eval --batch`, `geometry search --batch`): a
// header line naming the columns, then one row per case. Blank lines and lines starting with '#'
// are skipped; cells are trimmed of blanks; quoting is not supported (no cell holds a comma).
// Every error is std::invalid_argument located as "<source>:<line>: ...", with the column name
// where there is one.

#include <istream>
#include <set>
#include <string>
#include <vector>

namespace ferro::scenarios {

class CsvBatchReader {
 public:
  /// Reads the header from `in`; `source` names the input in messages ("stdin", a path).
  /// Throws when there is no header or a column name is empty or repeated.
  CsvBatchReader(std::istream& in, std::string source);

  [[nodiscard]] const std::vector<std::string>& header() const { return header_; }
  [[nodiscard]] const std::string& source() const { return source_; }
  /// Line number of the header or of the last row read (1-based).
  [[nodiscard]] int line() const { return line_; }

  /// Throws naming the first column not in `allowed` (and listing the allowed names).
  void require_known_columns(const std::set<std::string>& allowed) const;
  [[nodiscard]] bool has_column(const std::string& name) const;

  /// Next row: its cells, as many as the header's. False at the end of the input.
  bool next(std::vector<std::string>& cells);

  /// The whole cell `cells[column]` as a number; throws "<source>:<line>, column '<name>': not a
  /// number: '<cell>'".
  [[nodiscard]] double number(const std::vector<std::string>& cells, std::size_t column) const;

  /// "<source>:<line>: <message>", for errors found while using a row.
  [[nodiscard]] std::string located(const std::string& message) const;

 private:
  std::istream& in_;
  std::string source_;
  std::vector<std::string> header_;
  int line_ = 0;
};

/// Splits one CSV line at commas, trimming blanks (and a trailing carriage return) from each cell.
[[nodiscard]] std::vector<std::string> split_csv_line(const std::string& line);

}  // namespace ferro::scenarios
