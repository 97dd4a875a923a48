// The dense LU in single precision with refinement (MixedPrecisionLU, the rolling LU's Schur complement):
// solves to a double LU's accuracy on a matrix floats resolve, hands over to the double LU on one they do
// not, and reports a singular matrix.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>

#include "tirefem/solver/mixed_precision_lu.hpp"

namespace tirefem {
namespace {

// An unsymmetric m × m matrix with singular values spread log-uniformly from 1 to 10^-decades (Q Σ Pᵀ from
// the QR factors of two random matrices).
Eigen::MatrixXd with_condition(int m, double decades, unsigned seed) {
  std::srand(seed);
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(m, m)).householderQ();
  const Eigen::MatrixXd p = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(m, m)).householderQ();
  Eigen::VectorXd sigma(m);
  for (int i = 0; i < m; ++i) sigma[i] = std::pow(10.0, -decades * i / (m - 1));
  return q * sigma.asDiagonal() * p.transpose();
}

double backward_error(const Eigen::MatrixXd& s, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (b - s * x).lpNorm<Eigen::Infinity>() /
         (s.cwiseAbs().rowwise().sum().maxCoeff() * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
}

// x = S⁻¹ b by `lu`, factorised from a copy of S (factorize swaps its argument out).
Eigen::VectorXd factorized_solve(MixedPrecisionLU& lu, const Eigen::MatrixXd& s, const Eigen::VectorXd& b) {
  Eigen::MatrixXd copy = s;
  EXPECT_TRUE(lu.factorize(copy));
  Eigen::VectorXd x = b;
  lu.solve(x.data());
  return x;
}

TEST(MixedPrecisionLU, RefinesSinglePrecisionFactorsToDoubleAccuracy) {
  const int m = 300;
  const Eigen::MatrixXd s = with_condition(m, 3.0, 1);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(m, -1.0, 2.0);
  MixedPrecisionLU lu;
  Eigen::VectorXd x = factorized_solve(lu, s, b);
  EXPECT_FALSE(lu.double_factors());
  EXPECT_GE(lu.refinement_steps(), 2);  // one single-precision solve alone is not enough
  EXPECT_LE(lu.refinement_steps(), 4);
  EXPECT_LT(backward_error(s, x, b), 8 * 2.3e-16);
  const Eigen::VectorXd reference = s.partialPivLu().solve(b);
  EXPECT_LT((x - reference).norm(), 1e-11 * reference.norm());  // cond 1e3: both within 1e3 ε of the truth

  // The preconditioner's solve: single precision alone, about 1e-7 × cond off.
  Eigen::VectorXf y = b.cast<float>();
  lu.solve_single_precision(y.data());
  const double single_error = (y.cast<double>() - reference).norm() / reference.norm();
  EXPECT_LT(single_error, 1e-3);
  EXPECT_GT(single_error, 1e-12);
}

TEST(MixedPrecisionLU, HandsAMatrixTooIllConditionedForFloatsToTheDoubleLU) {
  const int m = 200;
  const Eigen::MatrixXd s = with_condition(m, 9.0, 2);  // cond 1e9: floats (ε 6e-8) cannot resolve it
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(m);
  MixedPrecisionLU lu;
  Eigen::VectorXd x = factorized_solve(lu, s, b);
  EXPECT_TRUE(lu.double_factors());
  EXPECT_LT(backward_error(s, x, b), 8 * 2.3e-16);
  const int steps = lu.refinement_steps();
  x = b;
  lu.solve(x.data());  // the double LU now serves at once
  EXPECT_EQ(lu.refinement_steps(), steps);
  EXPECT_LT(backward_error(s, x, b), 8 * 2.3e-16);
}

TEST(MixedPrecisionLU, ReportsASingularMatrix) {
  Eigen::MatrixXd s = with_condition(50, 2.0, 3);
  s.col(7) = 2.0 * s.col(3);
  s.col(7).head(10).setZero();
  s.row(20).setZero();
  MixedPrecisionLU lu;
  EXPECT_FALSE(lu.factorize(s));  // (s is swapped out)
}

}  // namespace
}  // namespace tirefem
