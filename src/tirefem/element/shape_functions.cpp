#include "tirefem/element/shape_functions.hpp"

#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace tirefem {

GaussRule gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("a Gauss rule needs at least one point");
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
  for (int k = 1; k < n; ++k) {
    const double b = k / std::sqrt(4.0 * k * k - 1.0);
    jacobi(k, k - 1) = jacobi(k - 1, k) = b;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(jacobi);
  GaussRule rule;
  for (int k = 0; k < n; ++k) {
    rule.points.push_back(eig.eigenvalues()[k]);
    rule.weights.push_back(2.0 * eig.eigenvectors()(0, k) * eig.eigenvectors()(0, k));
  }
  return rule;
}

}  // namespace tirefem
