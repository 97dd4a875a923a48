// Right-preconditioned GMRES: its stopping test is on the true residual, whatever the preconditioner.
#include "tirefem/solver/right_gmres.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

namespace {

// 1-D Laplacian (n unknowns) plus `springs` on every 7th diagonal entry: the springs play the new contact
// points, a low-rank change a preconditioner from the matrix without them does not know.
Eigen::SparseMatrix<double> laplacian(int n, double springs) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + (i % 7 == 0 ? springs : 0.0));
    if (i > 0) t.emplace_back(i, i - 1, -1.0), t.emplace_back(i - 1, i, -1.0);
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

TEST(RightGmres, MeetsTheTrueResidualWithAPreconditionerOfAnotherMatrix) {
  const int n = 200;
  const Eigen::SparseMatrix<double> a = laplacian(n, 50.0);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> old_factor(laplacian(n, 0.0));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  Eigen::VectorXd x;
  const tirefem::RightGmresResult r = tirefem::right_gmres(
      a, b, [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(old_factor.solve(v)); }, 1e-8, 60, x);
  ASSERT_TRUE(r.converged);
  EXPECT_GT(r.iterations, 1);
  EXPECT_LE((b - a * x).norm(), 1.01e-8 * b.norm());  // the estimate is the true residual
}

TEST(RightGmres, OneIterationWithTheExactPreconditioner) {
  const Eigen::SparseMatrix<double> a = laplacian(50, 3.0);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(a);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(50);
  Eigen::VectorXd x;
  const tirefem::RightGmresResult r = tirefem::right_gmres(
      a, b, [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(factor.solve(v)); }, 1e-10, 10, x);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_LE((b - a * x).norm(), 1e-10 * b.norm());
}

TEST(RightGmres, ReportsFailureWhenTheIterationsRunOut) {
  const Eigen::SparseMatrix<double> a = laplacian(200, 50.0);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(200);
  Eigen::VectorXd x;
  const tirefem::RightGmresResult r =
      tirefem::right_gmres(a, b, [](const Eigen::VectorXd& v) { return v; }, 1e-10, 5, x);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 5);
  EXPECT_GT(r.relative_residual, 1e-10);
}

}  // namespace
