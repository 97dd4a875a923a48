// The LU of a matrix unsymmetric in a small block only (CholeskySchurLU, through SparseDirectSolver's LU):
// a grid Laplacian (the shell) with an upstream coupling among a patch of nodes (the tread's friction,
// where a point's traction depends on the points it was carried from). It must solve exactly (as
// UMFPACK does) whether the patch's symmetric part is definite or not, take a local negative mode of the
// symmetric rest into its dense block, leave a rest indefinite everywhere to UMFPACK, follow a patch that
// moves, and precondition loose GMRES in single precision.
#include <gtest/gtest.h>

#include <utility>

#include <Eigen/UmfPackSupport>

#include "tirefem/solver/linear_solver.hpp"
#include "test_matrices.hpp"

namespace tirefem {
namespace {

constexpr int kGrid = 50;

// Node (i, j) of the grid gains −coupling · u(i − 1, j) in its row for i0 < i < i0 + rows, j0 ≤ j < j0 + cols:
// the patch's equations are the nodes i0 … i0 + rows − 1 of those columns.
SparseMatrix with_patch(SparseMatrix a, int i0, int j0, int rows, int cols, double coupling) {
  for (int i = i0 + 1; i < i0 + rows; ++i)
    for (int j = j0; j < j0 + cols; ++j) a.coeffRef(i * kGrid + j, (i - 1) * kGrid + j) -= coupling;
  a.makeCompressed();
  return a;
}

Eigen::VectorXd umfpack_solution(const SparseMatrix& a, const Eigen::VectorXd& b) {
  Eigen::UmfPackLU<SparseMatrix> lu(a);
  return lu.solve(b);
}

TEST(CholeskySchurLU, SolvesAsUmfpackWhetherThePatchsSymmetricPartIsDefiniteOrNot) {
  // 0.8 on a grid scaled over two decades: the patch's symmetric part is positive definite; 12 unscaled:
  // it is not (off-diagonal −7 against a diagonal near 4), and the Cholesky needs a larger σ than the first.
  for (const auto [coupling, decades] : {std::pair{0.8, 2.0}, std::pair{12.0, 0.0}}) {
    const SparseMatrix grid = scaled_grid_laplacian(kGrid, 0.05, decades);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(grid.rows(), -1.0, 2.0);
    const SparseMatrix a = with_patch(grid, 20, 15, 8, 10, coupling);
    SparseDirectSolver solver(false);
    solver.factorize(a);
    ASSERT_EQ(solver.stats().schur_factorizations, 1) << coupling;
    EXPECT_EQ(solver.stats().schur_block, 8 * 10) << coupling;
    EXPECT_EQ(solver.stats().failed_schur, 0) << coupling;
    const Eigen::VectorXd x = solver.solve(b);
    const Eigen::VectorXd reference = umfpack_solution(a, b);
    EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm()) << coupling;
    EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm()) << coupling;
  }
}

TEST(CholeskySchurLU, TakesALocalNegativeModeOfTheRestIntoTheBlock) {
  // A node far from the patch with a negative diagonal: A_VV indefinite there (as a rolling tangent's
  // shoulder ahead of the patch can be), A regular. Its neighbourhood joins the dense block.
  SparseMatrix a = with_patch(scaled_grid_laplacian(kGrid, 0.05, 0.0), 20, 15, 8, 10, 0.8);
  a.coeffRef(3, 3) = -40.0;
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  SparseDirectSolver solver(false);
  solver.factorize(a);
  EXPECT_EQ(solver.stats().failed_schur, 0);
  ASSERT_EQ(solver.stats().schur_factorizations, 1);
  EXPECT_GT(solver.stats().schur_block, 8 * 10);
  EXPECT_EQ(solver.stats().schur_analyses, 2);  // the patch's, then with the region added
  EXPECT_LT((a * solver.solve(b) - b).norm(), 1e-12 * b.norm());
  // The region stays in the block: the next factorisation succeeds at once.
  solver.factorize(a);
  EXPECT_EQ(solver.stats().schur_analyses, 2);
  EXPECT_EQ(solver.stats().schur_factorizations, 2);
}

TEST(CholeskySchurLU, LeavesAGloballyIndefiniteRestToUmfpack) {
  // Negative diagonal entries all over the grid: more negative modes than the regions one factorisation
  // may add.
  SparseMatrix a = with_patch(scaled_grid_laplacian(kGrid, 0.05, 0.0), 20, 15, 8, 10, 0.8);
  for (int i = 3; i < a.rows(); i += 97) a.coeffRef(i, i) = -40.0;
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  SparseDirectSolver solver(false);
  solver.factorize(a);
  EXPECT_EQ(solver.stats().failed_schur, 1);
  EXPECT_EQ(solver.stats().schur_factorizations, 0);
  EXPECT_LT((a * solver.solve(b) - b).norm(), 1e-12 * b.norm());
  // After one failure the next LU goes to UMFPACK at once, the one after tries again.
  const int factorizations = solver.stats().factorizations;
  solver.factorize(a);
  EXPECT_EQ(solver.stats().factorizations, factorizations + 1);
  solver.factorize(a);
  EXPECT_EQ(solver.stats().failed_schur, 2);
}

TEST(CholeskySchurLU, FollowsAPatchThatShrinksOrMoves) {
  const SparseMatrix grid = scaled_grid_laplacian(kGrid, 0.05, 1.0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(grid.rows(), 1.0, -1.0);
  SparseDirectSolver solver(false);
  const auto solves_exactly = [&](const SparseMatrix& a) {
    solver.factorize(a);
    return (a * solver.solve(b) - b).norm() < 1e-12 * b.norm();
  };
  EXPECT_TRUE(solves_exactly(with_patch(grid, 20, 15, 8, 10, 0.8)));
  EXPECT_EQ(solver.stats().schur_analyses, 1);
  // A patch one column narrower lies within the block analysed, which is not much larger: kept.
  EXPECT_TRUE(solves_exactly(with_patch(grid, 20, 15, 8, 9, 0.8)));
  EXPECT_EQ(solver.stats().schur_analyses, 1);
  EXPECT_EQ(solver.stats().schur_block, 8 * 10);
  // Moved elsewhere: analysed anew.
  EXPECT_TRUE(solves_exactly(with_patch(grid, 5, 30, 8, 10, 0.8)));
  EXPECT_EQ(solver.stats().schur_analyses, 2);
  EXPECT_EQ(solver.stats().schur_block, 8 * 10);
  EXPECT_EQ(solver.stats().schur_factorizations, 3);
}

TEST(CholeskySchurLU, PreconditionsLooseGmresInSinglePrecision) {
  const SparseMatrix grid = scaled_grid_laplacian(kGrid, 0.05, 0.0);
  const SparseMatrix a = with_patch(grid, 20, 15, 8, 10, 0.8);
  const SparseMatrix nearby = with_patch(grid, 20, 15, 8, 10, 0.9);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  SparseDirectSolver solver(false);
  solver.factorize(a);
  const Eigen::VectorXd exact = solver.solve(b);
  const Eigen::VectorXd single = solver.precondition(b, true);
  EXPECT_EQ(solver.stats().single_precision_solves, 1);
  const double difference = (single - exact).norm() / exact.norm();
  EXPECT_LT(difference, 1e-5);
  EXPECT_GT(difference, 1e-12);  // really single precision
  Eigen::VectorXd x;
  ASSERT_TRUE(solver.solve_preconditioned(nearby, b, x, 1e-3, 50));
  EXPECT_LT((nearby * x - b).norm(), 1e-2 * b.norm());
  const int singles = solver.stats().single_precision_solves;
  EXPECT_GT(singles, 1);
  // An exact step's tolerance: in double precision (in single GMRES would stall near 1e-5).
  ASSERT_TRUE(solver.solve_preconditioned(nearby, b, x, 1e-12, 50));
  EXPECT_LT((nearby * x - b).norm(), 1e-9 * b.norm());
  EXPECT_EQ(solver.stats().single_precision_solves, singles);
}

}  // namespace
}  // namespace tirefem
