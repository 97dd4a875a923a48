#pragma once
// The studies of a case run at the same time, one per worker thread. On 2 cores a sparse factorisation
// or a triangular solve keeps about one core busy (the BLAS gains little from a second thread on these
// supernodes), so two studies side by side, each on one core, use the machine fully.
#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace tirefem {

// Tasks that must run one after the other (a footprint, then the rolling study that starts from it).
using TaskChain = std::vector<std::function<void()>>;

// A chain that may start only once the first `tasks` tasks of an earlier chain have run (e.g. the second
// series of a tyre test's load, after the task that solved that load's footprint and free rolling).
struct ChainStart {
  std::size_t after_chain = 0;
  std::size_t tasks = 0;
  // While this chain waits, the chains after it are not taken either: a long chain that should start as
  // soon as it may (rather than after whatever a free worker took meanwhile).
  bool hold_later = false;
};

struct WorkerPlan {
  int workers = 1;
  int threads_per_worker = 1;  // OpenMP (assembly) and BLAS threads of each worker
};

// As many workers as there are chains and threads (OpenMP's maximum), the threads shared out evenly.
WorkerPlan plan_workers(int chains, int threads);

// The workers of one run_chains that still have chains to run. A worker left alone takes the threads of
// those that ran out for its OpenMP loops (the assembly, GMRES's products) at its next checkpoint: the last
// study of a run does not assemble on one core while the other idles. Its BLAS stays on one thread: the
// BLAS's round-off depends on its thread count, and the moment a worker is left alone varies from run to
// run, while the OpenMP loops give the same sums on any number of threads.
class WorkerShare {
 public:
  explicit WorkerShare(int threads) : threads_(threads) {}
  // From a worker's own thread, between solver steps (where its study reports progress).
  void checkpoint();

 private:
  friend void run_chains(const std::vector<TaskChain>&, const WorkerPlan&, std::atomic<bool>&, WorkerShare*,
                         const std::vector<std::optional<ChainStart>>&);
  int threads_;
  std::atomic<int> running_{0};  // 0: not running side by side (one worker, or outside run_chains)
};

// Runs the chains on plan.workers threads, each taking, when it becomes free, the first chain not yet
// taken whose start condition (`starts[c]`, if given: after_chain < c) holds, and not one after a chain
// that waits with hold_later; it waits while there is none. A
// worker runs its OpenMP loops on threads_per_worker threads, and with more than one worker the BLAS
// runs single-threaded in each (restored afterwards). An exception from a task ends its chain and sets
// `stop` (the other tasks poll it between solver steps and end early); once every worker has returned
// the first exception is rethrown. With `share`, the last worker running widens to all threads (above).
void run_chains(const std::vector<TaskChain>& chains, const WorkerPlan& plan, std::atomic<bool>& stop,
                WorkerShare* share = nullptr, const std::vector<std::optional<ChainStart>>& starts = {});

}  // namespace tirefem
