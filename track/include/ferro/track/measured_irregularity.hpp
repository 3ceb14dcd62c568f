#pragma once
// Measured irregularities read from a CSV file and interpolated along s.
//
// File format: '#' starts a comment line; blank lines are skipped; the first other line is a
// header naming the columns, in any order, each with its unit: s_m (or s_km),
// lateral_m / lateral_mm, vertical_m / vertical_mm, cross_level_m / cross_level_mm,
// gauge_m / gauge_mm. `s` is required; a missing channel column reads as zero; unknown columns
// are an error. Separators: comma, semicolon or tab. s must increase strictly.
// Example:
//   # recorded 2026-05-01, chord-corrected
//   s_m,lateral_mm,vertical_mm,cross_level_mm,gauge_mm
//   0.00,0.0,0.0,0.0,0.0
//   0.25,0.4,-0.3,0.1,0.2
//
// Interpolation: piecewise cubic Hermite with slopes of the parabola through three
// neighbouring points (centred inside, one-sided at the ends): value and slope continuous,
// quadratics reproduced exactly. Outside [s_first, s_last] the first / last values hold, with zero
// slope.
//
// References: EN 13848-1:2019 (channel definitions; sign conventions as irregularity.hpp).
// Known deviations: the data are taken as already filtered; no resampling or chord-transfer
// correction is applied.

#include <array>
#include <string>
#include <vector>

#include "ferro/track/irregularity.hpp"

namespace ferro::track {

class MeasuredIrregularity final : public Irregularity {
 public:
  /// Reads `path`; throws std::invalid_argument with "<path>:<line>: <what>" for a bad file
  /// (unreadable, no header, unknown or duplicate column, wrong field count, a non-number, s not
  /// increasing, fewer than two rows).
  explicit MeasuredIrregularity(const std::string& path);
  /// From samples already in SI units (s strictly increasing, every vector the same size).
  MeasuredIrregularity(std::vector<double> s, std::vector<double> lateral,
                       std::vector<double> vertical, std::vector<double> cross_level,
                       std::vector<double> gauge, std::string source = "samples");

  [[nodiscard]] std::string name() const override;
  [[nodiscard]] IrregularitySample at(double s) const override;
  [[nodiscard]] std::size_t size() const { return s_.size(); }
  [[nodiscard]] double s_first() const { return s_.front(); }
  [[nodiscard]] double s_last() const { return s_.back(); }

 private:
  void finish();  // checks sizes and order, computes the Hermite slopes

  std::string source_;
  std::vector<double> s_;
  std::array<std::vector<double>, 4> values_;  // lateral, vertical, cross_level, gauge
  std::array<std::vector<double>, 4> slopes_;
};

}  // namespace ferro::track
