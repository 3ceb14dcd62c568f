#pragma once
// A K_ij table over named axes (wheel load, layer thickness, layer shear modulus, layer shear
// strength): one reduction-factor computation and optional creep curves per grid node.
//
// References: Toumi (2016) section 3.4 (layer parameter study, Figs. 3.46-3.48), Table 3.9 (wheel
// loads 7.5 / 11.25 / 15 t), eq. (156); docs/KIJ_TABLE.md (layout of the result).
// Known deviations: the elastic finite-body and elasto-plastic rail compliances are not axes of
// this sweep (only the half-space + interfacial layer operator); see hertz_case.hpp for the layer.

#include <map>
#include <string>
#include <vector>

#include "ferro/contact/reduction_factors.hpp"
#include "ferro/fe_contact/creep_slopes.hpp"
#include "ferro/fe_contact/hertz_case.hpp"

namespace ferro::fe_contact {

/// Axis names a sweep accepts (SI units): normal_force [N], layer_thickness [m],
/// layer_shear_modulus [Pa], layer_yield_shear [Pa].
[[nodiscard]] const std::vector<std::string>& sweep_axis_names();

struct KijSweepSpec {
  HertzCase contact;     ///< normal_force is the default when it is not an axis
  InterfaceLayer layer;  ///< defaults for the layer axes that are not swept
  std::vector<std::string> axis_names;
  std::vector<std::vector<double>> axes;  ///< strictly increasing values per axis
  SlopeOptions slope;
  /// Creepages of the creep curves per configuration (x and y); empty: no curves.
  std::vector<double> curve_creepages;
  void validate(const std::string& where = "KijSweepSpec") const;
  [[nodiscard]] std::size_t points() const;
  /// Axis values of point `index` (row-major over the axes, last axis fastest).
  [[nodiscard]] std::vector<double> coordinates(std::size_t index) const;
  /// The case and layer of a point.
  void configure(std::size_t index, HertzCase& contact_out, InterfaceLayer& layer_out) const;
};

struct KijPoint {
  SlopeResult slopes;
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

/// Table from the per-point factors (index order of KijSweepSpec::coordinates), with provenance.
[[nodiscard]] contact::KijTable make_table(const KijSweepSpec& spec,
                                           const std::vector<contact::ReductionFactors>& k,
                                           std::map<std::string, std::string> provenance);

}  // namespace ferro::fe_contact
