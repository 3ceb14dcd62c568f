#pragma once
// A K_ij table over named axes (wheel load, layer thickness, layer shear modulus, layer shear
// strength, rail yield stress): one reduction-factor computation and optional creep curves per
// grid node. With the yield_stress axis every node is an elasto-plastic rail (see
// elastoplastic_kij.hpp): K is a range, shaken down (the table's K) to first pass.
//
// References: Toumi (2016) section 3.4 (layer parameter study, Figs. 3.46-3.48), Table 3.9 (wheel
// loads 7.5 / 11.25 / 15 t), eq. (156); docs/KIJ_TABLE.md (layout of the result).
// Known deviations: the elastic finite-body compliance is not an axis of this sweep; the
// elasto-plastic rail is not combined with a layer and has no creep curves; see hertz_case.hpp
// (layer) and elastoplastic_kij.hpp (elasto-plastic rail).

#include <map>
#include <string>
#include <vector>

#include "ferro/contact/kij/kij_table.hpp"
#include "ferro/fe_contact/creep_slopes.hpp"
#include "ferro/fe_contact/elastoplastic_kij.hpp"
#include "ferro/fe_contact/hertz_case.hpp"

namespace ferro::fe_contact {

/// Axis names a sweep accepts (SI units): normal_force [N], layer_thickness [m],
/// layer_shear_modulus [Pa], layer_yield_shear [Pa], yield_stress [Pa] (rail steel).
[[nodiscard]] const std::vector<std::string>& sweep_axis_names();

struct KijSweepSpec {
  HertzCase contact;     ///< normal_force is the default when it is not an axis
  InterfaceLayer layer;  ///< defaults for the layer axes that are not swept
  std::vector<std::string> axis_names;
  std::vector<std::vector<double>> axes;  ///< strictly increasing values per axis
  SlopeOptions slope;
  /// Creepages of the creep curves per configuration (x and y); empty: no curves.
  std::vector<double> curve_creepages;
  /// FE settings of the elasto-plastic rail (used with the yield_stress axis; its contact,
  /// yield_stress fields are set per point).
  ElastoplasticKijSpec plastic;
  /// Whether the sweep has the yield_stress axis (elasto-plastic rail).
  [[nodiscard]] bool elastoplastic() const;
  void validate(const std::string& where = "KijSweepSpec") const;
  [[nodiscard]] std::size_t points() const;
  /// Axis values of point `index` (row-major over the axes, last axis fastest).
  [[nodiscard]] std::vector<double> coordinates(std::size_t index) const;
  /// The case and layer of a point.
  void configure(std::size_t index, HertzCase& contact_out, InterfaceLayer& layer_out) const;
};

struct KijPoint {
  SlopeResult slopes;  ///< the table's K (elasto-plastic rail: shaken down)
  /// Elasto-plastic rail only: the first-pass end of the range and the load cycle.
  bool has_first_pass = false;
  SlopeResult first_pass;
  ElastoplasticResult cycle;
  CreepCurve curve_x;  ///< modified compliance
  CreepCurve curve_y;
  CreepCurve reference_curve_x;  ///< half-space on the same grid
  CreepCurve reference_curve_y;
  int nx = 0;
  int ny = 0;
  double element_size = 0.0;  ///< dx = dy [m]
};

/// Computes one point of the sweep.
[[nodiscard]] KijPoint compute_point(const KijSweepSpec& spec, std::size_t index);

/// Table from the per-point factors (index order of KijSweepSpec::coordinates), with provenance;
/// `first_pass` (same size, or empty) fills the table's first-pass range.
[[nodiscard]] contact::KijTable make_table(const KijSweepSpec& spec,
                                           const std::vector<contact::ReductionFactors>& k,
                                           std::map<std::string, std::string> provenance,
                                           const std::vector<contact::ReductionFactors>& first_pass = {});

}  // namespace ferro::fe_contact
