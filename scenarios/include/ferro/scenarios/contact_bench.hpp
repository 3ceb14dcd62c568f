#pragma once
// Speed-versus-error report of the tangential (creep-force) models: every model over a fixed set
// of Hertzian cases, against converged MIM (`ferrodyn bench contact`).

#include <string>
#include <vector>

#include "ferro/contact/tangential/tangential_model.hpp"
#include "ferro/scenarios/parameters.hpp"

namespace ferro::scenarios {

/// One Hertzian rolling case: semi-axes from a/b at c = sqrt(ab) = 5 mm, F_n = 80 kN,
/// mu = 0.3, steel (E = 210 GPa, nu = 0.28); creepages given in the normalised units of
/// contact/mim_table.hpp (1 = where Kalker's linear force reaches mu F_n along that axis; spin
/// phi* = G c^3 C23 phi / (mu F_n)).
struct ContactBenchCase {
  double ratio = 1.0;                         ///< a/b [-]
  double xi_x = 0.0, xi_y = 0.0, spin = 0.0;  ///< normalised creepages [-]
  std::string kind;  ///< "x", "y", "x+y" (creepage direction), "+spin" appended, or "spin"
};

/// The fixed case set: a/b in {0.2, 0.5, 1, 2, 5} x normalised spin in {0, 0.5, 1, 2} x seven
/// creepage directions (0, 30, ..., 180 deg in the (xi_x*, xi_y*) plane) x magnitudes {0.2, 0.5,
/// 0.8, 1.2, 2, 4} (micro-slip to full slip), plus pure spin at each spin level: 855 cases.
[[nodiscard]] std::vector<ContactBenchCase> contact_bench_cases();

/// The case's elliptic patch (a = c sqrt(a/b), b = c / sqrt(a/b), F_n) and its tangential
/// problem on that patch (which must outlive the problem): mu, steel, the creepages.
[[nodiscard]] ferro::contact::ContactPatch contact_bench_patch(const ContactBenchCase& c);
[[nodiscard]] ferro::contact::TangentialProblem contact_bench_problem(
    const ContactBenchCase& c, const ferro::contact::ContactPatch& patch);
/// Physical input of a case: semi-axes [m], F_n [N], mu [-], creepages xi_x, xi_y [-] and spin
/// [1/m] from the normalised ones (Kalker's C_ij at a/b, nu), steel on steel.
struct ContactBenchInput {
  double semi_axis_x = 0.0, semi_axis_y = 0.0, normal_force = 0.0, friction = 0.0;
  double creepage_x = 0.0, creepage_y = 0.0, spin = 0.0;
  double young = 0.0, poisson = 0.0;  ///< both bodies [Pa, -]
};
[[nodiscard]] ContactBenchInput contact_bench_input(const ContactBenchCase& c);

/// Reference value of one case: converged MIM in units of mu F_n (forces) and mu F_n c (moment).
struct ContactBenchReference {
  double fx = 0.0, fy = 0.0, mz = 0.0;  ///< Richardson-extrapolated
  double fx_n = 0.0, fy_n = 0.0;        ///< on the N x N grid over the patch
  double fx_2n = 0.0, fy_2n = 0.0;      ///< on the 2N x 2N grid
};

struct ContactBenchOptions {
  int reference_elements = 40;  ///< reference MIM: N (grids N x N and 2N x 2N over the patch)
  std::string reference;        ///< reference CSV: read if it matches the case set, else written
  std::string table;            ///< mim_table HDF5 file; empty: build the default table
  double min_time_s = 0.2;      ///< timing: repeat the case set until this much time passed
  int threads = 2;              ///< threads of the reference computation
  bool quick = false;           ///< 15 cases, coarse reference and table (smoke test)
};

struct ContactBenchRow {
  std::string label;            ///< model and options
  double us_per_eval = 0.0;     ///< CPU time per evaluation [us]
  double mean_error = 0.0;      ///< |F_t - F_t,ref| / (mu F_n), mean over the cases
  double p95_error = 0.0;       ///< 95th percentile
  double max_error = 0.0;       ///< maximum
  double mean_no_spin = 0.0;    ///< mean over the cases without spin
  double mean_spin = 0.0;       ///< mean over the cases with spin
  double mz_mean_error = 0.0;   ///< |M_z - M_z,ref| / (mu F_n c), mean
  double max_force = 0.0;       ///< largest |F_t| / (mu F_n) returned (Coulomb: <= 1)
};

struct ContactBenchResult {
  std::vector<ContactBenchRow> rows;
  std::vector<ContactBenchCase> cases;
  std::vector<ContactBenchReference> reference;
  int reference_elements = 0;
  bool reference_from_file = false;
};

/// The options as parameters (see parameters.hpp).
[[nodiscard]] Parameters parameters(ContactBenchOptions& options);

/// Runs every model over the cases. Throws std::invalid_argument for bad options,
/// std::runtime_error when a model fails.
[[nodiscard]] ContactBenchResult run_contact_bench(const ContactBenchOptions& options);

/// Converged-MIM reference of the cases: MIM on N x N and 2N x 2N grids over the patch, the
/// forces extrapolated as second order (F = F_2N + (F_2N - F_N) / 3).
[[nodiscard]] std::vector<ContactBenchReference> contact_bench_reference(
    const std::vector<ContactBenchCase>& cases, int elements, int threads);

/// One case of the reference's grid study: F_y / (mu F_n) by MIM over the patch at N/2, N and
/// 2N elements, the extrapolated value and the observed order p = log2(|F_N/2 - F_N| /
/// |F_N - F_2N|) (of the force vector; 0 when the last difference is 0).
struct ContactBenchGridRow {
  ContactBenchCase c;
  double fy_half = 0.0, fy_n = 0.0, fy_2n = 0.0, fy_extrapolated = 0.0, order = 0.0;
};
/// The grid study of `result`'s reference over pure spin (phi* = 1) and a transition creepage
/// (0.8 at 30 deg) for each a/b: empty when the reference has fewer than 16 elements.
[[nodiscard]] std::vector<ContactBenchGridRow> contact_bench_grid_study(
    const ContactBenchResult& result, int threads);
/// Mean |F(extrapolated) - F(2N)| / (mu F_n) over the cases: the size of the Richardson step.
[[nodiscard]] double contact_bench_mean_correction(const ContactBenchResult& result);

/// The report `ferrodyn bench contact` prints: the reference's grid study (computed here on
/// `threads` threads), then one Markdown row per model.
[[nodiscard]] std::string contact_bench_report(const ContactBenchResult& result, int threads);

/// Reference CSV I/O (ratio, xi_x, xi_y, spin, fx, fy, mz, fx_n, fy_n, fx_2n, fy_2n; '#' lines
/// are comments; the first comment names N). read returns false when the file is missing or its
/// cases differ from `cases`.
bool read_contact_bench_reference(const std::string& path,
                                  const std::vector<ContactBenchCase>& cases,
                                  std::vector<ContactBenchReference>& out, int& elements);
void write_contact_bench_reference(const std::string& path,
                                   const std::vector<ContactBenchCase>& cases,
                                   const std::vector<ContactBenchReference>& ref, int elements);

/// Writes the rows as CSV (label, us_per_eval, mean, p95, max, mean without / with spin, M_z mean,
/// largest force).
void write_contact_bench_csv(const ContactBenchResult& result, const std::string& path);
/// write_contact_bench_csv into <dir>/bench_contact.csv (the folder made when missing); returns
/// the file's path.
[[nodiscard]] std::string write_contact_bench_csv_in(const ContactBenchResult& result,
                                                     const std::string& dir);

}  // namespace ferro::scenarios
