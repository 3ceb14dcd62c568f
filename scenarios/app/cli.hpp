#pragma once
// The ferrodyn command line. Each verb group (one file in scenarios/app/) registers its
// subcommands on the root app; the chosen subcommand stores its handler, which run_main calls.
//
// Error convention for handlers: throw std::invalid_argument for bad user input (the message
// names the file, key or option and the allowed values) -> exit code 2; throw
// std::runtime_error for a failed run -> exit code 1. Handlers return their own exit code.

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
class Option;
}

namespace ferro::scenarios {
struct Parameter;
}

namespace ferro::cli {

using VerbHandler = std::function<int()>;

/// Exit codes of the ferrodyn program.
inline constexpr int kExitOk = 0;
inline constexpr int kExitRunFailure = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInterrupted = 130;

// Flags that every verb spells the same way. Old spellings stay accepted, hidden from the help,
// for one release.
/// The output (file or folder) of a verb: -o/--output.
CLI::Option* add_output_option(CLI::App* cmd, std::string& target, const std::string& help,
                               const std::vector<std::string>& old_names = {});
/// The switch that skips pictures: --no-plots.
void add_no_plots_flag(CLI::App* cmd, bool& target,
                       const std::vector<std::string>& old_names = {});
/// The switch that lets a verb replace existing output files: --overwrite.
void add_overwrite_flag(CLI::App* cmd, bool& target);

// Strict option values. strict_values() gives every option of `app` and its subcommands the
// checks that hold for all: a number option takes one whole finite number (no "nan", "inf",
// "", "1x"), a text option a non-empty text. A parameter's range (parameters.hpp) is checked by
// its option (add_parameters); the message names the option, the allowed range and the value.
void strict_values(CLI::App& app);

/// Exit status of the plotting scripts when python3-matplotlib or python3-h5py is missing.
inline constexpr int kPlotsNeedPython = 3;

/// One option per parameter (scenarios/parameters.hpp): --key ('-' for '_'; -j for jobs), its
/// help with the unit, the default shown when it has one, the check of its range, its former
/// key as a hidden option; a switch on by default is --no-key.
void add_parameters(CLI::App* cmd, const std::vector<scenarios::Parameter>& parameters);
/// A hidden alias (a former spelling) of an option that takes a text.
void add_hidden_alias(CLI::App* cmd, const std::string& old_name, std::string& target);
/// Once `cmd` is parsed, `handler` is set to run `verb(*args)`.
template <class Args, class Verb>
void on_parsed(CLI::App* cmd, VerbHandler& handler, std::shared_ptr<Args> args, Verb verb);
/// A verb: the subcommand `name` of `parent` and its arguments (default Args, for the caller to
/// bind to options); once it is parsed, `handler` runs `verb(*args)`.
template <class Args, class Verb>
std::pair<CLI::App*, std::shared_ptr<Args>> add_verb(CLI::App* parent, VerbHandler& handler,
                                                     Verb verb, const std::string& name,
                                                     const std::string& help);

/// Parses argv, runs the chosen verb, returns the process exit code.
int run_main(int argc, char** argv);

// Verb groups. Each adds its subcommands to `app` and, from the subcommand's callback, sets
// `handler` to the work to do once parsing has finished.
void add_scene_commands(CLI::App& app, VerbHandler& handler);    // run, plot, validate
void add_contact_commands(CLI::App& app, VerbHandler& handler);  // contact eval, curve, patch
void add_geometry_commands(CLI::App& app, VerbHandler& handler); // geometry search, pair
/// After add_contact_commands: contact mim (and the hidden top-level mim).
void add_mim_commands(CLI::App& app, VerbHandler& handler);
/// After add_contact_commands: contact mim-table.
void add_mim_table_commands(CLI::App& app, VerbHandler& handler);
/// After add_contact_commands: contact wheelset.
void add_wheelset_contact_commands(CLI::App& app, VerbHandler& handler);
void add_bench_commands(CLI::App& app, VerbHandler& handler);    // bench contact
void add_fe_kij_commands(CLI::App& app, VerbHandler& handler);   // fe-kij
/// assess, eig, critical-speed {ramp, bifurcation, eigen}, kij-study, sweep
void add_analysis_commands(CLI::App& app, VerbHandler& handler);

}  // namespace ferro::cli

#include <CLI/CLI.hpp>

namespace ferro::cli {
template <class Args, class Verb>
void on_parsed(CLI::App* cmd, VerbHandler& handler, std::shared_ptr<Args> args, Verb verb) {
  cmd->callback([&handler, args, verb] { handler = [args, verb] { return verb(*args); }; });
}
template <class Args, class Verb>
std::pair<CLI::App*, std::shared_ptr<Args>> add_verb(CLI::App* parent, VerbHandler& handler,
                                                     Verb verb, const std::string& name,
                                                     const std::string& help) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = parent->add_subcommand(name, help);
  on_parsed(cmd, handler, args, verb);
  return {cmd, args};
}
}  // namespace ferro::cli
