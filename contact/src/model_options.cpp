// Parsers of contact-model options (see the header).
//
// References: none (input handling). Known deviations: none.
#include "ferro/contact/model_options.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "ferro/io/csv.hpp"

namespace ferro::contact {

double option_double(const ModelOptions& options, const std::string& key, double fallback) {
  const auto it = options.find(key);
  if (it == options.end()) return fallback;
  const std::optional<double> v = io::parse_number(it->second);
  if (v && std::isfinite(*v)) return *v;
  throw std::invalid_argument(
      fmt::format("option '{}': expected a finite number, got '{}'", key, it->second));
}

int option_int(const ModelOptions& options, const std::string& key, int fallback) {
  const auto it = options.find(key);
  if (it == options.end()) return fallback;
  try {
    std::size_t used = 0;
    const int v = std::stoi(it->second, &used);
    if (used != it->second.size()) throw std::invalid_argument("trailing characters");
    return v;
  } catch (const std::exception&) {
    throw std::invalid_argument(
        fmt::format("option '{}': expected an integer, got '{}'", key, it->second));
  }
}

std::string option_string(const ModelOptions& options, const std::string& key,
                          const std::string& fallback) {
  const auto it = options.find(key);
  return it == options.end() ? fallback : it->second;
}

void check_option_keys(std::string_view model, const ModelOptions& options,
                       const std::vector<std::string>& allowed) {
  for (const auto& [key, value] : options) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw std::invalid_argument(fmt::format(
          "model '{}': unknown option '{}'; allowed: {}", model, key,
          allowed.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(allowed, ", "))));
    }
  }
}

}  // namespace ferro::contact
