#pragma once
// The output table of a K_ij study (`ferrodyn fe-kij`), claimed before anything is computed so
// that a path that would be refused is refused at once, not after hours of finite elements.

#include "ferro/scenarios/fe_kij_study.hpp"
#include "ferro/scenarios/output_file.hpp"

namespace ferro::scenarios {

/// Claims study.output() in `outputs` (named "output" in messages). When it is refused and no
/// point was resumed, the study's work folder is removed if empty, then the error is rethrown.
OutputFile& claim_fe_kij_table(const FeKijStudy& study, OutputSet& outputs);

/// What `ferrodyn fe-kij` says before the run: the configurations and those already done in the
/// work folder (one line).
[[nodiscard]] std::string fe_kij_start_text(const FeKijStudy& study);
/// ... and after it: the table written with this run's CPU and wall time, or, when interrupted,
/// the finished points kept in the work folder for a resume (one line).
[[nodiscard]] std::string fe_kij_end_text(const FeKijStudy& study, const FeKijReport& report);

}  // namespace ferro::scenarios
