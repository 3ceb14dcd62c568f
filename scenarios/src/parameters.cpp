#include "ferro/scenarios/parameters.hpp"

#include <stdexcept>

namespace ferro::scenarios {

std::string spelled(std::string_view key, Spelling spelling) {
  if (spelling == Spelling::key) return std::string(key);
  std::string s = "--";
  for (char c : key) s += c == '_' ? '-' : c;
  return s;
}

std::string parameter_help(const Parameter& p) {
  return p.unit.empty() ? p.help : p.help + " [" + p.unit + "]";
}

Parameters select_parameters(const Parameters& all, const std::vector<std::string_view>& keys) {
  Parameters out;
  for (std::string_view key : keys) {
    bool found = false;
    for (const Parameter& p : all) {
      if (p.key == key) {
        out.push_back(p);
        found = true;
      }
    }
    if (!found) throw std::logic_error("no parameter '" + std::string(key) + "'");
  }
  return out;
}

}  // namespace ferro::scenarios
