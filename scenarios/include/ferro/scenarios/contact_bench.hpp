#pragma once
// Speed-versus-error report of the tangential (creep-force) models: every model over a fixed set
// of Hertzian cases, against fine-grid MIM (`ferrodyn bench contact`).

#include <string>
#include <vector>

namespace ferro::scenarios {

/// One Hertzian rolling case: semi-axes from a/b at c = sqrt(ab) = 5 mm, F_n = 80 kN,
/// mu = 0.3, steel (E = 210 GPa, nu = 0.28); creepages given in the normalised units of
/// contact/mim_table.hpp (1 = where Kalker's linear force reaches mu F_n along that axis).
struct ContactBenchCase {
  double ratio = 1.0;                            ///< a/b [-]
  double xi_x = 0.0, xi_y = 0.0, spin = 0.0;     ///< normalised creepages [-]
  std::string kind;                              ///< "x", "y", "spin", "x+y", "y+spin", "x+y+spin"
};

/// The fixed case set: a/b in {0.2, 0.5, 1, 2, 5} x 6 creepage kinds x 3 magnitudes (micro-slip,
/// transition, full slip) = 90 cases.
[[nodiscard]] std::vector<ContactBenchCase> contact_bench_cases();

struct ContactBenchOptions {
  int reference_elements = 48;  ///< fine MIM grid (elements across the shorter axis)
  std::string table;            ///< mim_table HDF5 file; empty: build the default table
  double min_time_s = 0.2;      ///< timing: repeat the case set until this much time passed
  bool quick = false;           ///< every 6th case and a coarse reference (smoke test)
};

struct ContactBenchRow {
  std::string label;          ///< model and options
  double us_per_eval = 0.0;   ///< CPU time per evaluation [us]
  double mean_error = 0.0;    ///< |F_t - F_t,ref| / (mu F_n), mean over the cases
  double p95_error = 0.0;     ///< 95th percentile
  double max_error = 0.0;     ///< maximum
};

struct ContactBenchResult {
  std::vector<ContactBenchRow> rows;  ///< the reference is the last row (error 0)
  int cases = 0;
};

/// Runs every model over the cases. Throws std::runtime_error when a model fails.
[[nodiscard]] ContactBenchResult run_contact_bench(const ContactBenchOptions& options);

/// Writes the rows as CSV (label, us_per_eval, mean, p95, max).
void write_contact_bench_csv(const ContactBenchResult& result, const std::string& path);

}  // namespace ferro::scenarios
