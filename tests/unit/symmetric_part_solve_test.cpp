// GMRES on an unsymmetric matrix preconditioned by a Cholesky factorisation of its symmetric part
// (SparseDirectSolver::solve_by_symmetric_part): the rolling tangent's solve. It must give the LU's
// solution where the symmetric part is positive definite, refuse (so that the LU serves) where it is
// far from that, and then leave the next calls to the LU without new attempts.
#include <gtest/gtest.h>

#include <vector>

#include "tirefem/solver/linear_solver.hpp"

namespace tirefem {
namespace {

// A chain of unit springs on an elastic foundation (diagonal `diagonal`, −1 beside it) plus an
// unsymmetric coupling of each node to its neighbour upstream, as a tread point's stick traction depends
// on the point it is carried from. Its eigenvalues (a Toeplitz matrix) lie in diagonal ∓ 2√(1 + coupling),
// its symmetric part's in diagonal ∓ (2 + coupling): with 4.5 and 3 the matrix is regular (smallest
// eigenvalue about 0.5) while its symmetric part is indefinite (about −0.5).
SparseMatrix spring_chain_with_upstream_coupling(int n, double coupling, double diagonal = 3.0) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, diagonal);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0), t.emplace_back(i + 1, i, -1.0);
    if (i > 0) t.emplace_back(i, i - 1, -coupling);  // row i depends on node i − 1 only
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

TEST(SymmetricPartSolve, EqualsTheLuSolutionWhenTheSymmetricPartIsPositiveDefinite) {
  const int n = 200;
  const SparseMatrix a = spring_chain_with_upstream_coupling(n, 0.3);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  SparseDirectSolver lu(false);
  lu.factorize(a);
  const Eigen::VectorXd exact = lu.solve(b);
  ASSERT_LT((a * exact - b).norm(), 1e-12 * b.norm());

  SparseDirectSolver solver(false);
  Eigen::VectorXd x;
  ASSERT_TRUE(solver.solve_by_symmetric_part(a, b, x, 1e-12, 100));
  EXPECT_LT((x - exact).norm(), 1e-9 * exact.norm());
  EXPECT_EQ(solver.stats().symmetric_part_factorizations, 1);
  EXPECT_FALSE(solver.stats().used_lu);
  // The factorisation stays held and preconditions the next solve, of a nearby matrix.
  const SparseMatrix nearby = spring_chain_with_upstream_coupling(n, 0.35);
  ASSERT_TRUE(solver.solve_preconditioned(nearby, b, x, 1e-10, 100));
  EXPECT_LT((nearby * x - b).norm(), 1e-8 * b.norm());
}

TEST(SymmetricPartSolve, AnIndefiniteSymmetricPartIsRefusedAndTheNextCallsGoToTheLu) {
  // (Few nodes: the unsymmetric chain is far from normal, its condition number growing as 2ⁿ.)
  const int n = 20;
  // The symmetric part needs a relative shift of about 0.1, far beyond the largest one tried.
  const SparseMatrix hard = spring_chain_with_upstream_coupling(n, 3.0, 4.5);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  SparseDirectSolver solver(false);
  Eigen::VectorXd x;
  EXPECT_FALSE(solver.solve_by_symmetric_part(hard, b, x, 1e-10, 50));
  const int attempts = solver.stats().factorizations;
  EXPECT_GE(attempts, 1);
  EXPECT_EQ(solver.stats().symmetric_part_factorizations, 0);
  // The caller's LU serves.
  solver.factorize(hard);
  EXPECT_LT((hard * solver.solve(b) - b).norm(), 1e-10 * b.norm());
  // One failure: the next call goes to the LU at once (no factorisation attempted), the one after
  // tries again.
  const SparseMatrix easy = spring_chain_with_upstream_coupling(n, 0.3);
  EXPECT_FALSE(solver.solve_by_symmetric_part(easy, b, x, 1e-10, 50));
  EXPECT_EQ(solver.stats().factorizations, attempts + 1);  // only the LU above
  ASSERT_TRUE(solver.solve_by_symmetric_part(easy, b, x, 1e-10, 50));
  EXPECT_LT((easy * x - b).norm(), 1e-8 * b.norm());
}

}  // namespace
}  // namespace tirefem
