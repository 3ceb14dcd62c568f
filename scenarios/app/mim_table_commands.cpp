// `ferrodyn contact mim-table`: builds the tabulated-MIM HDF5 table of the "mim_table" model.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "ferro/contact/tangential/mim_table.hpp"
#include "ferro/io/text_writer.hpp"
#include "ferro/scenarios/output_file.hpp"

namespace ferro::cli {

void add_mim_table_commands(CLI::App& app, VerbHandler& handler) {
  CLI::App* contact = app.get_subcommand("contact");
  auto out = std::make_shared<std::string>();
  auto spec = std::make_shared<contact::MimTableSpec>(contact::MimTableSpec::default_spec());
  spec->threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  CLI::App* cmd = contact->add_subcommand(
      "mim-table",
      "Precompute MIM creep forces over normalised creepages, spin and a/b into an HDF5 table "
      "(model mim_table; layout in docs/OUTPUT.md)");
  add_output_option(cmd, *out, "HDF5 file to write (required)", {"--out"});
  cmd->add_option("--elements", spec->elements, "MIM elements across the shorter axis")
      ->capture_default_str();
  cmd->add_option("--grid", spec->grid,
                  "MIM grid of the nodes: minor (square elements, --elements across the shorter "
                  "axis), patch (--elements x --elements over the patch), patch_richardson (patch "
                  "grid, forces extrapolated from --elements and its half)")
      ->capture_default_str();
  cmd->add_option("--threads", spec->threads, "build threads")->capture_default_str();
  cmd->add_option("--poisson", spec->poisson, "combined Poisson ratio of the table")
      ->capture_default_str();
  cmd->add_option("--density", spec->density,
                  "node density: split every creepage and spin interval into N parts (1-8)")
      ->capture_default_str();
  auto map_path = std::make_shared<std::string>();
  auto map_points = std::make_shared<int>(200);
  auto overwrite = std::make_shared<bool>(false);
  add_overwrite_flag(cmd, *overwrite);
  cmd->add_option("--error-map", *map_path,
                  "CSV of table-versus-direct MIM errors at random points (empty: none)");
  cmd->add_option("--error-map-points", *map_points, "points of the error map")
      ->capture_default_str();
  cmd->callback([&handler, out, spec, map_path, map_points, overwrite] {
    handler = [out, spec, map_path, map_points, overwrite] {
      try {
        spec->validate();
      } catch (const std::invalid_argument& e) {
        // Name the command-line options, not the table fields.
        std::string msg = e.what();
        for (const auto& [field, option] :
             {std::pair<std::string, std::string>{"mim table elements", "--elements"},
              {"mim table threads", "--threads"},
              {"mim table grid", "--grid"},
              {"mim table poisson", "--poisson"},
              {"mim table density", "--density"}}) {
          if (msg.rfind(field, 0) == 0) msg = option + msg.substr(field.size());
        }
        throw std::invalid_argument(msg);
      }
      if (*map_points < 1) {
        throw std::invalid_argument(
            fmt::format("--error-map-points: must be >= 1, got {}", *map_points));
      }
      if (out->empty()) throw std::invalid_argument("contact mim-table: -o/--output is required");
      // Claimed before the (long) build: a path that would be refused is refused now.
      scenarios::OutputSet outputs({*overwrite, {}});
      scenarios::OutputFile& file = outputs.claim(*out, "-o");
      scenarios::OutputFile* map_file =
          map_path->empty() ? nullptr : &outputs.claim(*map_path, "--error-map");
      const auto t0 = std::chrono::steady_clock::now();
      const contact::MimTable table = contact::MimTable::build(*spec);
      table.write_hdf5(file.write_path());
      file.commit();
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      fmt::print("wrote {} ({} x {} x {} x {} nodes, {} elements, nu {}) in {:.1f} s\n", *out,
                 table.spec().ratio.size(), table.spec().xi_x.size(), table.spec().xi_y.size(),
                 table.spec().spin.size(),
                 spec->elements, spec->poisson, s);
      if (!map_path->empty()) {
        std::vector<contact::MimTableErrorPoint> map =
            contact::mim_table_error_map(table, *map_points, 1, spec->threads);
        io::TextWriter csv(map_file->write_path());
        csv.write("ratio,xi_x,xi_y,phi,fx_table,fy_table,fx_mim,fy_mim,error_mu_fn\n");
        std::vector<double> err;
        for (const auto& e : map) {
          csv.print("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n",
                             e.ratio, e.xi_x, e.xi_y, e.spin, e.table.f_x, e.table.f_y,
                             e.direct.f_x, e.direct.f_y, e.error);
          err.push_back(e.error);
        }
        csv.close();
        map_file->commit();
        std::sort(err.begin(), err.end());
        double sum = 0.0;
        for (double v : err) sum += v;
        fmt::print("error map {} ({} points): table vs direct MIM mean {:.4f}, p95 {:.4f}, max "
                   "{:.4f} mu Fn\n",
                   *map_path, err.size(), sum / static_cast<double>(err.size()),
                   err[static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(err.size()))) - 1],
                   err.back());
      }
      return kExitOk;
    };
  });
}

}  // namespace ferro::cli
