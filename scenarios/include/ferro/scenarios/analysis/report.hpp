#pragma once
// Text reports of the analyses: what the `ferrodyn` analysis verbs print, and what the Python
// module's analysis results give as their summary. Plain text, two-space indented lines, units
// in the headings; every line ends in '\n'.

#include <string>
#include <vector>

#include "ferro/scenarios/analysis/assessment.hpp"
#include "ferro/scenarios/analysis/studies.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"

namespace ferro::scenarios::analysis {

/// The vehicle, category and sections; f0 and Nadal's mu; per group a table of quantity, item,
/// value, limit, position, section and verdict: every row (`all_rows`) or, per quantity and item,
/// its worst section (largest value / limit, else value); the notes; the verdict.
[[nodiscard]] std::string assessment_report(const std::string& run_file, const Assessment& assessment,
                                            bool all_rows = false);
/// The ramp, the speed where the envelope decays for good and where its growth turns to decay.
[[nodiscard]] std::string ramp_report(const RampStudy& study, const RampRequest& request);
/// The heading printed before the branch is followed: the scene and the reduction factors.
[[nodiscard]] std::string branch_heading(const Scene& scene, const BranchRequest& request);
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
