#pragma once
// Reduction factors K_ij (reduction_factors.hpp) interpolated from an HDF5 table (layout:
// docs/KIJ_TABLE.md, version 2 with provenance and an optional first-pass range; version 1 still
// read).
//
// References: Toumi (2016) eq. (156), section 3 (K_ij from FE creep curves), Table 4.1.
// Known deviations: the table is interpolated multilinearly and clamped at its axis ends
// (queries outside the axes are counted in KijTable::clamped_queries()).

#include <array>
#include <atomic>
#include <map>
#include <string>
#include <vector>

#include "ferro/contact/kij/reduction_factors.hpp"
#include "ferro/contact/normal/contact_patch.hpp"

namespace ferro::contact {

/// K_ij tabulated over named axes (e.g. "normal_force" [N], "layer_thickness" [m]).
class KijTable {
 public:
  /// Current layout version written by write_hdf5 (docs/KIJ_TABLE.md); 1 and 2 are read.
  static constexpr int kSchemaVersion = 2;
  /// Reads a table written in the docs/KIJ_TABLE.md layout (version 1 or 2). Throws
  /// std::invalid_argument (file, dataset, reason) on a missing or inconsistent file.
  static KijTable read_hdf5(const std::string& path);
  /// Writes the table in the version 2 layout (for the FE module and the tests).
  void write_hdf5(const std::string& path) const;

  /// Provenance (version 2): name -> text, e.g. "mesh_size_m", "grid", "solver_tolerance",
  /// "command". Stored as string attributes of the group /provenance.
  [[nodiscard]] const std::map<std::string, std::string>& provenance() const { return provenance_; }
  void set_provenance(std::map<std::string, std::string> provenance) {
    provenance_ = std::move(provenance);
  }
  /// Where the physics is not single-valued (elasto-plastic rail: first pass vs shaken down),
  /// K11..K33 hold the value used for interpolation (shaken down) and this optional second set
  /// the other end of the range (first pass), same shape; K33 entry may be empty. Version 2.
  void set_first_pass(std::vector<double> k11, std::vector<double> k22, std::vector<double> k23,
                      std::vector<double> k33 = {});
  [[nodiscard]] bool has_first_pass() const { return !k11_first_.empty(); }
  /// First-pass factors at a point (values in axis order); std::logic_error without them.
  [[nodiscard]] ReductionFactors first_pass_at(const std::vector<double>& point) const;

  /// Builds a table in memory. values_* are row-major over axes in the given order, one value per
  /// grid node; k33 may be empty (then K33 = K22 is not assumed: K33 = 1).
  KijTable(std::vector<std::string> axis_names, std::vector<std::vector<double>> axes,
           std::vector<double> k11, std::vector<double> k22, std::vector<double> k23,
           std::vector<double> k33 = {});

  [[nodiscard]] const std::vector<std::string>& axis_names() const { return names_; }
  [[nodiscard]] const std::vector<std::vector<double>>& axes() const { return axes_; }

  /// Multilinear interpolation at the point given by axis name -> value (every axis needed;
  /// std::invalid_argument names a missing or unknown axis). Values outside an axis are clamped.
  [[nodiscard]] ReductionFactors at(const std::map<std::string, double>& point) const;
  /// Same with values in axis order.
  [[nodiscard]] ReductionFactors at(const std::vector<double>& point) const;

  /// Same, filling the axes "normal_force" [N] and "peak_pressure" [Pa] from the patch when the
  /// table has them and `point` does not give them.
  [[nodiscard]] ReductionFactors at_patch(const ContactPatch& patch,
                                          std::map<std::string, double> point = {}) const;

  [[nodiscard]] long clamped_queries() const { return clamped_; }

  KijTable(const KijTable& other)
      : names_(other.names_),
        axes_(other.axes_),
        k11_(other.k11_),
        k22_(other.k22_),
        k23_(other.k23_),
        k33_(other.k33_),
        k11_first_(other.k11_first_),
        k22_first_(other.k22_first_),
        k23_first_(other.k23_first_),
        k33_first_(other.k33_first_),
        provenance_(other.provenance_),
        clamped_(other.clamped_.load()) {}

 private:
  [[nodiscard]] ReductionFactors interpolate(const std::vector<double>& point,
                                             const std::vector<double>& k11,
                                             const std::vector<double>& k22,
                                             const std::vector<double>& k23,
                                             const std::vector<double>& k33) const;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> axes_;
  std::vector<double> k11_, k22_, k23_, k33_;
  std::vector<double> k11_first_, k22_first_, k23_first_, k33_first_;
  std::map<std::string, std::string> provenance_;
  mutable std::atomic<long> clamped_{0};
};

/// A K_ij table with every axis but the patch's own fixed: precomputed at construction on the
/// table's nodes of `normal_force` and `peak_pressure` (those of them the table has and `fixed`
/// does not give), then looked up per contact patch without allocation (for right-hand sides).
/// Same multilinear interpolation and end clamping as KijTable::at.
class KijPatchLookup {
 public:
  /// Throws std::invalid_argument naming an axis of the table that `fixed` must give (any
  /// axis other than normal_force, peak_pressure) or a name in `fixed` the table does not have.
  KijPatchLookup(const KijTable& table, const std::map<std::string, double>& fixed);
  [[nodiscard]] ReductionFactors at(const ContactPatch& patch) const;

 private:
  std::vector<bool> pressure_axis_;            ///< per patch axis: peak_pressure (else force)
  std::vector<std::vector<double>> axes_;      ///< at most 2
  std::vector<std::array<double, 4>> values_;  ///< row-major over axes_
};

}  // namespace ferro::contact
