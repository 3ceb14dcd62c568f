// Measured irregularities from CSV (the one CSV reader), cubic Hermite interpolation.
//
// References: EN 13848-1:2019 (channels). Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980)
// for piecewise cubic Hermite interpolation (here without their monotonicity limiter).
// Known deviations: see measured_irregularity.hpp.

#include "ferro/track/measured_irregularity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "ferro/io/csv.hpp"
#include "ferro/numerics/interpolation.hpp"

namespace ferro::track {
namespace {

// Column roles: 0 = s, 1..4 = lateral, vertical, cross_level, gauge.
struct Column {
  int role = -1;
  double to_si = 1.0;
};

std::optional<Column> parse_column(std::string_view name) {
  static constexpr std::array<std::string_view, 5> kNames = {"s", "lateral", "vertical",
                                                             "cross_level", "gauge"};
  for (int role = 0; role < 5; ++role) {
    const std::string_view base = kNames[role];
    if (name.size() <= base.size() + 1 || name.substr(0, base.size()) != base ||
        name[base.size()] != '_') {
      continue;
    }
    const std::string_view unit = name.substr(base.size() + 1);
    if (unit == "m") return Column{role, 1.0};
    if (role == 0 && unit == "km") return Column{role, 1000.0};
    if (role > 0 && unit == "mm") return Column{role, 1e-3};
  }
  return std::nullopt;
}

}  // namespace

MeasuredIrregularity::MeasuredIrregularity(const std::string& path) : source_(path) {
  io::CsvFormat format;
  format.separators = ",;\t";
  io::CsvReader csv = io::CsvReader::open(path, format, "irregularity file");
  std::vector<Column> columns;
  for (auto& v : values_) v.clear();
  // Header.
  std::array<bool, 5> seen{};
  for (const std::string& f : csv.header()) {
    const auto col = parse_column(f);
    if (!col) {
      throw std::invalid_argument(csv.located(fmt::format(
          "unknown column '{}' (allowed: s_m or s_km; lateral, vertical, cross_level, gauge with "
          "_m or _mm)",
          f)));
    }
    if (seen[col->role]) {
      throw std::invalid_argument(csv.located(fmt::format("column '{}' given twice", f)));
    }
    seen[col->role] = true;
    columns.push_back(*col);
  }
  if (!seen[0]) {
    throw std::invalid_argument(csv.located("the header has no arc-length column s_m (or s_km)"));
  }
  std::vector<std::string> fields;
  while (csv.next(fields)) {
    std::array<double, 5> row{};
    for (std::size_t i = 0; i < fields.size(); ++i) {
      row[columns[i].role] = csv.number(fields, i) * columns[i].to_si;
    }
    if (!s_.empty() && !(row[0] > s_.back())) {
      throw std::invalid_argument(csv.located(
          fmt::format("s = {} m does not increase (previous row: {} m)", row[0], s_.back())));
    }
    s_.push_back(row[0]);
    for (int c = 0; c < 4; ++c) values_[c].push_back(row[c + 1]);
  }
  if (s_.size() < 2) {
    throw std::invalid_argument(
        csv.located(fmt::format("at least two data rows are needed (found {})", s_.size())));
  }
  finish();
}

MeasuredIrregularity::MeasuredIrregularity(std::vector<double> s, std::vector<double> lateral,
                                           std::vector<double> vertical,
                                           std::vector<double> cross_level,
                                           std::vector<double> gauge, std::string source)
    : source_(std::move(source)), s_(std::move(s)) {
  values_ = {std::move(lateral), std::move(vertical), std::move(cross_level), std::move(gauge)};
  finish();
}

void MeasuredIrregularity::finish() {
  const std::size_t n = s_.size();
  if (n < 2) {
    throw std::invalid_argument(fmt::format("{}: at least two samples are needed", source_));
  }
  for (const auto& v : values_) {
    if (v.size() != n) {
      throw std::invalid_argument(
          fmt::format("{}: every channel needs {} samples (got {})", source_, n, v.size()));
    }
  }
  for (std::size_t i = 1; i < n; ++i) {
    if (!(s_[i] > s_[i - 1])) {
      throw std::invalid_argument(fmt::format(
          "{}: s must increase strictly (sample {}: {} after {})", source_, i, s_[i], s_[i - 1]));
    }
  }
  for (int c = 0; c < 4; ++c) {
    const auto& y = values_[c];
    auto& m = slopes_[c];
    m.assign(n, 0.0);
    m[0] = (y[1] - y[0]) / (s_[1] - s_[0]);
    m[n - 1] = (y[n - 1] - y[n - 2]) / (s_[n - 1] - s_[n - 2]);
    if (n >= 3) {
      // Ends: slope of the parabola through the three end points.
      const double h0 = s_[1] - s_[0], h1 = s_[2] - s_[1];
      const double d0 = (y[1] - y[0]) / h0, d1 = (y[2] - y[1]) / h1;
      m[0] = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
      const double ha = s_[n - 2] - s_[n - 3], hb = s_[n - 1] - s_[n - 2];
      const double da = (y[n - 2] - y[n - 3]) / ha, db = (y[n - 1] - y[n - 2]) / hb;
      m[n - 1] = ((2 * hb + ha) * db - hb * da) / (ha + hb);
    }
    for (std::size_t i = 1; i + 1 < n; ++i) {
      // Slope of the parabola through three points.
      const double h0 = s_[i] - s_[i - 1], h1 = s_[i + 1] - s_[i];
      const double d0 = (y[i] - y[i - 1]) / h0, d1 = (y[i + 1] - y[i]) / h1;
      m[i] = (h1 * d0 + h0 * d1) / (h0 + h1);
    }
  }
}

std::string MeasuredIrregularity::name() const {
  return fmt::format("measured ({}, {} samples over [{}, {}] m)", source_, s_.size(), s_.front(),
                     s_.back());
}

IrregularitySample MeasuredIrregularity::at(double s) const {
  IrregularitySample out;
  if (!(s > s_.front())) {
    out.lateral = values_[0].front();
    out.vertical = values_[1].front();
    out.cross_level = values_[2].front();
    out.gauge = values_[3].front();
    return out;
  }
  if (s >= s_.back()) {
    out.lateral = values_[0].back();
    out.vertical = values_[1].back();
    out.cross_level = values_[2].back();
    out.gauge = values_[3].back();
    return out;
  }
  const numerics::AxisCell cell = numerics::locate(s_, s);
  const std::size_t j = cell.index;
  const double h = s_[j + 1] - s_[j];
  const numerics::HermiteBasis b(cell.t);
  constexpr std::array<IrregularityChannel, 4> kOrder = {
      IrregularityChannel::kLateral, IrregularityChannel::kVertical,
      IrregularityChannel::kCrossLevel, IrregularityChannel::kGauge};
  for (int c = 0; c < 4; ++c) {
    const auto& y = values_[c];
    const auto& m = slopes_[c];
    const double v = b.h00 * y[j] + b.h10 * h * m[j] + b.h01 * y[j + 1] + b.h11 * h * m[j + 1];
    const double dv = (b.g00 * y[j] + b.g01 * y[j + 1]) / h + b.g10 * m[j] + b.g11 * m[j + 1];
    out.add(kOrder[c], v, dv);
  }
  return out;
}

}  // namespace ferro::track
