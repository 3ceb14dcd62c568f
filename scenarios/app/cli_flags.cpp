// Flags shared by every verb and what the environment adds to them (see cli.hpp).
#include <CLI/CLI.hpp>
#include <cstdlib>

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

std::map<std::string, std::string> with_environment_options(
    const std::string& model, std::map<std::string, std::string> options) {
  if (model == "mim_table" && options.count("table") == 0) {
    const char* table = std::getenv("FERRO_MIM_TABLE");
    if (table != nullptr && *table != '\0') options["table"] = table;
  }
  return options;
}

}  // namespace ferro::cli
