// Flags shared by every verb and the strict reading of every option value (see cli.hpp).
#include <CLI/CLI.hpp>

#include "cli.hpp"
#include "ferro/scenarios/number_text.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/parameters.hpp"

namespace ferro::cli {

void add_hidden_alias(CLI::App* cmd, const std::string& old_name, std::string& target) {
  cmd->add_option(old_name, target)->group("");
}

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

namespace {
template <class Range>
CLI::Validator values_in(const Range& range) {
  return CLI::Validator([range](std::string& text) { return range.problem(text); }, range.text());
}

// The parameter's former key as a hidden option setting its value times to_si; given together
// with the parameter's own option it is bad input.
void add_former_key(CLI::App* cmd, const scenarios::Parameter& p, CLI::Option* option) {
  double* const* target = std::get_if<double*>(&p.target);
  if (target == nullptr) throw std::logic_error("former key of a parameter that is not a number");
  const std::string name = scenarios::spelled(p.former->key, scenarios::Spelling::option);
  cmd->add_option_function<double>(
         name,
         [value = *target, to_si = p.former->to_si, option, name](const double& v) {
           if (option->count() > 0)
             throw CLI::ValidationError(option->get_name(), "given twice (also as " + name + ")");
           *value = v * to_si;
         })
      ->group("");
}
}  // namespace

void strict_values(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (type == "FLOAT")
      option->check(values_in(scenarios::NumberRange{-scenarios::kNoBound, scenarios::kNoBound,
                                                      true, true, ""}));
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
    if (p.range) o->check(values_in(*p.range));
    if (p.count) o->check(values_in(*p.count));
    if (p.former) add_former_key(cmd, p, o);
  }
}

}  // namespace ferro::cli
