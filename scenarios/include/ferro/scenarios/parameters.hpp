#pragma once
// The user-settable values of a request struct, named once: key, unit and meaning. The command
// line declares one option per parameter (--key, with '-' for '_'; a switch that is on by
// default becomes --no-key), the Python module one keyword argument, each with this text as its
// help; errors name the same key (see Spelling).

#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ferro::scenarios {

/// How an error names a value: as a key (`t_end`, the Python keyword) or as a command-line
/// option (`--t-end`: the key with '-' for '_').
enum class Spelling { key, option };

/// `key` spelled for messages: unchanged, or "--" + key with '_' replaced by '-'.
[[nodiscard]] std::string spelled(std::string_view key, Spelling spelling);

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
};
using Parameters = std::vector<Parameter>;

/// The help line of a parameter: its text, then " [unit]" when it has one.
[[nodiscard]] std::string parameter_help(const Parameter& p);

/// The parameters whose keys are listed, in that order. Throws std::logic_error for a key that
/// `all` does not have.
[[nodiscard]] Parameters select_parameters(const Parameters& all,
                                           const std::vector<std::string_view>& keys);

}  // namespace ferro::scenarios
