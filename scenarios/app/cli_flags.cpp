// Flags shared by every verb (see cli.hpp).
#include <CLI/CLI.hpp>

#include "cli.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/parameters.hpp"

namespace ferro::cli {

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
