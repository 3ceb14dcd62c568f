#pragma once
// Text reports of the analyses: what the `ferrodyn` analysis verbs print, and what the Python
// module's analysis results give as their summary. Plain text, two-space indented lines, units
// in the headings; every line ends in '\n'.

#include <string>
#include <vector>

#include "ferro/scenarios/analysis/derailment.hpp"
#include "ferro/scenarios/analysis/studies.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"

namespace ferro::scenarios::analysis {

/// Per wheel: peak Y/Q of the sliding mean, Nadal's limit, peak unloading; per axle: peak sum Y
/// against Prud'homme's limit; the verdict.
[[nodiscard]] std::string derailment_report(const std::string& run_file,
                                            const DerailmentOptions& options,
                                            const DerailmentReport& report);
/// The ramp, the speed where the envelope decays for good and where its growth turns to decay.
[[nodiscard]] std::string ramp_report(const RampStudy& study, const RampRequest& request);
/// The branch's points (amplitudes of each wheelset in mm), the fold and its onset, the Hopf
/// speed.
[[nodiscard]] std::string branch_report(const KijRow& row, const std::vector<std::string>& names);
/// The fold against the factors, beside the thesis's Table 4.1 where a factor matches.
[[nodiscard]] std::string kij_study_report(const Scene& scene, const KijStudyRequest& request,
                                           const KijStudy& study);
/// Every point of a complete sweep and the CPU time; `ranks` is the executor's size.
[[nodiscard]] std::string sweep_report(const Scene& scene, const SweepRequest& request,
                                       const SweepOutcome& outcome, int ranks);

}  // namespace ferro::scenarios::analysis
