#pragma once
// The progress lines of the long analyses (bifurcation branch, K_ij study, sweep), for a program
// to print on its diagnostic stream while they run. Each line ends in a newline.

#include <cstddef>
#include <string>
#include <vector>

#include "ferro/scenarios/analysis/critical_speed.hpp"
#include "ferro/scenarios/analysis/output.hpp"
#include "ferro/scenarios/analysis/sweep.hpp"

namespace ferro::scenarios::analysis {

/// One point of the branch of factors `k`: speed, outcome, amplitude [mm] of the holding state
/// (named from `names`, "?" when out of range), simulated time and, when fitted, the growth rate.
[[nodiscard]] std::string branch_progress_line(const contact::ReductionFactors& k,
                                               const std::vector<std::string>& names,
                                               const BranchPoint& p);

/// A K_ij row finished: its factors and `done` of `total`.
[[nodiscard]] std::string kij_progress_line(const KijRow& row, std::size_t done,
                                            std::size_t total);

/// The sweep's start: its points, those finished in the journal, ranks x threads.
[[nodiscard]] std::string sweep_start_line(std::size_t total, std::size_t finished,
                                           const std::string& journal, int ranks, int threads);

/// One sweep point finished on `rank` (`done` of its `todo`, `elapsed` wall seconds): speed,
/// factors, outcome, amplitude [mm] of the holding wheelset (1-based).
[[nodiscard]] std::string sweep_point_line(int rank, std::size_t done, std::size_t todo,
                                           double elapsed, const SweepPointResult& r);

/// The sweep stopped before its end: points finished and where they are kept for a resume.
[[nodiscard]] std::string sweep_stopped_line(const SweepOutcome& r, const std::string& journal);

}  // namespace ferro::scenarios::analysis
