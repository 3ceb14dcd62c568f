// Flags shared by every verb (see cli.hpp).
#include <CLI/CLI.hpp>

#include "cli.hpp"

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

}  // namespace ferro::cli
