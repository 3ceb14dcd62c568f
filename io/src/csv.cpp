// The one reader of delimited text tables (see the header).
//
// References: RFC 4180 (comma-separated values; quoting is not supported here).
// Known deviations: no quoted cells.
#include "ferro/io/csv.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace ferro::io {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

}  // namespace

std::string_view trim(std::string_view text) {
  constexpr std::string_view kBlanks = " \t\r\n";
  const auto b = text.find_first_not_of(kBlanks);
  if (b == std::string_view::npos) return {};
  const auto e = text.find_last_not_of(kBlanks);
  return text.substr(b, e - b + 1);
}

std::vector<std::string> split_cells(std::string_view line, const CsvFormat& format) {
  std::vector<std::string> out;
  if (format.blank_separated) line = trim(line);
  const auto is_separator = [&](char c) {
    return format.separators.find(c) != std::string_view::npos;
  };
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i) {
    const bool end = i == line.size();
    if (!end && !is_separator(line[i]) && !(format.blank_separated && is_blank(line[i]))) continue;
    out.emplace_back(trim(line.substr(start, i - start)));
    if (end) break;
    if (format.blank_separated) {
      // One delimiter: a run of blanks with at most one separator in it.
      bool separated = is_separator(line[i]);
      while (i + 1 < line.size()) {
        const char c = line[i + 1];
        if (is_blank(c)) {
          ++i;
        } else if (!separated && is_separator(c)) {
          separated = true;
          ++i;
        } else {
          break;
        }
      }
    }
    start = i + 1;
  }
  return out;
}

std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto res = std::from_chars(text.data(), end, v);
  if (res.ec != std::errc() || res.ptr != end) return std::nullopt;
  return v;
}

CsvReader::CsvReader(std::istream& in, std::string source, CsvFormat format)
    : in_(&in), source_(std::move(source)), format_(format) {
  if (!format_.header) return;
  std::string text;
  if (next_line(text)) header_ = split_cells(text, format_);
  if (header_.empty()) {
    throw std::invalid_argument(
        fmt::format("{}: empty input (expected a CSV header line naming the columns)", source_));
  }
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i].empty())
      throw std::invalid_argument(located(fmt::format("header column {} has no name", i + 1)));
    if (std::find(header_.begin(), header_.begin() + static_cast<long>(i), header_[i]) !=
        header_.begin() + static_cast<long>(i)) {
      throw std::invalid_argument(located(fmt::format("column '{}' appears twice", header_[i])));
    }
  }
}

CsvReader CsvReader::open(const std::string& path, CsvFormat format, std::string_view what) {
  auto file = std::make_unique<std::ifstream>(path);
  if (!*file) throw std::invalid_argument(fmt::format("{}: cannot open the {}", path, what));
  std::istream& in = *file;
  CsvReader reader(in, path, format);
  reader.owned_ = std::move(file);
  return reader;
}

CsvReader::CsvReader(CsvReader&&) noexcept = default;
CsvReader::~CsvReader() = default;

void CsvReader::require_known_columns(const std::set<std::string>& allowed) const {
  for (const auto& h : header_) {
    if (allowed.count(h) == 0) {
      throw std::invalid_argument(fmt::format("{}:{}: unknown CSV column '{}'; allowed: {}",
                                              source_, 1, h, fmt::join(allowed, ", ")));
    }
  }
}

bool CsvReader::has_column(const std::string& name) const {
  return std::find(header_.begin(), header_.end(), name) != header_.end();
}

bool CsvReader::next_line(std::string& text) {
  std::string raw;
  while (std::getline(*in_, raw)) {
    ++line_;
    std::string_view content = trim(raw);
    if (content.empty()) continue;
    if (!format_.comment_marks.empty()) {
      if (format_.comment_marks.find(content.front()) != std::string_view::npos) {
        comments_.emplace_back(trim(content.substr(1)));
        continue;
      }
      if (format_.trailing_comments) {
        const auto mark = content.find_first_of(format_.comment_marks);
        if (mark != std::string_view::npos) content = trim(content.substr(0, mark));
        if (content.empty()) continue;
      }
    }
    text.assign(content);
    return true;
  }
  return false;
}

bool CsvReader::next(std::vector<std::string>& cells) {
  std::string text;
  if (!next_line(text)) return false;
  cells = split_cells(text, format_);
  if (format_.header && cells.size() != header_.size()) {
    throw std::invalid_argument(
        located(fmt::format("{} cells, the header has {}", cells.size(), header_.size())));
  }
  return true;
}

std::string CsvReader::column_name(std::size_t column) const {
  return column < header_.size() ? fmt::format("column '{}'", header_[column])
                                 : fmt::format("column {}", column + 1);
}

double CsvReader::number(const std::vector<std::string>& cells, std::size_t column) const {
  const std::string& cell = cells.at(column);
  const std::optional<double> v = parse_number(cell);
  if (v && std::isfinite(*v)) return *v;
  throw std::invalid_argument(fmt::format("{}:{}, {}: not a {}number: '{}'", source_, line_,
                                          column_name(column), v ? "finite " : "", cell));
}

std::string CsvReader::located(const std::string& message) const {
  return fmt::format("{}:{}: {}", source_, line_, message);
}

}  // namespace ferro::io
