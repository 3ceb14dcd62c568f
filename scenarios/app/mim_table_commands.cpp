// `ferrodyn contact mim-table`: builds the tabulated-MIM HDF5 table of the "mim_table" model.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "ferro/contact/mim_table.hpp"
#include "cli.hpp"

namespace ferro::cli {

void add_mim_table_commands(CLI::App& app, VerbHandler& handler) {
  CLI::App* contact = app.get_subcommand("contact");
  auto out = std::make_shared<std::string>();
  auto spec = std::make_shared<contact::MimTableSpec>(contact::MimTableSpec::default_spec());
  spec->threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  CLI::App* cmd = contact->add_subcommand(
      "mim-table",
      "Precompute MIM creep forces over normalised creepages, spin and a/b into an HDF5 table "
      "(model mim_table; layout in docs/reports/mim-integration.md)");
  cmd->add_option("--out", *out, "HDF5 file to write")->required();
  cmd->add_option("--elements", spec->elements, "MIM elements across the shorter axis")
      ->capture_default_str();
  cmd->add_option("--threads", spec->threads, "build threads")->capture_default_str();
  cmd->add_option("--poisson", spec->poisson, "combined Poisson ratio of the table")
      ->capture_default_str();
  cmd->callback([&handler, out, spec] {
    handler = [out, spec] {
      try {
        spec->validate();
      } catch (const std::invalid_argument& e) {
        // Name the command-line options, not the table fields.
        std::string msg = e.what();
        for (const auto& [field, option] :
             {std::pair<std::string, std::string>{"mim table elements", "--elements"},
              {"mim table threads", "--threads"},
              {"mim table poisson", "--poisson"}}) {
          if (msg.rfind(field, 0) == 0) msg = option + msg.substr(field.size());
        }
        throw std::invalid_argument(msg);
      }
      const auto t0 = std::chrono::steady_clock::now();
      const contact::MimTable table = contact::MimTable::build(*spec);
      table.write_hdf5(*out);
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      fmt::print("wrote {} ({} x {} x {} x {} nodes, {} elements, nu {}) in {:.1f} s\n", *out,
                 spec->ratio.size(), spec->xi_x.size(), spec->xi_y.size(), spec->spin.size(),
                 spec->elements, spec->poisson, s);
      return kExitOk;
    };
  });
}

}  // namespace ferro::cli
