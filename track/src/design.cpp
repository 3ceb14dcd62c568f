// Validation of the design-geometry parameter structs.
//
// References: EN 13803:2017 (section types; cant limits are a design rule, not checked here
// beyond |cant| < rail_spacing).
// Known deviations: none.

#include "ferro/track/design.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace ferro::track {

SectionKind section_kind_from_string(std::string_view name, const std::string& where) {
  if (name == "straight") return SectionKind::kStraight;
  if (name == "transition" || name == "clothoid") return SectionKind::kTransition;
  if (name == "curve" || name == "circular") return SectionKind::kCurve;
  throw std::invalid_argument(fmt::format(
      "{}: unknown section kind '{}' (allowed: straight, transition, curve)", where, name));
}

std::string_view to_string(SectionKind kind) {
  switch (kind) {
    case SectionKind::kStraight:
      return "straight";
    case SectionKind::kTransition:
      return "transition";
    case SectionKind::kCurve:
      return "curve";
  }
  return "?";
}

void SectionSpec::validate(const std::string& where) const {
  if (!(std::isfinite(length) && length > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{}.length: must be positive and finite [m] (got {})", where, length));
  }
  if (!std::isfinite(cant)) {
    throw std::invalid_argument(fmt::format("{}.cant: must be finite [m] (got {})", where, cant));
  }
  if (!(std::isfinite(gauge_widening) && gauge_widening >= 0.0)) {
    throw std::invalid_argument(fmt::format(
        "{}.gauge_widening: must be finite and >= 0 [m] (got {})", where, gauge_widening));
  }
  if (kind == SectionKind::kCurve) {
    if (!(std::isfinite(radius) && radius != 0.0)) {
      throw std::invalid_argument(fmt::format(
          "{}.radius: must be non-zero and finite for a curve, positive turning left [m] (got {})",
          where, radius));
    }
    return;
  }
  // Straights and transitions take no own radius, cant or widening.
  const auto kind_name = to_string(kind);
  if (!std::isnan(radius)) {
    throw std::invalid_argument(
        fmt::format("{}.radius: only a curve has a radius; a {} {} (got {})", where, kind_name,
                    kind == SectionKind::kStraight ? "has zero curvature"
                                                   : "takes its curvatures from its neighbours",
                    radius));
  }
  if (cant != 0.0) {
    throw std::invalid_argument(fmt::format(
        "{}.cant: only a curve has its own cant; a {} {} (got {})", where, kind_name,
        kind == SectionKind::kStraight ? "has zero cant" : "ramps between its neighbours", cant));
  }
  if (gauge_widening != 0.0) {
    throw std::invalid_argument(
        fmt::format("{}.gauge_widening: only a curve has its own gauge widening (got {})", where,
                    gauge_widening));
  }
}

void TrackDesign::validate(const std::string& where) const {
  // Field names are prefixed with `where.` when a prefix is given.
  const std::string pre = where.empty() ? std::string() : where + ".";
  if (sections.empty()) {
    throw std::invalid_argument(fmt::format("{}sections: at least one section is required", pre));
  }
  auto check_finite = [&pre](double v, const char* name) {
    if (!std::isfinite(v)) {
      throw std::invalid_argument(fmt::format("{}{}: must be finite (got {})", pre, name, v));
    }
  };
  check_finite(start_s, "start_s");
  check_finite(start_x, "start_x");
  check_finite(start_y, "start_y");
  check_finite(start_heading, "start_heading");
  if (!(std::isfinite(gauge) && gauge > 0.0)) {
    throw std::invalid_argument(fmt::format("{}gauge: must be positive [m] (got {})", pre, gauge));
  }
  if (!(std::isfinite(rail_spacing) && rail_spacing > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{}rail_spacing: must be positive [m] (got {})", pre, rail_spacing));
  }
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const auto name = fmt::format("{}sections[{}]", pre, i);
    sections[i].validate(name);
    if (std::abs(sections[i].cant) >= rail_spacing) {
      throw std::invalid_argument(
          fmt::format("{}.cant: |cant| must be smaller than rail_spacing = {} m (got {})", name,
                      rail_spacing, sections[i].cant));
    }
    if (i > 0 && sections[i].kind == SectionKind::kTransition &&
        sections[i - 1].kind == SectionKind::kTransition) {
      throw std::invalid_argument(fmt::format(
          "{}.kind: a transition cannot follow a transition (sections[{}]); put a curve or "
          "straight between them",
          name, i - 1));
    }
  }
}

double TrackDesign::total_length() const {
  double sum = 0.0;
  for (const auto& sec : sections) sum += sec.length;
  return sum;
}

}  // namespace ferro::track
