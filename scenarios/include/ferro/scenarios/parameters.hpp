#pragma once
// The user-settable values of a request struct, named once: key, unit and meaning. The command
// line declares one option per parameter (--key, with '-' for '_'; a switch that is on by
// default becomes --no-key), the Python module one keyword argument, each with this text as its
// help; errors name the same key (see Spelling).

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "ferro/scenarios/number_text.hpp"

namespace ferro::scenarios {

/// How an error names a value: as a key (`t_end`, the Python keyword) or as a command-line
/// option (`--t-end`: the key with '-' for '_').
enum class Spelling { key, option };

/// `key` spelled for messages: unchanged, or "--" + key with '_' replaced by '-'.
[[nodiscard]] std::string spelled(std::string_view key, Spelling spelling);

/// A former key of a parameter in another unit (e.g. y_mm for y [m]), still read: its value times
/// `to_si` is the parameter's. The command line takes it as a hidden option; given together
/// with the parameter it is bad input.
struct FormerKey {
  std::string key;     ///< snake_case name
  double to_si = 1.0;  ///< factor to the parameter's unit
};

struct Parameter {
  using Target = std::variant<double*, int*, bool*, std::string*, std::vector<double>*,
                              std::vector<std::string>*>;
  std::string key;   ///< snake_case name
  std::string unit;  ///< SI unit ("-": dimensionless; "": a name, a list or a switch)
  std::string help;  ///< meaning and allowed values
  Target target;     ///< the field it sets
  /// The field's initial value is a real default worth showing (false: an "unset" marker such
  /// as NaN, keep the scene's value).
  bool has_default = true;
  /// The numbers a number parameter takes (none: any finite number); the command line refuses
  /// others naming the option, the range and the value.
  std::optional<NumberRange> range = std::nullopt;
  /// The whole numbers a count parameter takes (none: any).
  std::optional<CountRange> count = std::nullopt;
  std::optional<FormerKey> former = std::nullopt;

  /// This parameter, taking the numbers in `r` only.
  [[nodiscard]] Parameter within(NumberRange r) && {
    range = std::move(r);
    return std::move(*this);
  }
  /// This parameter, taking the whole numbers in `c` only.
  [[nodiscard]] Parameter counting(CountRange c) && {
    count = c;
    return std::move(*this);
  }
  /// This parameter, also read under `former_key` (value x `to_si`).
  [[nodiscard]] Parameter formerly(std::string former_key, double to_si = 1.0) && {
    former = FormerKey{std::move(former_key), to_si};
    return std::move(*this);
  }
};
using Parameters = std::vector<Parameter>;

/// Most worker threads a request takes (its `jobs`).
inline constexpr long kMaxJobs = 1024;

/// The help line of a parameter: its text, then " [unit]" when it has one.
[[nodiscard]] std::string parameter_help(const Parameter& p);

/// The parameters whose keys are listed, in that order. Throws std::logic_error for a key that
/// `all` does not have.
[[nodiscard]] Parameters select_parameters(const Parameters& all,
                                           const std::vector<std::string_view>& keys);

}  // namespace ferro::scenarios
