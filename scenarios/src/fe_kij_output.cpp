#include "ferro/scenarios/fe_kij_output.hpp"

#include <filesystem>

namespace ferro::scenarios {

OutputFile& claim_fe_kij_table(const FeKijStudy& study, OutputSet& outputs) {
  try {
    return outputs.claim(study.output(), "output");
  } catch (...) {
    std::error_code ec;
    if (study.resumed() == 0) std::filesystem::remove(study.work_dir(), ec);  // only when empty
    throw;
  }
}

}  // namespace ferro::scenarios
