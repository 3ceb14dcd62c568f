#include "ferro/scenarios/csv_batch.hpp"

#include <cmath>
#include <string_view>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <stdexcept>

namespace ferro::scenarios {
namespace {

bool skipped(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

}  // namespace

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    const std::string cell =
        line.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto b = cell.find_first_not_of(" \t\r");
    const auto e = cell.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? std::string() : cell.substr(b, e - b + 1));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

CsvBatchReader::CsvBatchReader(std::istream& in, std::string source)
    : in_(in), source_(std::move(source)) {
  std::string text;
  while (std::getline(in_, text)) {
    ++line_;
    if (skipped(text)) continue;
    header_ = split_csv_line(text);
    break;
  }
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

void CsvBatchReader::require_known_columns(const std::set<std::string>& allowed) const {
  for (const auto& h : header_) {
    if (allowed.count(h) == 0) {
      throw std::invalid_argument(
          fmt::format("{}:{}: unknown CSV column '{}'; allowed: {}", source_, 1, h,
                      fmt::join(allowed, ", ")));
    }
  }
}

bool CsvBatchReader::has_column(const std::string& name) const {
  return std::find(header_.begin(), header_.end(), name) != header_.end();
}

bool CsvBatchReader::next(std::vector<std::string>& cells) {
  std::string text;
  while (std::getline(in_, text)) {
    ++line_;
    if (skipped(text)) continue;
    cells = split_csv_line(text);
    if (cells.size() != header_.size()) {
      throw std::invalid_argument(
          located(fmt::format("{} cells, the header has {}", cells.size(), header_.size())));
    }
    return true;
  }
  return false;
}

double CsvBatchReader::number(const std::vector<std::string>& cells, std::size_t column) const {
  const std::string& cell = cells.at(column);
  try {
    std::size_t used = 0;
    const double v = std::stod(cell, &used);
    if (used == cell.size() && std::isfinite(v)) return v;
    if (used == cell.size()) {
      throw std::invalid_argument(fmt::format("{}:{}, column '{}': not a finite number: '{}'",
                                              source_, line_, header_.at(column), cell));
    }
  } catch (const std::invalid_argument& e) {
    if (std::string_view(e.what()).find("not a finite number") != std::string_view::npos) throw;
  } catch (const std::out_of_range&) {
  }
  throw std::invalid_argument(fmt::format("{}:{}, column '{}': not a number: '{}'", source_, line_,
                                          header_.at(column), cell));
}

std::string CsvBatchReader::located(const std::string& message) const {
  return fmt::format("{}:{}: {}", source_, line_, message);
}

}  // namespace ferro::scenarios
