#include "tirefem/analysis/parallel_chains.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>

#include <omp.h>

#include "tirefem/solver/blas_kernel.hpp"

namespace tirefem {

WorkerPlan plan_workers(int chains, int threads) {
  WorkerPlan plan;
  plan.workers = std::max(1, std::min(chains, threads));
  plan.threads_per_worker = std::max(1, threads / plan.workers);
  return plan;
}

void WorkerShare::checkpoint() {
  if (running_ != 1) return;  // others still running, or not side by side at all
  if (omp_get_max_threads() < threads_) omp_set_num_threads(threads_);  // this thread's own setting
}

void run_chains(const std::vector<TaskChain>& chains, const WorkerPlan& plan, std::atomic<bool>& stop,
                WorkerShare* share) {
  std::atomic<std::size_t> next{0};
  std::mutex error_mutex;
  std::exception_ptr first_error;
  const auto run = [&] {
    omp_set_num_threads(plan.threads_per_worker);  // this thread's own setting
    for (std::size_t c = next++; c < chains.size(); c = next++) {
      try {
        for (const auto& task : chains[c]) {
          if (stop) return;
          task();
        }
      } catch (...) {
        stop = true;
        const std::lock_guard lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        return;
      }
    }
  };
  const auto work = [&] {
    run();
    if (share && plan.workers > 1) --share->running_;  // out of chains (or stopped)
  };
  if (share) share->running_ = plan.workers > 1 ? plan.workers : 0;
  if (plan.workers == 1) {
    work();
  } else {
    const int blas = blas_threads();
    set_blas_threads(1);
    std::vector<std::thread> threads;
    for (int w = 1; w < plan.workers; ++w) threads.emplace_back(work);
    const int own = omp_get_max_threads();
    work();
    omp_set_num_threads(own);
    for (std::thread& t : threads) t.join();
    set_blas_threads(blas);
  }
  if (share) share->running_ = 0;
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace tirefem
