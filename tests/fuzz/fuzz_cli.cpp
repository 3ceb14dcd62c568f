// Fuzz target: the command line of the verbs that take a scene or a run (the options of `run`,
// `eig`, `assess`), through the program's own registration and strict option reading
// (scenarios/app/cli.hpp), and for `run` the overrides it applies to a scene. The first byte
// picks the verb (kVerbs; adding a verb is one line there), the rest are the arguments,
// separated by newlines or NUL bytes. No verb runs: a bad value must surface as a CLI11 parse
// error or std::invalid_argument (exit code 2 in the program); anything else escaping (another
// exception type, a crash, a sanitizer report) is a defect.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ferro/scenarios/overrides.hpp"
#include "ferro/scenarios/scene.hpp"

namespace {

// The verbs under test: the subcommand path each input's first byte selects.
const std::vector<std::vector<std::string>> kVerbs = {
    {"run"},
    {"eig"},
    {"assess"},
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const ferro::scenarios::Scene hunting =
      ferro::scenarios::load_scene("scenarios/scenes/wheelset_hunting.yaml");
  static const ferro::scenarios::Scene vehicle =
      ferro::scenarios::load_scene("scenarios/scenes/manchester_straight_erri.yaml");
  const auto& verb = kVerbs[data[0] % kVerbs.size()];
  std::vector<std::string> args = {"ferrodyn"};
  args.insert(args.end(), verb.begin(), verb.end());
  std::string token;
  for (std::size_t i = 1; i < size && args.size() < 40; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\n' || c == '\0') {
      args.push_back(token);
      token.clear();
    } else {
      token += c;
    }
  }
  if (!token.empty()) args.push_back(token);

  // The verbs are registered once (registering every option costs ~50x a parse); clear()
  // forgets the previous input's parse. A variable bound to an option keeps an earlier input's
  // value when this input does not give the option, as a parse only sets what it is given.
  static CLI::App app{"ferrodyn"};
  static ferro::cli::VerbHandler handler;
  static const bool registered = [] {
    ferro::cli::add_scene_commands(app, handler);
    ferro::cli::add_analysis_commands(app, handler);
    ferro::cli::strict_values(app);
    return true;
  }();
  (void)registered;
  app.clear();
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), const_cast<char**>(argv.data()));
  } catch (const CLI::ParseError&) {
    return 0;
  }
  if (verb.front() != "run") return 0;
  // The overrides `run` applies before it builds anything (read back after parsing), on a linear
  // and a vehicle scene.
  CLI::App* run = app.get_subcommand("run");
  ferro::scenarios::RunOverrides o;
  if (auto* opt = run->get_option_no_throw("--t-end"); opt && opt->count() > 0)
    o.t_end = opt->as<double>();
  if (auto* opt = run->get_option_no_throw("--speed"); opt && opt->count() > 0)
    o.speed = opt->as<double>();
  if (auto* opt = run->get_option_no_throw("--tangential"); opt && opt->count() > 0)
    o.tangential = opt->as<std::string>();
  for (const auto* base : {&hunting, &vehicle}) {
    ferro::scenarios::Scene scene = *base;
    try {
      ferro::scenarios::apply_overrides(scene, o, ferro::scenarios::Spelling::option);
    } catch (const std::invalid_argument&) {
    }
  }
  return 0;
}
