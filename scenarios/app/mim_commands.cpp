// `ferrodyn contact mim`: one MIM (boundary-element) rolling-contact solve on a Hertzian patch.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "ferro/contact/mim/mim.hpp"
#include "cli.hpp"
#include "ferro/scenarios/output_file.hpp"

namespace ferro::cli {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct MimArgs {
  double a = kNaN, b = kNaN;        // semi-axes [m]
  double a_mm = kNaN, b_mm = kNaN;  // old spellings [mm]
  double normal_force = std::numeric_limits<double>::quiet_NaN();
  double creepage_x = 0.0;
  double creepage_y = 0.0;
  double spin_per_m = 0.0;
  double friction = 0.3;
  double young = 210.0e9;    // [Pa]
  double young_gpa = kNaN;   // old spelling [GPa]
  double poisson = 0.28;
  int elements = 40;
  std::string out;
  bool overwrite = false;
};

// The value given under the SI name, else under the old non-SI one (scaled), else an error.
double si_value(double si, double old, double scale, const char* name) {
  if (!std::isnan(si)) return si;
  if (!std::isnan(old)) return old * scale;
  throw std::invalid_argument(fmt::format("contact mim: {} is required", name));
}

int run_mim(const MimArgs& args) {
  contact::mim::HertzRollingInput in;
  in.semi_axis_x = si_value(args.a, args.a_mm, 1.0e-3, "--a [m]");
  in.semi_axis_y = si_value(args.b, args.b_mm, 1.0e-3, "--b [m]");
  in.normal_force = args.normal_force;
  in.rolling =
      contact::mim::RollingInput{args.creepage_x, args.creepage_y, args.spin_per_m, args.friction};
  in.body1 = in.body2 = contact::Material::from_young(
      std::isnan(args.young_gpa) ? args.young : args.young_gpa * 1.0e9, args.poisson);
  in.elements_minor = args.elements;
  // Name the command-line options, not the library's fields, in bad-input messages.
  try {
    in.validate("mim");
  } catch (const std::invalid_argument& e) {
    std::string msg = e.what();
    const std::pair<const char*, const char*> names[] = {
        {"mim.semi_axis_x/semi_axis_y", "--a-mm/--b-mm"},
        {"mim.normal_force", "--fn"},
        {"mim.elements_minor", "--elements"},
        {"mim.rolling.creepage_x", "--xi-x"},
        {"mim.rolling.creepage_y", "--xi-y"},
        {"mim.rolling.spin", "--spin"},
        {"mim.rolling.friction", "--mu"},
        {"mim.body1", "--young-gpa/--poisson"}};
    for (const auto& [field, option] : names) {
      if (msg.rfind(field, 0) == 0) {
        msg = option + msg.substr(std::string(field).size());
        break;
      }
    }
    throw std::invalid_argument(msg);
  }
  scenarios::OutputSet outputs({args.overwrite, {}});
  scenarios::OutputFile* fields = args.out.empty() ? nullptr : &outputs.claim(args.out, "-o");
  const auto t0 = std::chrono::steady_clock::now();
  const contact::mim::MimResult r = contact::mim::solve_hertz_rolling(in);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  int stick = 0, slip = 0;
  for (auto s : r.state) {
    stick += s == contact::mim::ElementState::stick ? 1 : 0;
    slip += s == contact::mim::ElementState::slip ? 1 : 0;
  }
  fmt::print("grid {} x {}, dx = {:.4f} mm; {} stick, {} slip elements\n", r.grid.nx, r.grid.ny,
             r.grid.dx * 1.0e3, stick, slip);
  fmt::print("Fn = {:.6g} N, Fx = {:.6g} N, Fy = {:.6g} N, Mz = {:.6g} N m, approach = {:.6g} mm\n",
             r.normal_force, r.force_x, r.force_y, r.moment_z, r.approach * 1.0e3);
  fmt::print("Fx/(mu Fn) = {:.5f}, Fy/(mu Fn) = {:.5f}; converged: {}; {:.1f} ms (incl. set-up)\n",
             args.friction > 0.0 ? r.force_x / (args.friction * r.normal_force) : 0.0,
             args.friction > 0.0 ? r.force_y / (args.friction * r.normal_force) : 0.0,
             r.converged ? "yes" : "NO", ms);
  if (r.patch_truncated) {
    fmt::print("warning: the pressure reaches the grid boundary (patch truncated)\n");
  }
  if (fields != nullptr) {
    contact::mim::write_hdf5(r, fields->write_path());
    fields->commit();
    fmt::print("fields written to {}\n", args.out);
  }
  return r.converged ? kExitOk : kExitRunFailure;
}

}  // namespace

void add_mim_commands(CLI::App& app, VerbHandler& handler) {
  auto args = std::make_shared<MimArgs>();
  const auto define = [&](CLI::App* cmd) {
    cmd->add_option("--a", args->a, "semi-axis along the rolling direction [m]");
    cmd->add_option("--b", args->b, "lateral semi-axis [m]");
    cmd->add_option("--fn", args->normal_force, "normal force [N]")->required();
    cmd->add_option("--xi-x", args->creepage_x, "longitudinal creepage [-] (default 0)");
    cmd->add_option("--xi-y", args->creepage_y, "lateral creepage [-] (default 0)");
    cmd->add_option("--spin", args->spin_per_m, "spin creepage [1/m] (default 0)");
    cmd->add_option("--mu", args->friction, "friction coefficient [-] (default 0.3)");
    cmd->add_option("--young", args->young, "Young's modulus of both bodies [Pa] (210e9)");
    cmd->add_option("--poisson", args->poisson, "Poisson's ratio of both bodies [-] (0.28)");
    cmd->add_option("--elements", args->elements, "elements across the shorter axis (40)");
    add_output_option(cmd, args->out, "HDF5 file for the pressure, traction, slip fields",
                      {"--out"});
    add_overwrite_flag(cmd, args->overwrite);
    add_hidden_alias(cmd, "--a-mm", args->a_mm);
    add_hidden_alias(cmd, "--b-mm", args->b_mm);
    add_hidden_alias(cmd, "--young-gpa", args->young_gpa);
    cmd->callback([args, &handler] { handler = [args] { return run_mim(*args); }; });
  };
  const char* help =
      "MIM boundary-element rolling contact on a Hertz ellipse (normal + steady rolling)";
  define(app.get_subcommand("contact")->add_subcommand("mim", help));
  // The former top-level spelling, hidden, for one release.
  define(app.add_subcommand("mim", help)->group(""));
}

}  // namespace ferro::cli
