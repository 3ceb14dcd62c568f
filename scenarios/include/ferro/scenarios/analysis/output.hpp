#pragma once
// HDF5 files of the critical-speed analyses (layouts: docs/ANALYSES.md); each carries the
// scene text and a `kind` attribute the plotting script dispatches on.

#include <optional>
#include <string>
#include <vector>

#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/scene_analysis.hpp"

namespace ferro::scenarios::analysis {

/// kind "ramp": /ramp/{time, speed, signal (samples x wheelsets), wheelset_envelope (samples x
/// wheelsets), envelope (the vehicle's)}; attributes wheelsets, holder, decay_speed, threshold.
void write_ramp(const Scene& scene, const RampResult& r, const RampOptions& o,
                const std::vector<std::string>& names, const std::string& path);

/// kind "bifurcation": /branch/{speed, outcome, holder, bisection, period, amplitude (points x
/// wheelsets)}; attributes lowest_sustained, holder, bracket_low, bracket_high, hopf_speed (NaN
/// when not computed), k11, k22.
void write_branch(const Scene& scene, const BranchResult& b,
                  const std::vector<std::string>& wheelset_names, std::optional<double> hopf_speed,
                  const std::string& path);

/// One row of a reduction-factor study.
struct KijRow {
  contact::ReductionFactors k;
  BranchResult branch;
  std::optional<double> hopf_speed;  ///< [m/s]
};

/// kind "kij_study": /kij/{k11, k22, critical_speed, bracket_low, bracket_high, hopf_speed}.
void write_kij_study(const Scene& scene, const std::vector<KijRow>& rows, const std::string& path);

/// The thesis's Table 4.1 (Toumi 2016): uniform reduction factor K against the nonlinear
/// critical speed of the Manchester vehicle [km/h].
struct ThesisTableRow {
  double k;
  double critical_speed_kmh;
};
[[nodiscard]] const std::vector<ThesisTableRow>& thesis_table_4_1();

}  // namespace ferro::scenarios::analysis
