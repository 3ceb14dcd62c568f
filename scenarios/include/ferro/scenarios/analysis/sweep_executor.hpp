#pragma once
// Where the points of a sweep run: the processes (MPI ranks, each with its own threads) that
// share a sweep's points, and how rank 0 collects what the others computed. A local executor is
// one process; the MPI executor needs the library built with MPI (FERRO_WITH_MPI) and a process
// started by an MPI launcher (the program asks for it when mpirun's environment is set).
// Points are dealt to ranks by index (i mod size) and to threads within a rank by a pool, so a
// serial, a threaded and an MPI sweep compute every point with the same function and numbers.

#include <memory>
#include <string>
#include <vector>

namespace ferro::scenarios::analysis {

class SweepExecutor {
 public:
  virtual ~SweepExecutor() = default;
  [[nodiscard]] virtual int rank() const { return 0; }
  [[nodiscard]] virtual int size() const { return 1; }
  /// Waits for every rank.
  virtual void barrier() {}
  /// Rank 0 receives every rank's text, in rank order (itself first); other ranks get their own.
  [[nodiscard]] virtual std::vector<std::string> gather(const std::string& mine) { return {mine}; }
  /// Ends every rank of the job with `code` after an error on this rank (another rank may wait
  /// in a collective); does nothing on a single process.
  virtual void abort(int code) { (void)code; }
};

/// With `mpi` and a library built with MPI: the MPI executor (MPI is initialised here and
/// finalised when the executor is destroyed); else a local one.
[[nodiscard]] std::unique_ptr<SweepExecutor> make_sweep_executor(bool mpi);

/// True when this library was built with MPI.
[[nodiscard]] bool sweep_executor_has_mpi();

}  // namespace ferro::scenarios::analysis
