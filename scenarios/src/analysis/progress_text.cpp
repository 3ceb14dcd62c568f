#include "ferro/scenarios/analysis/progress_text.hpp"

#include <fmt/format.h>

#include <cmath>

namespace ferro::scenarios::analysis {

std::string branch_progress_line(const contact::ReductionFactors& k,
                                 const std::vector<std::string>& names, const BranchPoint& p) {
  const auto& fit = p.run.fit;
  const std::string growth =
      fit.valid() ? fmt::format(" (sigma = {:.3g} +- {:.2g} /s, beta = {:.3g} /(s mm^2))",
                                fit.sigma, fit.sigma_error, fit.beta * 1e-6)
                  : std::string();
  return fmt::format(
      "progress: K = ({}, {}) V = {:.4f} m/s{}: {} {:.4f} mm ({}) after {:.1f} s{}\n", k.k11,
      k.k22, p.speed, p.bisection ? " (bisection)" : "", to_string(p.run.outcome),
      p.run.amplitude[p.run.holder] * 1e3,
      p.run.holder < names.size() ? names[p.run.holder] : std::string("?"), p.run.time, growth);
}

std::string kij_progress_line(const KijRow& row, std::size_t done, std::size_t total) {
  return fmt::format("progress: K11 = {}, K22 = {} done ({}/{})\n", row.k.k11, row.k.k22, done,
                     total);
}

std::string sweep_start_line(std::size_t total, std::size_t finished, const std::string& journal,
                             int ranks, int threads) {
  return fmt::format(
      "ferrodyn sweep: {} points ({} already finished in {}), {} rank(s) x {} thread(s)\n", total,
      finished, journal, ranks, threads);
}

std::string sweep_point_line(int rank, std::size_t done, std::size_t todo, double elapsed,
                             const SweepPointResult& r) {
  return fmt::format(
      "[rank {} {:>4}/{:<4} {:6.1f} s] V = {:8.4f} m/s K = ({:.3f}, {:.3f}): {} {:.4f} mm "
      "(wheelset {})\n",
      rank, done, todo, elapsed, r.point.speed, r.point.k.k11, r.point.k.k22,
      to_string(r.outcome), r.amplitude.empty() ? NAN : r.amplitude[r.holder] * 1e3,
      r.holder + 1);
}

std::string sweep_stopped_line(const SweepOutcome& r, const std::string& journal) {
  return fmt::format(
      "ferrodyn sweep: stopped with {} of {} points finished (recorded in {}); run the same "
      "command again to resume\n",
      r.finished, r.total, journal);
}

}  // namespace ferro::scenarios::analysis
