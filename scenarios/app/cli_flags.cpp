// Flags shared by every verb and the strict reading of every option value (see cli.hpp).
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "cli.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/parameters.hpp"

namespace ferro::cli {
namespace {

// The number in `text`, or NaN when it is not one whole finite number.
double strict_number(const std::string& text) {
  if (text.empty()) return std::nan("");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
    return std::nan("");
  return v;
}

std::string bound_text(double lo, double hi, bool lo_open, bool hi_open, const std::string& unit) {
  const std::string u = unit.empty() ? "" : " " + unit;
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi)
    return fmt::format("in {}{:g}, {:g}{}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]", u);
  if (has_lo) return fmt::format("{} {:g}{}", lo_open ? ">" : ">=", lo, u);
  if (has_hi) return fmt::format("{} {:g}{}", hi_open ? "<" : "<=", hi, u);
  return "a finite number";
}

}  // namespace

CLI::Option* add_output_option(CLI::App* cmd, std::string& target, const std::string& help,
                               const std::vector<std::string>& old_names) {
  CLI::Option* option = cmd->add_option("-o,--output", target, help);
  for (const auto& name : old_names) add_hidden_alias(cmd, name, target);
  return option;
}

void add_no_plots_flag(CLI::App* cmd, bool& target, const std::vector<std::string>& old_names) {
  cmd->add_flag("--no-plots", target, "Do not draw pictures (write the data files only)");
  for (const auto& name : old_names) cmd->add_flag(name, target)->group("");
}

void add_overwrite_flag(CLI::App* cmd, bool& target) {
  cmd->add_flag("--overwrite", target, "Replace output files that exist already");
}

CLI::Validator number_in(double lo, double hi, bool lo_open, bool hi_open,
                         const std::string& unit) {
  const std::string allowed = bound_text(lo, hi, lo_open, hi_open, unit);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const double v = strict_number(text);
        const bool ok = !std::isnan(v) && (lo_open ? v > lo : v >= lo) &&
                        (hi_open ? v < hi : v <= hi);
        return ok ? std::string() : fmt::format("must be {}, got '{}'", allowed, text);
      },
      allowed);
}

CLI::Validator count_in(long lo, long hi) {
  const std::string allowed = hi == std::numeric_limits<long>::max()
                                  ? fmt::format(">= {}", lo)
                                  : fmt::format("in {}..{}", lo, hi);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        char* end = nullptr;
        errno = 0;
        const long v = std::strtol(text.c_str(), &end, 10);
        const bool ok = !text.empty() && end == text.c_str() + text.size() && errno == 0 &&
                        v >= lo && v <= hi;
        return ok ? std::string() : fmt::format("must be a whole number {}, got '{}'", allowed, text);
      },
      allowed);
}

void check_plot_folder(const std::string& dir, const std::string& what) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::absolute(dir);
  // Folders missing on the way are made for the probe and removed again.
  std::vector<fs::path> missing;
  std::error_code ec;
  fs::path existing = folder;
  while (!fs::exists(existing, ec) && existing != existing.parent_path()) {
    missing.push_back(existing);
    existing = existing.parent_path();
  }
  const auto fail = [&](const std::string& why) {
    for (const auto& m : missing) rmdir(m.c_str());
    throw std::invalid_argument(fmt::format("{}: cannot write the plots in '{}': {}", what, dir, why));
  };
  if (!fs::is_directory(existing, ec)) fail(fmt::format("'{}' is not a folder", existing.string()));
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (mkdir(it->c_str(), 0777) != 0) fail(std::strerror(errno));
  }
  std::string probe = (folder / ".ferrodyn-probe-XXXXXX").string();
  const int fd = mkstemp(probe.data());
  if (fd < 0) fail(std::strerror(errno));
  close(fd);
  unlink(probe.c_str());
  for (const auto& m : missing) rmdir(m.c_str());
}

void strict_values(CLI::App& app) {
  const double inf = std::numeric_limits<double>::infinity();
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (type == "FLOAT") option->check(number_in(-inf, inf, true, true, ""));
    if (type == "TEXT") {
      option->check(CLI::Validator(
          [](std::string& text) {
            return text.empty() ? std::string("must not be empty") : std::string();
          },
          ""));
    }
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) strict_values(*sub);
}

void add_parameters(CLI::App* cmd, const std::vector<scenarios::Parameter>& parameters) {
  for (const scenarios::Parameter& p : parameters) {
    const std::string name =
        (p.key == "jobs" ? "-j," : "") + scenarios::spelled(p.key, scenarios::Spelling::option);
    const std::string help = scenarios::parameter_help(p);
    if (bool* const* flag = std::get_if<bool*>(&p.target)) {
      bool* target = *flag;
      if (*target) {
        cmd->add_flag_function(
            "--no-" + name.substr(2), [target](std::int64_t) { *target = false; }, "skip " + help);
      } else {
        cmd->add_flag(name, *target, help);
      }
      continue;
    }
    CLI::Option* o = std::visit(
        [&](auto* target) -> CLI::Option* {
          if constexpr (std::is_same_v<decltype(target), bool*>) {
            return nullptr;
          } else {
            return cmd->add_option(name, *target, help);
          }
        },
        p.target);
    if (std::holds_alternative<std::vector<double>*>(p.target) ||
        std::holds_alternative<std::vector<std::string>*>(p.target))
      o->delimiter(',');
    if (p.has_default) o->capture_default_str();
  }
}

}  // namespace ferro::cli
