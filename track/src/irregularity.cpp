// Irregularity samples, their sum, and isolated defects.
//
// References: EN 13848-1:2019 (channel definitions); Toumi (2016) §4.3 (lateral alignment
// defect of given amplitude exciting the hunting motion), §4.2 (local twist defect).
// Known deviations: none beyond irregularity.hpp.

#include "ferro/track/irregularity.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ferro::track {

IrregularityChannel irregularity_channel_from_string(std::string_view name,
                                                     const std::string& where) {
  if (name == "lateral" || name == "alignment") return IrregularityChannel::kLateral;
  if (name == "vertical" || name == "level") return IrregularityChannel::kVertical;
  if (name == "cross_level") return IrregularityChannel::kCrossLevel;
  if (name == "gauge") return IrregularityChannel::kGauge;
  throw std::invalid_argument(fmt::format(
      "{}: unknown irregularity channel '{}' (allowed: lateral, vertical, cross_level, gauge)",
      where, name));
}

std::string_view to_string(IrregularityChannel channel) {
  switch (channel) {
    case IrregularityChannel::kLateral:
      return "lateral";
    case IrregularityChannel::kVertical:
      return "vertical";
    case IrregularityChannel::kCrossLevel:
      return "cross_level";
    case IrregularityChannel::kGauge:
      return "gauge";
  }
  return "?";
}

double IrregularitySample::value(IrregularityChannel channel) const {
  switch (channel) {
    case IrregularityChannel::kLateral:
      return lateral;
    case IrregularityChannel::kVertical:
      return vertical;
    case IrregularityChannel::kCrossLevel:
      return cross_level;
    case IrregularityChannel::kGauge:
      return gauge;
  }
  return 0.0;
}

double IrregularitySample::derivative(IrregularityChannel channel) const {
  switch (channel) {
    case IrregularityChannel::kLateral:
      return d_lateral;
    case IrregularityChannel::kVertical:
      return d_vertical;
    case IrregularityChannel::kCrossLevel:
      return d_cross_level;
    case IrregularityChannel::kGauge:
      return d_gauge;
  }
  return 0.0;
}

void IrregularitySample::add(IrregularityChannel channel, double v, double dv) {
  switch (channel) {
    case IrregularityChannel::kLateral:
      lateral += v;
      d_lateral += dv;
      break;
    case IrregularityChannel::kVertical:
      vertical += v;
      d_vertical += dv;
      break;
    case IrregularityChannel::kCrossLevel:
      cross_level += v;
      d_cross_level += dv;
      break;
    case IrregularityChannel::kGauge:
      gauge += v;
      d_gauge += dv;
      break;
  }
}

IrregularitySample& IrregularitySample::operator+=(const IrregularitySample& o) {
  lateral += o.lateral;
  vertical += o.vertical;
  cross_level += o.cross_level;
  gauge += o.gauge;
  d_lateral += o.d_lateral;
  d_vertical += o.d_vertical;
  d_cross_level += o.d_cross_level;
  d_gauge += o.d_gauge;
  return *this;
}

RailIrregularity IrregularitySample::left_rail() const {
  return {lateral + 0.5 * gauge, vertical - 0.5 * cross_level, d_lateral + 0.5 * d_gauge,
          d_vertical - 0.5 * d_cross_level};
}

RailIrregularity IrregularitySample::right_rail() const {
  return {lateral - 0.5 * gauge, vertical + 0.5 * cross_level, d_lateral - 0.5 * d_gauge,
          d_vertical + 0.5 * d_cross_level};
}

IrregularitySum::IrregularitySum(std::vector<std::shared_ptr<const Irregularity>> parts) {
  for (auto& p : parts) add(std::move(p));
}

void IrregularitySum::add(std::shared_ptr<const Irregularity> part) {
  if (!part) throw std::invalid_argument("irregularities: a part of the sum is null");
  parts_.push_back(std::move(part));
}

std::string IrregularitySum::name() const {
  std::string out = "sum(";
  for (std::size_t i = 0; i < parts_.size(); ++i) {
    if (i > 0) out += ", ";
    out += parts_[i]->name();
  }
  return out + ")";
}

IrregularitySample IrregularitySum::at(double s) const {
  IrregularitySample total;
  for (const auto& p : parts_) total += p->at(s);
  return total;
}

DefectShape defect_shape_from_string(std::string_view name, const std::string& where) {
  if (name == "one_minus_cosine" || name == "1-cos") return DefectShape::kOneMinusCosine;
  if (name == "sine") return DefectShape::kSine;
  if (name == "dipped_joint") return DefectShape::kDippedJoint;
  throw std::invalid_argument(
      fmt::format("{}: unknown defect shape '{}' (allowed: one_minus_cosine, sine, dipped_joint)", where, name));
}

void IsolatedDefectSpec::validate(const std::string& where) const {
  if (!std::isfinite(amplitude)) {
    throw std::invalid_argument(
        fmt::format("{}.amplitude: must be finite [m] (got {})", where, amplitude));
  }
  if (!(std::isfinite(wavelength) && wavelength > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{}.wavelength: must be positive and finite [m] (got {})", where, wavelength));
  }
  if (!std::isfinite(start_s)) {
    throw std::invalid_argument(
        fmt::format("{}.start_s: must be finite [m] (got {})", where, start_s));
  }
  if (periods < 1) {
    throw std::invalid_argument(fmt::format("{}.periods: must be >= 1 (got {})", where, periods));
  }
}

IsolatedDefect::IsolatedDefect(const IsolatedDefectSpec& spec) : spec_(spec) {
  spec_.validate();
}

std::string IsolatedDefect::name() const {
  return fmt::format("isolated {} defect ({} m over {} x {} m at s = {} m)",
                     to_string(spec_.channel), spec_.amplitude, spec_.periods, spec_.wavelength,
                     spec_.start_s);
}

IrregularitySample IsolatedDefect::at(double s) const {
  IrregularitySample out;
  const double x = s - spec_.start_s;
  if (!(x > 0.0 && x < spec_.periods * spec_.wavelength)) return out;
  const double k = 2.0 * std::numbers::pi / spec_.wavelength;
  double v = 0.0, dv = 0.0;
  switch (spec_.shape) {
    case DefectShape::kOneMinusCosine:
      v = 0.5 * spec_.amplitude * (1.0 - std::cos(k * x));
      dv = 0.5 * spec_.amplitude * k * std::sin(k * x);
      break;
    case DefectShape::kSine:
      v = spec_.amplitude * std::sin(k * x);
      dv = spec_.amplitude * k * std::cos(k * x);
      break;
    case DefectShape::kDippedJoint: {
      const double u = 2.0 * std::fmod(x, spec_.wavelength) / spec_.wavelength - 1.0;  // [-1, 1)
      v = spec_.amplitude * (1.0 - std::abs(u));
      dv = spec_.amplitude * 2.0 / spec_.wavelength * (u < 0.0 ? 1.0 : -1.0);
      break;
    }
  }
  out.add(spec_.channel, v, dv);
  return out;
}

}  // namespace ferro::track
