#pragma once
// Sparse direct solver: CHOLMOD supernodal Cholesky for symmetric tangents (falls back to UMFPACK LU if
// the matrix is not positive definite), UMFPACK for unsymmetric ones. The symbolic analysis is done on
// the first factorisation and reused, since the pattern never changes within a run.
#include <memory>

#include "tirefem/solver/sparse_system.hpp"

namespace tirefem {

struct LinearSolverStats {
  int factorizations = 0;
  int solves = 0;
  double analysis_s = 0.0;
  double factorization_s = 0.0;
  double solve_s = 0.0;
  bool used_lu = false;
};

class SparseDirectSolver {
 public:
  explicit SparseDirectSolver(bool symmetric);
  ~SparseDirectSolver();
  SparseDirectSolver(const SparseDirectSolver&) = delete;
  SparseDirectSolver& operator=(const SparseDirectSolver&) = delete;

  // Throws std::runtime_error if the matrix is singular.
  void factorize(const SparseMatrix& matrix);
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs);
  const LinearSolverStats& stats() const { return stats_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  LinearSolverStats stats_;
};

}  // namespace tirefem
