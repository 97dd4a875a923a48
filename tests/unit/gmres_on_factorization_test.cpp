// GMRES on a reused factorisation (SparseDirectSolver::solve_preconditioned): a solve is accepted only if
// it cuts the true residual tenfold. GMRES measures the preconditioned residual, which a factorisation of
// another matrix can make small while the true one is not; for a symmetric problem GMRES then goes on a few
// iterations towards the true residual, for an unsymmetric one (a rolling LU) the solve is given up and the
// caller factorises afresh (docs/studies/load-curve-newton-cost.md, last section), unless the caller asks
// for the continuation (near the end of a Newton solve).
#include <gtest/gtest.h>

#include "tirefem/solver/linear_solver.hpp"
#include "test_matrices.hpp"

namespace tirefem {
namespace {

// The grid Laplacian with rows and columns scaled over 2 decades (stiff and soft equations side by side, as
// the shell's), and the same with every 13th diagonal entry (in a scattered order) 50% larger: the
// factorisation of the first, as a preconditioner for the second, meets GMRES's tolerance of 1e-3 with a
// true residual of about 0.19.
struct StaleFactorisation {
  SparseMatrix factorised = scaled_grid_laplacian(30, 0.01, 2.0);
  SparseMatrix solved = factorised;
  Eigen::VectorXd rhs = Eigen::VectorXd::Ones(factorised.rows());
  StaleFactorisation() {
    for (int k = 0; k < solved.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(solved, k); it; ++it)
        if (it.row() == it.col() && (it.row() * 7919) % 13 == 0) it.valueRef() *= 1.5;
  }
  double true_residual(const Eigen::VectorXd& x) const { return (rhs - solved * x).norm() / rhs.norm(); }
};

TEST(GmresOnFactorization, AnUnsymmetricSolveWhoseTrueResidualIsTooLargeIsGivenUp) {
  const StaleFactorisation m;
  SparseDirectSolver lu(false);  // UMFPACK's LU (the matrix is symmetric: no Cholesky-plus-dense-LU form)
  lu.factorize(m.factorised);
  Eigen::VectorXd x;
  EXPECT_FALSE(lu.solve_preconditioned(m.solved, m.rhs, x, 1e-3, 25));
  EXPECT_GT(m.true_residual(x), 0.1);  // met the preconditioned tolerance, not the true one
  EXPECT_EQ(lu.stats().krylov_failures, 1);
}

TEST(GmresOnFactorization, ASymmetricSolveGoesOnAFewIterationsUntilTheTrueResidualIsCutTenfold) {
  const StaleFactorisation m;
  SparseDirectSolver lu(false), cholesky(true);
  lu.factorize(m.factorised);
  cholesky.factorize(m.factorised);
  Eigen::VectorXd x_lu, x;
  lu.solve_preconditioned(m.solved, m.rhs, x_lu, 1e-3, 25);
  ASSERT_TRUE(cholesky.solve_preconditioned(m.solved, m.rhs, x, 1e-3, 25));
  EXPECT_LE(m.true_residual(x), 0.1);
  EXPECT_EQ(cholesky.stats().krylov_failures, 0);
  // The same first solve as the LU's, then at most 4 more iterations.
  EXPECT_GT(cholesky.stats().krylov_iterations, lu.stats().krylov_iterations);
  EXPECT_LE(cholesky.stats().krylov_iterations, lu.stats().krylov_iterations + 4);
}

// Near a Newton solve's end (NewtonSettings::keep_lu_below_residual) an LU's solve goes on as well.
TEST(GmresOnFactorization, AnUnsymmetricSolveGoesOnWhenAsked) {
  const StaleFactorisation m;
  SparseDirectSolver lu(false), given_up(false);
  lu.factorize(m.factorised);
  given_up.factorize(m.factorised);
  Eigen::VectorXd x, x_given_up;
  given_up.solve_preconditioned(m.solved, m.rhs, x_given_up, 1e-3, 25);
  ASSERT_TRUE(lu.solve_preconditioned(m.solved, m.rhs, x, 1e-3, 25, /*continue_unsymmetric=*/true));
  EXPECT_LE(m.true_residual(x), 0.1);
  EXPECT_GT(lu.stats().krylov_iterations, given_up.stats().krylov_iterations);
  EXPECT_LE(lu.stats().krylov_iterations, given_up.stats().krylov_iterations + 4);
}

TEST(GmresOnFactorization, NoContinuationFromASolveNoBetterThanZero) {
  // Every 13th diagonal entry 20% larger over 3 decades of scaling: GMRES meets its tolerance with a true
  // residual above that of x = 0; it is given up at once, symmetric or not.
  SparseMatrix factorised = scaled_grid_laplacian(30, 0.01, 3.0), solved = factorised;
  for (int k = 0; k < solved.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(solved, k); it; ++it)
      if (it.row() == it.col() && (it.row() * 7919) % 13 == 0) it.valueRef() *= 1.2;
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(solved.rows());
  SparseDirectSolver lu(false), cholesky(true);
  lu.factorize(factorised);
  cholesky.factorize(factorised);
  Eigen::VectorXd x_lu, x;
  EXPECT_FALSE(lu.solve_preconditioned(solved, rhs, x_lu, 1e-3, 25));
  EXPECT_FALSE(cholesky.solve_preconditioned(solved, rhs, x, 1e-3, 25));
  EXPECT_GE((rhs - solved * x).norm(), rhs.norm());
  EXPECT_EQ(cholesky.stats().krylov_iterations, lu.stats().krylov_iterations);  // the first solve's alone
}

}  // namespace
}  // namespace tirefem
