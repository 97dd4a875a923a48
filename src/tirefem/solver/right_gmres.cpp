#include "tirefem/solver/right_gmres.hpp"

#include <cmath>
#include <vector>

#include <Eigen/Dense>

namespace tirefem {

RightGmresResult right_gmres(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                             const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& precondition,
                             double tolerance, int max_iterations, Eigen::VectorXd& x) {
  RightGmresResult out;
  const Eigen::Index n = b.size();
  const int m = std::max(max_iterations, 1);
  x = Eigen::VectorXd::Zero(n);
  const double beta = b.norm();
  if (beta == 0.0 || !std::isfinite(beta)) {
    out.converged = beta == 0.0;
    out.relative_residual = beta == 0.0 ? 0.0 : beta;
    return out;
  }
  Eigen::MatrixXd v(n, m + 1), z(n, m);  // Arnoldi basis, and P⁻¹ of each of its vectors
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, m);
  Eigen::VectorXd cs(m), sn(m), g = Eigen::VectorXd::Zero(m + 1);
  v.col(0) = b / beta;
  g[0] = beta;
  int k = 0;
  for (; k < m; ++k) {
    z.col(k) = precondition(v.col(k));
    Eigen::VectorXd w = a * z.col(k);
    // Modified Gram–Schmidt, twice (a few dozen vectors: the second pass costs little and keeps the
    // basis orthogonal to round-off, so the residual estimate stays the true one).
    for (int pass = 0; pass < 2; ++pass)
      for (int i = 0; i <= k; ++i) {
        const double hik = v.col(i).dot(w);
        h(i, k) += hik;
        w -= hik * v.col(i);
      }
    h(k + 1, k) = w.norm();
    if (!std::isfinite(h(k + 1, k))) return out;
    if (h(k + 1, k) > 0) v.col(k + 1) = w / h(k + 1, k);
    for (int i = 0; i < k; ++i) {  // earlier Givens rotations on the new column
      const double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
      h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
      h(i, k) = t;
    }
    const double r = std::hypot(h(k, k), h(k + 1, k));
    cs[k] = r > 0 ? h(k, k) / r : 1.0;
    sn[k] = r > 0 ? h(k + 1, k) / r : 0.0;
    h(k, k) = r;
    h(k + 1, k) = 0.0;
    g[k + 1] = -sn[k] * g[k];
    g[k] = cs[k] * g[k];
    out.relative_residual = std::abs(g[k + 1]) / beta;
    if (out.relative_residual <= tolerance) {
      ++k;
      break;
    }
  }
  out.iterations = k;
  if (out.relative_residual > tolerance) return out;
  const Eigen::VectorXd y =
      h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  x = z.leftCols(k) * y;
  out.converged = x.allFinite();
  return out;
}

}  // namespace tirefem
