#pragma once
// Options of a contact model as a scene, a case file or the command line give them (string
// key -> string value), and the helpers each model uses to parse its own.
//
// References: none (input handling). Known deviations: none.

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <initializer_list>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ferro::contact {

/// String options of a model, as read from YAML or the command line ("strips" -> "200").
using ModelOptions = std::map<std::string, std::string>;

/// Option parsers (throw std::invalid_argument naming the key and the value).
[[nodiscard]] double option_double(const ModelOptions& options, const std::string& key,
                                   double fallback);
[[nodiscard]] int option_int(const ModelOptions& options, const std::string& key, int fallback);
[[nodiscard]] std::string option_string(const ModelOptions& options, const std::string& key,
                                        const std::string& fallback);
/// Throws std::invalid_argument if options hold a key not in `allowed`.
void check_option_keys(std::string_view model, const ModelOptions& options,
                       const std::vector<std::string>& allowed);

/// The value of option `key` among named choices (`fallback` when absent); throws
/// std::invalid_argument "<model> option '<key>': unknown value '<v>'; allowed: <names>".
template <class Value>
[[nodiscard]] Value option_choice(std::string_view model, const ModelOptions& options,
                                  const std::string& key,
                                  std::initializer_list<std::pair<std::string_view, Value>> choices,
                                  std::string_view fallback) {
  const auto it = options.find(key);
  const std::string_view given = it == options.end() ? fallback : std::string_view(it->second);
  std::vector<std::string_view> names;
  for (const auto& [name, value] : choices) {
    if (name == given) return value;
    names.push_back(name);
  }
  throw std::invalid_argument(fmt::format("{} option '{}': unknown value '{}'; allowed: {}", model,
                                          key, given, fmt::join(names, ", ")));
}

/// The names of a registry's entries (each with a `name`), in registry order.
template <class Entry>
[[nodiscard]] std::vector<std::string> registry_names(std::span<const Entry> entries) {
  std::vector<std::string> names;
  for (const Entry& e : entries) names.emplace_back(e.name);
  return names;
}

/// The registry entry named `name`; throws std::invalid_argument "unknown <kind> contact model
/// '<name>'; allowed: <names>".
template <class Entry>
[[nodiscard]] const Entry& registry_entry(std::span<const Entry> entries, std::string_view name,
                                          std::string_view kind) {
  for (const Entry& e : entries) {
    if (e.name == name) return e;
  }
  throw std::invalid_argument(fmt::format("unknown {} contact model '{}'; allowed: {}", kind, name,
                                          fmt::join(registry_names(entries), ", ")));
}

}  // namespace ferro::contact
