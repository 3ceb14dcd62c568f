#pragma once
// The output table of a K_ij study (`ferrodyn fe-kij`), claimed before anything is computed so
// that a path that would be refused is refused at once, not after hours of finite elements.

#include "ferro/scenarios/fe_kij_study.hpp"
#include "ferro/scenarios/output_file.hpp"

namespace ferro::scenarios {

/// Claims study.output() in `outputs` (named "output" in messages). When it is refused and no
/// point was resumed, the study's work folder is removed if empty, then the error is rethrown.
OutputFile& claim_fe_kij_table(const FeKijStudy& study, OutputSet& outputs);

}  // namespace ferro::scenarios
