// The studies-side-by-side scheduler: how threads are shared out, that every task runs once and the
// tasks of a chain in order, that a failing task stops the others and reaches the caller, and that the last
// worker running takes the threads of the others.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <omp.h>

#include "tirefem/analysis/parallel_chains.hpp"

namespace tirefem {
namespace {

TEST(ParallelChains, ThreadsAreSharedOutAmongAsManyWorkersAsChains) {
  EXPECT_EQ(plan_workers(5, 2).workers, 2);
  EXPECT_EQ(plan_workers(5, 2).threads_per_worker, 1);
  EXPECT_EQ(plan_workers(1, 2).workers, 1);
  EXPECT_EQ(plan_workers(1, 2).threads_per_worker, 2);
  EXPECT_EQ(plan_workers(0, 4).workers, 1);
  EXPECT_EQ(plan_workers(2, 5).threads_per_worker, 2);
}

TEST(ParallelChains, EveryTaskRunsOnceAndAChainInOrder) {
  for (int workers : {1, 2, 3}) {
    std::mutex m;
    std::vector<std::vector<int>> seen(4);
    std::vector<TaskChain> chains(4);
    for (int c = 0; c < 4; ++c)
      for (int t = 0; t < 3; ++t)
        chains[c].push_back([&, c, t] {
          const std::lock_guard lock(m);
          seen[c].push_back(t);
        });
    std::atomic<bool> stop{false};
    run_chains(chains, {workers, 1}, stop);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(seen[c], (std::vector<int>{0, 1, 2})) << workers << " workers, chain " << c;
    EXPECT_FALSE(stop);
  }
}

// Three chains: a start (30 ms) and a first series after it; a second series waiting for the start; and
// another. Returns the order in which their tasks ended.
std::vector<std::string> start_and_series(int workers, bool hold_later) {
  std::mutex m;
  std::vector<std::string> order;
  const auto note = [&](std::string what) {
    const std::lock_guard lock(m);
    order.push_back(std::move(what));
  };
  const auto slow = [&](std::string what) {
    return [&, what] {
      std::this_thread::sleep_for(std::chrono::milliseconds(30));
      note(what);
    };
  };
  std::vector<TaskChain> chains(3);
  chains[0] = {slow("start"), slow("first series")};
  chains[1] = {[&] { note("second series"); }};
  chains[2] = {[&] { note("other"); }};
  std::vector<std::optional<ChainStart>> starts(3);
  starts[1] = ChainStart{0, 1, hold_later};
  std::atomic<bool> stop{false};
  run_chains(chains, {workers, 1}, stop, nullptr, starts);
  return order;
}

// A chain that waits for the first task of an earlier one starts only once that task has run, whatever the
// number of workers; a free worker meanwhile runs a chain that may start. With hold_later the waiting chain
// keeps the free worker for itself: "other" runs after it.
TEST(ParallelChains, AChainWaitsForTheTasksItStartsAfter) {
  for (int workers : {1, 2, 3}) {
    const std::vector<std::string> order = start_and_series(workers, false);
    ASSERT_EQ(order.size(), 4u) << workers << " workers";
    const auto at = [&](const std::string& s) { return std::find(order.begin(), order.end(), s) - order.begin(); };
    EXPECT_LT(at("start"), at("second series")) << workers << " workers";
    EXPECT_LT(at("start"), at("first series")) << workers << " workers";
    if (workers >= 2) EXPECT_LT(at("other"), at("start")) << "the free worker runs the startable chain meanwhile";
  }
  EXPECT_EQ(start_and_series(2, true), (std::vector<std::string>{"start", "second series", "other", "first series"}));
  std::vector<TaskChain> chains(2, TaskChain{[] {}});
  std::vector<std::optional<ChainStart>> backwards(2);
  backwards[0] = ChainStart{1, 1};
  std::atomic<bool> stop{false};
  EXPECT_THROW(run_chains(chains, {2, 1}, stop, nullptr, backwards), std::invalid_argument);
}

TEST(ParallelChains, AFailingTaskStopsTheRunAndIsRethrown) {
  std::atomic<int> after_failure{0};
  std::vector<TaskChain> chains(2);
  chains[0] = {[] { throw std::runtime_error("first chain failed"); }, [&] { ++after_failure; }};
  // The other chain polls the stop flag between its steps, as the studies do through their progress.
  std::atomic<bool> stop{false};
  chains[1] = {[&] {
    for (int i = 0; i < 2000 && !stop; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }, [&] { ++after_failure; }};
  EXPECT_THROW(run_chains(chains, {2, 1}, stop), std::runtime_error);
  EXPECT_TRUE(stop);
  EXPECT_EQ(after_failure, 0);  // no task starts once the run is stopped
}

// Two workers of one thread each: the long chain's checkpoints keep one thread while the short chain
// runs and take both once it has ended; afterwards the caller's own setting is back.
TEST(ParallelChains, TheLastWorkerRunningTakesTheThreadsOfTheOthers) {
  const int own = omp_get_max_threads();
  WorkerShare share(4);
  std::atomic<bool> short_done{false};
  std::atomic<int> while_both = -1, when_alone = -1;
  std::vector<TaskChain> chains(2);
  chains[0] = {[&] {
    share.checkpoint();
    while_both = omp_get_max_threads();
    for (int i = 0; i < 5000 && !short_done; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    // Until the short chain's worker has returned (at most 5 s).
    for (int i = 0; i < 5000 && omp_get_max_threads() < 4; ++i) {
      share.checkpoint();
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    when_alone = omp_get_max_threads();
  }};
  chains[1] = {[&] { short_done = true; }};
  std::atomic<bool> stop{false};
  run_chains(chains, {2, 1}, stop, &share);
  EXPECT_EQ(while_both, 1);
  EXPECT_EQ(when_alone, 4);
  EXPECT_EQ(omp_get_max_threads(), own);
  share.checkpoint();  // outside run_chains: no effect
  EXPECT_EQ(omp_get_max_threads(), own);
}

}  // namespace
}  // namespace tirefem
