#pragma once
// K_ij reduction-factor tables from offline contact computations (fe_contact): a study over
// wheel load, interfacial-layer parameters and the rail's yield stress, read from a CONFIG.yaml,
// written as an HDF5 table in the docs/KIJ_TABLE.md layout (version 2), with creep and
// derivative curves per configuration. Finished points are kept in a journal folder next to the
// output (<output>.d/), so an interrupted study resumes where it stopped.
//
// CONFIG.yaml (SI units):
//   schema_version: 1
//   contact: {reference_force, semi_axis_x, semi_axis_y, young_modulus, poisson, friction,
//             elements_minor, margin}
//   layer:   {thickness, shear_modulus, yield_shear}      # defaults of the unswept layer axes
//   axes:    {normal_force: [...], layer_thickness: [...], layer_shear_modulus: [...],
//             layer_yield_shear: [...], yield_stress: [...]}  # any non-empty subset;
//                                                         # yield_stress: only with normal_force
//   plastic: {elements_per_semi_axis, load_steps, unload_steps, hardening_modulus, growth,
//             extent}                                     # FE rail with the yield_stress axis
//   solver:  {tolerance, probe_creepage, probe_spin_times_a}
//   curves:  {creepages: [...]}                           # optional
//   output:  kij.h5                                       # relative to the config file
//   plots:   true

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

namespace ferro::scenarios {

struct FeKijRunOptions {
  /// Polled before each point; true stops the study (finished points stay in the journal).
  std::function<bool()> should_stop;
  /// Called after each point (done so far, total).
  std::function<void(std::size_t done, std::size_t total)> progress;
  /// Where the table is written (empty: output()), e.g. a temporary name the caller renames.
  std::string table_path;
};

struct FeKijReport {
  bool interrupted = false;   ///< should_stop fired: no table written
  std::size_t finished = 0;   ///< points in the journal when the study ended
  double cpu_seconds = 0.0;   ///< process CPU time of this call [s]
  double wall_seconds = 0.0;  ///< [s]
};

class FeKijStudy {
 public:
  /// Reads and validates the configuration (YamlInputError with file, line and key) and the
  /// journal of a previous run (forgotten when `restart`).
  FeKijStudy(const std::string& config_path, bool restart);
  ~FeKijStudy();
  FeKijStudy(const FeKijStudy&) = delete;
  FeKijStudy& operator=(const FeKijStudy&) = delete;

  [[nodiscard]] std::size_t points() const;           ///< configurations of the study
  [[nodiscard]] std::size_t resumed() const;          ///< already finished in the journal
  [[nodiscard]] const std::string& output() const;    ///< the HDF5 table
  [[nodiscard]] const std::string& work_dir() const;  ///< the journal and curve CSVs
  /// The configuration asks for pictures (`plots`) and curves were computed.
  [[nodiscard]] bool wants_curve_plots() const;

  /// Computes the missing points, then writes the table. Throws std::runtime_error when a
  /// point's MIM solves do not converge or a file cannot be written.
  FeKijReport run(const FeKijRunOptions& options = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ferro::scenarios
