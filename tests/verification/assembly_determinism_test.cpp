// The assembly gives the same bits on any number of threads: element blocks computed in parallel are
// summed in element order (BlockBatch), not in the order threads finish. Shell + follower pressure +
// Winkler tread of the inflated tyre pressed onto the plane, residual and tangent.
#include <cstring>
#include <iostream>

#include <gtest/gtest.h>
#include <omp.h>

#include "contact_support.hpp"

namespace tirefem::verification {
namespace {

struct Assembled {
  Eigen::VectorXd residual;
  std::vector<double> tangent;
};

Assembled assemble_with_threads(NonlinearProblem& problem, const Eigen::VectorXd& u, int threads) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  problem.evaluate(u, 1.0, true);
  omp_set_num_threads(before);
  const SparseMatrix& k = problem.system().tangent();
  return {problem.system().residual(), std::vector<double>(k.valuePtr(), k.valuePtr() + k.nonZeros())};
}

bool same_bits(const double* a, const double* b, std::size_t n) { return std::memcmp(a, b, n * sizeof(double)) == 0; }

TEST(AssemblyDeterminism, SameBitsOnOneTwoAndThreeThreads) {
  TyrePressedOntoPlane pressed;
  NonlinearProblem& problem = *pressed.run.problem;
  const Eigen::VectorXd& u = pressed.inflated();
  const Assembled one = assemble_with_threads(problem, u, 1);
  ASSERT_GT(one.residual.norm(), 0.0);
  // The test programs run with the program's OpenMP thread limit (one per usable core, test_main.cpp):
  // thread counts beyond it are not tried, since the program never runs them there (on 2 cores: 1 against
  // 2 only; on 1 core nothing to compare).
  if (omp_get_thread_limit() < 2) GTEST_SKIP() << "one OpenMP thread on this machine: nothing to compare";
  for (int threads : {2, 3}) {
    if (threads > omp_get_thread_limit()) {
      std::cout << "  (" << threads << " threads: above this machine's thread limit, " << omp_get_thread_limit()
                << ", not tried)\n";
      continue;
    }
    const Assembled many = assemble_with_threads(problem, u, threads);
    EXPECT_TRUE(same_bits(one.residual.data(), many.residual.data(), one.residual.size())) << threads << " threads";
    ASSERT_EQ(one.tangent.size(), many.tangent.size());
    EXPECT_TRUE(same_bits(one.tangent.data(), many.tangent.data(), one.tangent.size())) << threads << " threads";
  }
}

}  // namespace
}  // namespace tirefem::verification
