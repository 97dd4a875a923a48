// Forward and back substitution over the leading columns of a CHOLMOD supernodal factor (the part
// CholeskySchurLU eliminates before its dense block): stopped inside a supernode, and completed by a
// dense solve of the trailing block, they must give CHOLMOD's own solution.
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>

#include "tirefem/solver/supernodal_solve.hpp"
#include "test_matrices.hpp"

namespace tirefem {
namespace {

class Factor : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  const cholmod_factor* factor() const { return m_cholmodFactor; }
};

TEST(SupernodalSolve, StoppedInsideASupernodeAndCompletedDenselyGivesCholmodsSolution) {
  const SparseMatrix a = scaled_grid_laplacian(40, 0.05, 1.0);
  Factor cholesky;
  cholesky.compute(a);
  ASSERT_EQ(cholesky.info(), Eigen::Success);
  const SupernodalFactorView<double> f = view_of(*cholesky.factor());
  ASSERT_GT(f.n, 0);
  // The last supernode of at least three columns, with rows below them: stop after its first column.
  int end = -1;
  for (int s = 0; s < f.supernodes; ++s)
    if (f.first_column[s + 1] - f.first_column[s] >= 3 && f.row_start[s + 1] - f.row_start[s] > 3 &&
        f.first_column[s] > 0)
      end = f.first_column[s] + 1;
  ASSERT_GT(end, 0);
  const int n = f.n, tail = n - end;
  // The trailing block of L, dense.
  Eigen::MatrixXd l22 = Eigen::MatrixXd::Zero(tail, tail);
  for (int s = 0; s < f.supernodes; ++s) {
    const int k1 = f.first_column[s], rows = f.row_start[s + 1] - f.row_start[s];
    for (int col = std::max(k1, end); col < f.first_column[s + 1]; ++col)
      for (int i = col - k1; i < rows; ++i)
        l22(f.rows[f.row_start[s] + i] - end, col - end) = f.values[f.value_start[s] + (col - k1) * rows + i];
  }
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 3.0);
  Eigen::VectorXd y(n);
  for (int k = 0; k < n; ++k) y[k] = b[f.permutation[k]];
  std::vector<double> below;  // grown by the substitutions as they need
  forward_substitute(f, y.data(), below, end);
  const Eigen::VectorXd z = l22.triangularView<Eigen::Lower>().solve(y.tail(tail));
  y.tail(tail) = l22.transpose().triangularView<Eigen::Upper>().solve(z);
  back_substitute(f, y.data(), below, end);
  Eigen::VectorXd x(n);
  for (int k = 0; k < n; ++k) x[f.permutation[k]] = y[k];
  const Eigen::VectorXd reference = cholesky.solve(b);
  EXPECT_LT((x - reference).norm(), 1e-12 * reference.norm());
}

}  // namespace
}  // namespace tirefem
