#pragma once
// GMRES preconditioned on the right: it minimises the TRUE residual ‖b − A x‖ over x = x₀ + P⁻¹·K, so its
// stopping test is on the residual Newton sees. Eigen's GMRES preconditions on the left and measures
// ‖P⁻¹(b − A x)‖, which a preconditioner from another matrix (the factorisation of the previous load
// point, without the new contact springs) can make small while the true residual is 0.1–0.4.
#include <functional>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace tirefem {

struct RightGmresResult {
  bool converged = false;
  int iterations = 0;               // preconditioner applications = products with A
  double relative_residual = 1.0;   // ‖b − A x‖ / ‖b‖ as GMRES estimates it
};

// Solves A x = b from x = 0 without restarts (max_iterations is small: a few dozen), storing the
// preconditioned vectors (flexible-GMRES storage), so x needs no extra preconditioner application.
// Stops when the residual is ≤ tolerance · ‖b‖ (converged) or after max_iterations (not converged).
RightGmresResult right_gmres(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                             const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& precondition,
                             double tolerance, int max_iterations, Eigen::VectorXd& x);

}  // namespace tirefem
