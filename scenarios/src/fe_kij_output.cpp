#include "ferro/scenarios/fe_kij_output.hpp"

#include <fmt/format.h>

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

std::string fe_kij_start_text(const FeKijStudy& study) {
  return fmt::format("fe-kij: {} configurations ({} already done in {})\n", study.points(),
                     study.resumed(), study.work_dir());
}

std::string fe_kij_end_text(const FeKijStudy& study, const FeKijReport& r) {
  if (r.interrupted) {
    return fmt::format("fe-kij: interrupted; {} finished points kept in {} (run again to resume)\n",
                       r.finished, study.work_dir());
  }
  return fmt::format("fe-kij: wrote {} ({} configurations; this run {:.2f} s CPU, {:.1f} s wall)\n",
                     study.output(), study.points(), r.cpu_seconds, r.wall_seconds);
}

}  // namespace ferro::scenarios
