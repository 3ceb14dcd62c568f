// Local and MPI executors of a sweep (see the header).
#include "ferro/scenarios/analysis/sweep_executor.hpp"

#ifdef FERRO_WITH_MPI
#include <mpi.h>
#endif

namespace ferro::scenarios::analysis {
namespace {

#ifdef FERRO_WITH_MPI
class MpiExecutor final : public SweepExecutor {
 public:
  MpiExecutor() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiExecutor() override { MPI_Finalize(); }
  MpiExecutor(const MpiExecutor&) = delete;
  MpiExecutor& operator=(const MpiExecutor&) = delete;

  [[nodiscard]] int rank() const override { return rank_; }
  [[nodiscard]] int size() const override { return size_; }
  void barrier() override { MPI_Barrier(MPI_COMM_WORLD); }
  void abort(int code) override {
    if (size_ > 1) MPI_Abort(MPI_COMM_WORLD, code);
  }

  std::vector<std::string> gather(const std::string& mine) override {
    int len = static_cast<int>(mine.size());
    std::vector<int> lens(static_cast<std::size_t>(size_));
    MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> displ(static_cast<std::size_t>(size_), 0);
    int total = 0;
    for (int i = 0; i < size_; ++i) {
      displ[static_cast<std::size_t>(i)] = total;
      total += lens[static_cast<std::size_t>(i)];
    }
    std::string buf(static_cast<std::size_t>(rank_ == 0 ? total : 0), '\0');
    MPI_Gatherv(mine.data(), len, MPI_CHAR, buf.data(), lens.data(), displ.data(), MPI_CHAR, 0,
                MPI_COMM_WORLD);
    if (rank_ != 0) return {mine};
    std::vector<std::string> all;
    for (int i = 0; i < size_; ++i)
      all.push_back(buf.substr(static_cast<std::size_t>(displ[static_cast<std::size_t>(i)]),
                               static_cast<std::size_t>(lens[static_cast<std::size_t>(i)])));
    return all;
  }

 private:
  int rank_ = 0, size_ = 1;
};
#endif

}  // namespace

std::unique_ptr<SweepExecutor> make_sweep_executor(bool mpi) {
#ifdef FERRO_WITH_MPI
  if (mpi) return std::make_unique<MpiExecutor>();
#else
  (void)mpi;
#endif
  return std::make_unique<SweepExecutor>();
}

bool sweep_executor_has_mpi() {
#ifdef FERRO_WITH_MPI
  return true;
#else
  return false;
#endif
}

}  // namespace ferro::scenarios::analysis
