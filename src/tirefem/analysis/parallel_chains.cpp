#include "tirefem/analysis/parallel_chains.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
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
                WorkerShare* share, const std::vector<std::optional<ChainStart>>& starts) {
  for (std::size_t c = 0; c < starts.size() && c < chains.size(); ++c)
    if (starts[c] && starts[c]->after_chain >= c)
      throw std::invalid_argument("run_chains: a chain may wait only for an earlier one");
  // Under `mutex`: which chains are taken, how many tasks of each have run. (A run that stops starts
  // nothing more: the waiting workers see `stop` and return.)
  std::mutex mutex;
  std::condition_variable progressed;
  std::vector<char> taken(chains.size(), 0);
  std::vector<std::size_t> tasks_run(chains.size(), 0);
  std::exception_ptr first_error;
  const auto may_start = [&](std::size_t c) {
    if (c >= starts.size() || !starts[c]) return true;
    const ChainStart& s = *starts[c];
    return tasks_run[s.after_chain] >= std::min(s.tasks, chains[s.after_chain].size());
  };
  // The next chain for a free worker: the first one not taken that may start; none when all are taken.
  // (Waiting for a chain's start ends: what it waits for is an earlier chain, taken or startable.)
  const auto take = [&]() -> std::optional<std::size_t> {
    std::unique_lock lock(mutex);
    for (;;) {
      if (stop) return std::nullopt;
      bool waiting = false;
      for (std::size_t c = 0; c < chains.size(); ++c) {
        if (taken[c]) continue;
        if (may_start(c)) {
          taken[c] = 1;
          return c;
        }
        waiting = true;
        if (starts[c]->hold_later) break;
      }
      if (!waiting) return std::nullopt;
      // (`stop` may also be set from outside, without a notification: polled.)
      progressed.wait_for(lock, std::chrono::milliseconds(50));
    }
  };
  const auto ran = [&](std::size_t c, std::size_t n) {
    {
      const std::lock_guard lock(mutex);
      tasks_run[c] = n;
    }
    progressed.notify_all();
  };
  const auto run = [&] {
    omp_set_num_threads(plan.threads_per_worker);  // this thread's own setting
    while (const std::optional<std::size_t> c = take()) {
      try {
        for (std::size_t t = 0; t < chains[*c].size(); ++t) {
          if (stop) break;
          chains[*c][t]();
          ran(*c, t + 1);
        }
      } catch (...) {
        {
          const std::lock_guard lock(mutex);
          stop = true;
          if (!first_error) first_error = std::current_exception();
        }
        progressed.notify_all();
        return;
      }
      if (stop) return;
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
