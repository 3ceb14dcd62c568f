#pragma once
// Strict reading of numbers given as text (command-line values): one whole finite number, no
// "nan", "inf", "", "1x"; with the range a value must lie in and the message when it does not.

#include <limits>
#include <string>

namespace ferro::scenarios {

/// The number in `text`, or NaN when it is not one whole finite number.
[[nodiscard]] double strict_number(const std::string& text);

/// The end of a NumberRange that has no bound.
inline constexpr double kNoBound = std::numeric_limits<double>::infinity();

/// A range of finite numbers lo..hi, ends open or closed; an infinite end: no bound on that side.
struct NumberRange {
  double lo, hi;
  bool lo_open, hi_open;
  std::string unit;  ///< appended to the text of the bounds ("" for none)
  /// "in [0, 2)", ">= 0 m", "< 1", or "a finite number" without bounds.
  [[nodiscard]] std::string text() const;
  /// Empty when `value` is a strict number in the range, else "must be <text()>, got '<value>'".
  [[nodiscard]] std::string problem(const std::string& value) const;
};

/// A range of whole numbers lo..hi (hi = LONG_MAX: no upper bound).
struct CountRange {
  long lo, hi;
  /// "in 1..1024" or ">= 0".
  [[nodiscard]] std::string text() const;
  /// Empty when `value` is one whole number in the range, else
  /// "must be a whole number <text()>, got '<value>'".
  [[nodiscard]] std::string problem(const std::string& value) const;
};

}  // namespace ferro::scenarios
