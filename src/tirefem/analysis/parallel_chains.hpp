#pragma once
// The studies of a case run at the same time, one per worker thread. On 2 cores a sparse factorisation
// or a triangular solve keeps about one core busy (the BLAS gains little from a second thread on these
// supernodes), so two studies side by side, each on one core, use the machine fully.
#include <atomic>
#include <functional>
#include <vector>

namespace tirefem {

// Tasks that must run one after the other (a footprint, then the rolling study that starts from it).
using TaskChain = std::vector<std::function<void()>>;

struct WorkerPlan {
  int workers = 1;
  int threads_per_worker = 1;  // OpenMP (assembly) and BLAS threads of each worker
};

// As many workers as there are chains and threads (OpenMP's maximum), the threads shared out evenly.
WorkerPlan plan_workers(int chains, int threads);

// Runs the chains on plan.workers threads, each taking the next chain in order when it becomes free. A
// worker runs its OpenMP loops on threads_per_worker threads, and with more than one worker the BLAS
// runs single-threaded in each (restored afterwards). An exception from a task ends its chain and sets
// `stop` (the other tasks poll it between solver steps and end early); once every worker has returned
// the first exception is rethrown.
void run_chains(const std::vector<TaskChain>& chains, const WorkerPlan& plan, std::atomic<bool>& stop);

}  // namespace tirefem
