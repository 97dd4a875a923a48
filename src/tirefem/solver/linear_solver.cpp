#include "tirefem/solver/linear_solver.hpp"

#include <chrono>
#include <stdexcept>

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

namespace tirefem {
namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

struct SparseDirectSolver::Impl {
  bool use_lu = false;
  bool cholesky_analysed = false;
  bool lu_analysed = false;
  bool lu_active = false;  // the last factorisation is the LU one
  int cholesky_failures = 0;
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> cholesky;
  Eigen::UmfPackLU<SparseMatrix> lu;
};

SparseDirectSolver::SparseDirectSolver(bool symmetric) : impl_(std::make_unique<Impl>()) {
  impl_->use_lu = !symmetric;
}

SparseDirectSolver::~SparseDirectSolver() = default;

void SparseDirectSolver::factorize(const SparseMatrix& matrix) {
  auto& s = *impl_;
  if (!s.use_lu) {
    if (!s.cholesky_analysed) {
      const auto t0 = std::chrono::steady_clock::now();
      s.cholesky.analyzePattern(matrix);
      s.cholesky_analysed = true;
      stats_.analysis_s += seconds_since(t0);
    }
    const auto t0 = std::chrono::steady_clock::now();
    s.cholesky.factorize(matrix);
    stats_.factorization_s += seconds_since(t0);
    ++stats_.factorizations;
    if (s.cholesky.info() == Eigen::Success) {
      s.cholesky_failures = 0;
      s.lu_active = false;
      return;
    }
    // Not positive definite: LU for this matrix; after two such matrices in a row, LU from now on.
    if (++s.cholesky_failures >= 2) s.use_lu = true;
  }
  if (!s.lu_analysed) {
    const auto t0 = std::chrono::steady_clock::now();
    s.lu.analyzePattern(matrix);
    s.lu_analysed = true;
    stats_.analysis_s += seconds_since(t0);
  }
  const auto t0 = std::chrono::steady_clock::now();
  s.lu.factorize(matrix);
  stats_.factorization_s += seconds_since(t0);
  ++stats_.factorizations;
  stats_.used_lu = true;
  s.lu_active = true;
  if (s.lu.info() != Eigen::Success) throw std::runtime_error("the tangent stiffness matrix is singular");
}

Eigen::VectorXd SparseDirectSolver::solve(const Eigen::VectorXd& rhs) {
  const auto t0 = std::chrono::steady_clock::now();
  Eigen::VectorXd x = impl_->lu_active ? Eigen::VectorXd(impl_->lu.solve(rhs))
                                    : Eigen::VectorXd(impl_->cholesky.solve(rhs));
  stats_.solve_s += seconds_since(t0);
  ++stats_.solves;
  return x;
}

}  // namespace tirefem
