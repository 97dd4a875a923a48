// GMRES's preconditioner with the Cholesky factor in single precision (SinglePrecisionFactor, through
// SparseDirectSolver::precondition): the supernodal solve with CHOLMOD's permutation must give CHOLMOD's
// own solution to single precision, serve GMRES to loose tolerances only, and leave
// UMFPACK's LU solves exact (CholeskySchurLU's: cholesky_schur_lu_test.cpp).
#include <gtest/gtest.h>

#include "tirefem/solver/linear_solver.hpp"
#include "test_matrices.hpp"

namespace tirefem {
namespace {

TEST(SinglePrecisionFactor, GivesTheDoubleFactorsSolutionToSinglePrecision) {
  for (const double decades : {0.0, 3.0}) {
    const SparseMatrix a = scaled_grid_laplacian(70, 0.05, decades);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 2.0);
    SparseDirectSolver solver(true);
    solver.factorize(a);
    const Eigen::VectorXd exact = solver.solve(b);
    ASSERT_LT((a * exact - b).norm(), 1e-10 * b.norm());
    const Eigen::VectorXd single = solver.precondition(b, true);
    EXPECT_EQ(solver.stats().single_precision_solves, 1);
    const double difference = (single - exact).norm() / exact.norm();
    // Single precision (unit round-off 6e-8) times the growth through the factor, not double's 1e-16.
    EXPECT_LT(difference, 1e-5) << decades;
    EXPECT_GT(difference, 1e-12) << decades;
    EXPECT_EQ(solver.precondition(b, false), exact);  // the double solve when not asked for
  }
}

TEST(SinglePrecisionFactor, PreconditionsLooseGmresSolvesOnlyAndFollowsEachNewFactorisation) {
  // (Unscaled: GMRES's tolerance is on the preconditioned residual, here of the true one's size.)
  const SparseMatrix a = scaled_grid_laplacian(60, 0.05, 0.0);
  const SparseMatrix nearby = scaled_grid_laplacian(60, 0.06, 0.0);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  SparseDirectSolver solver(true);
  solver.factorize(a);
  Eigen::VectorXd x;
  ASSERT_TRUE(solver.solve_preconditioned(nearby, b, x, 1e-3, 50));  // an inexact Newton step's tolerance
  EXPECT_LT((nearby * x - b).norm(), 1e-2 * b.norm());
  const int single = solver.stats().single_precision_solves;
  EXPECT_GT(single, 0);
  ASSERT_TRUE(solver.solve_preconditioned(nearby, b, x, 1e-9, 50));  // an exact step's: double
  EXPECT_LT((nearby * x - b).norm(), 1e-8 * b.norm());
  EXPECT_EQ(solver.stats().single_precision_solves, single);
  // A new factorisation (of `nearby` itself) replaces the single-precision copy: GMRES then converges at once.
  solver.factorize(nearby);
  const int before = solver.stats().krylov_iterations;
  ASSERT_TRUE(solver.solve_preconditioned(nearby, b, x, 1e-3, 50));
  EXPECT_LE(solver.stats().krylov_iterations - before, 1);
  EXPECT_LT((nearby * x - b).norm(), 1e-4 * b.norm());
}

TEST(SinglePrecisionFactor, UmfpacksLuServesInDoublePrecision) {
  // Unsymmetric everywhere (each row coupled to the next node, as no tangent of the tyre is): UMFPACK's
  // LU, whose solves stay exact whatever GMRES asks for.
  SparseMatrix a = scaled_grid_laplacian(20, 0.05, 0.0);
  for (int i = 0; i + 1 < a.rows(); ++i) a.coeffRef(i, i + 1) -= 0.3;
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  SparseDirectSolver solver(false);
  solver.factorize(a);
  EXPECT_EQ(solver.stats().schur_factorizations, 0);
  EXPECT_LT((a * solver.precondition(b, true) - b).norm(), 1e-12 * b.norm());
  EXPECT_EQ(solver.stats().single_precision_solves, 0);
}

}  // namespace
}  // namespace tirefem
