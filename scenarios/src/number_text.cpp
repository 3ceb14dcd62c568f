#include "ferro/scenarios/number_text.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace ferro::scenarios {

double strict_number(const std::string& text) {
  if (text.empty()) return std::nan("");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    return std::nan("");
  return v;
}

std::string NumberRange::text() const {
  const std::string u = unit.empty() ? "" : " " + unit;
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi)
    return fmt::format("in {}{:g}, {:g}{}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]", u);
  if (has_lo) return fmt::format("{} {:g}{}", lo_open ? ">" : ">=", lo, u);
  if (has_hi) return fmt::format("{} {:g}{}", hi_open ? "<" : "<=", hi, u);
  return "a finite number";
}

std::string NumberRange::problem(const std::string& value) const {
  const double v = strict_number(value);
  const bool ok =
      !std::isnan(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  return ok ? std::string() : fmt::format("must be {}, got '{}'", text(), value);
}

std::string CountRange::text() const {
  return hi == std::numeric_limits<long>::max() ? fmt::format(">= {}", lo)
                                                : fmt::format("in {}..{}", lo, hi);
}

std::string CountRange::problem(const std::string& value) const {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(value.c_str(), &end, 10);
  const bool ok = !value.empty() && end == value.c_str() + value.size() && errno == 0 &&
                  v >= lo && v <= hi;
  return ok ? std::string() : fmt::format("must be a whole number {}, got '{}'", text(), value);
}

}  // namespace ferro::scenarios
