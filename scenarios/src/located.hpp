#pragma once
// Turning a parameter struct's validate() message ("path.field: message") into an error at the
// field's line in the YAML file the struct was read from. Private to the scene loaders.

#include <string>

#include "ferro/scenarios/yaml_reader.hpp"

namespace ferro::scenarios::detail {

/// Runs `check`; a std::invalid_argument it throws becomes a YamlInputError located at the
/// deepest node of `reader` that the message's field path names. `strip` is removed from the
/// front of the field path first (e.g. the prefix validate() was given).
template <class F>
void located(const MapReader& reader, F&& check, const std::string& strip = "") {
  try {
    check();
  } catch (const YamlInputError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    const auto colon = msg.find(": ");
    std::string field = colon == std::string::npos ? std::string() : msg.substr(0, colon);
    for (const std::string& prefix : {strip.empty() ? std::string() : strip + ".",
                                      reader.path() + "."}) {
      if (!prefix.empty() && prefix != "." && field.rfind(prefix, 0) == 0)
        field = field.substr(prefix.size());
    }
    if (!field.empty() && field.front() == '.') field.erase(0, 1);
    // Walk to the deepest node that exists, through mappings and "name[i]" list items.
    YAML::Node at = reader.yaml();
    std::size_t start = 0;
    while (!field.empty() && start < field.size()) {
      const auto dot = field.find('.', start);
      std::string part =
          field.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
      long item = -1;
      if (const auto br = part.find('['); br != std::string::npos && part.back() == ']') {
        item = std::strtol(part.c_str() + br + 1, nullptr, 10);
        part = part.substr(0, br);
      }
      if (!at.IsMap() || !at[part].IsDefined()) break;
      YAML::Node next = at[part];
      if (item >= 0) {
        if (!next.IsSequence() || item >= static_cast<long>(next.size())) break;
        next = next[static_cast<std::size_t>(item)];
      }
      at = next;
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
    const auto [l, c] = position_of(at);
    throw YamlInputError(reader.file(), l, c,
                         field.empty() ? reader.path() : reader.key_path(field),
                         colon == std::string::npos ? msg : msg.substr(colon + 2));
  }
}

}  // namespace ferro::scenarios::detail
