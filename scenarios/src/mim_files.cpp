#include "ferro/scenarios/mim_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "ferro/scenarios/output_file.hpp"

namespace ferro::scenarios {

MimSolveOutcome solve_mim_files(const MimRequest& request, const std::string& fields_path,
                                bool overwrite) {
  const auto in = mim_input(request, Spelling::option);
  OutputSet outputs({overwrite, {}});
  OutputFile* fields = fields_path.empty() ? nullptr : &outputs.claim(fields_path, "-o");
  const auto t0 = std::chrono::steady_clock::now();
  const contact::mim::MimResult result = contact::mim::solve_hertz_rolling(in);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  MimSolveOutcome outcome{mim_report(request, result, ms), result.converged};
  if (fields != nullptr) {
    contact::mim::write_hdf5(result, fields->write_path());
    fields->commit();
  }
  return outcome;
}

contact::MimTableSpec machine_table_spec() {
  contact::MimTableSpec spec = contact::MimTableSpec::default_spec();
  spec.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return spec;
}

void write_mim_table_files(const MimTableRequest& a,
                           const std::function<void(const std::string&)>& say) {
  check_mim_table_spec(a.spec, Spelling::option);
  if (a.map_points < 1) {
    throw std::invalid_argument(
        fmt::format("--error-map-points: must be >= 1, got {}", a.map_points));
  }
  if (a.out.empty()) throw std::invalid_argument("contact mim-table: -o/--output is required");
  // Claimed before the (long) build: a path that would be refused is refused now.
  OutputSet outputs({a.overwrite, {}});
  OutputFile& file = outputs.claim(a.out, "-o");
  OutputFile* map_file = a.map_path.empty() ? nullptr : &outputs.claim(a.map_path, "--error-map");
  const auto t0 = std::chrono::steady_clock::now();
  const contact::MimTable table = contact::MimTable::build(a.spec);
  table.write_hdf5(file.write_path());
  file.commit();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto& t = table.spec();
  say(fmt::format("wrote {} ({} x {} x {} x {} nodes, {} elements, nu {}) in {:.1f} s\n", a.out,
                  t.ratio.size(), t.xi_x.size(), t.xi_y.size(), t.spin.size(), a.spec.elements,
                  a.spec.poisson, s));
  if (map_file != nullptr) {
    const auto map = contact::mim_table_error_map(table, a.map_points, 1, a.spec.threads);
    const std::string report = write_mim_table_error_map(map, map_file->write_path(), a.map_path);
    map_file->commit();
    say(report);
  }
}

}  // namespace ferro::scenarios
