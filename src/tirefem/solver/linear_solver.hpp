#pragma once
// Sparse direct solver: CHOLMOD supernodal Cholesky for symmetric tangents (falls back to an LU if the
// matrix is not positive definite); for unsymmetric ones CholeskySchurLU when only a small block is
// unsymmetric (a rolling tangent), else UMFPACK's LU. The symbolic analysis is done on
// the first factorisation and reused, since the pattern never changes within a run.
#include <memory>
#include <optional>

#include "tirefem/solver/sparse_system.hpp"

namespace tirefem {

struct LinearSolverStats {
  int factorizations = 0;
  int solves = 0;
  int single_precision_solves = 0;  // of them, with the Cholesky factor in single precision (GMRES's)
  double factor_flops = 0.0;     // of one Cholesky factorisation, from the symbolic analysis
  double factor_nonzeros = 0.0;  // in its factor L
  double analysis_s = 0.0;
  double factorization_s = 0.0;
  double solve_s = 0.0;
  bool used_lu = false;
  int shifted_factorizations = 0;  // Cholesky of an indefinite matrix with a diagonal shift
  int failed_cholesky = 0;         // attempts that found the matrix not positive definite (counted in
                                   // factorizations too: they cost nearly as much)
  int symmetric_part_factorizations = 0;  // Cholesky of ½(A + Aᵀ) for GMRES on an unsymmetric A
  // LUs of a matrix unsymmetric in a small block only, by CholeskySchurLU instead of UMFPACK (counted in
  // factorizations): made, attempts that found its symmetric rest indefinite (UMFPACK then), symbolic
  // analyses; the flops of the last and its unsymmetric block's size.
  int schur_factorizations = 0;
  int failed_schur = 0;
  int schur_analyses = 0;
  double schur_flops = 0.0;
  int schur_block = 0;
  int krylov_solves = 0;      // successful preconditioned GMRES solves (a factorisation reused)
  int krylov_failures = 0;    // GMRES solves given up (followed by a new factorisation)
  int krylov_iterations = 0;  // over all of them
  double krylov_s = 0.0;
};

class SparseDirectSolver {
 public:
  // factorize(): after two symmetric matrices in a row that are not positive definite, LU for all later
  // ones (saves the failed Cholesky attempts when the problem stays indefinite).
  explicit SparseDirectSolver(bool symmetric);
  ~SparseDirectSolver();
  SparseDirectSolver(const SparseDirectSolver&) = delete;
  SparseDirectSolver& operator=(const SparseDirectSolver&) = delete;

  // Throws std::runtime_error if the matrix is singular.
  void factorize(const SparseMatrix& matrix);
  // An LU factorisation whatever the matrix (solve() then uses it): CholeskySchurLU's when the matrix is
  // unsymmetric in a small block only, else UMFPACK's. Throws if the matrix is singular.
  void factorize_lu(const SparseMatrix& matrix);
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs);
  // GMRES's preconditioner: solve(), or with `single_precision` and a Cholesky factorisation held, the
  // same solve with that factor in single precision (SinglePrecisionFactor: twice as fast, about 4e-7
  // relative off; for GMRES to a loose tolerance).
  Eigen::VectorXd precondition(const Eigen::VectorXd& rhs, bool single_precision);
  bool has_factorization() const;
  // The factorisation held is solve_by_symmetric_part's (of an unsymmetric matrix's symmetric part).
  bool holds_symmetric_part() const;
  // The GMRES iterations of the solve that made that factorisation (0 when another one is held).
  int symmetric_part_iterations() const;
  // True when every factorisation is an LU (an unsymmetric problem, or a sticky switch after indefinite ones).
  bool uses_lu() const;
  // The relative shift σ of the Cholesky factorisation solve() uses (0: of A itself); < 0 when solve()
  // uses an LU or nothing.
  double held_cholesky_shift() const;

  // Inertia correction (symmetric A): a Cholesky factorisation of A + σ·diag|A| with the smallest σ of
  // 0, 1e-6, 1e-5, … that makes it positive definite (starting near the last σ that worked, since
  // consecutive tangents are alike). Returns σ: 0 when A itself is positive definite; σ > 0 marks an
  // indefinite A, and solve() then gives a step that descends the energy (MODEL.md §8). Throws when even
  // σ = 1e4 fails. `first_shift`: the first σ tried, whatever the last σ was (0: to tell whether A is
  // stable; kFirstShift when σ = 0 has just failed on this A).
  static constexpr double kFirstShift = 1e-6;
  double factorize_inertia_corrected(const SparseMatrix& matrix, std::optional<double> first_shift = {});
  // One Cholesky attempt of A + σ·diag|A| (σ = relative_shift ≥ 0): false when that is not positive
  // definite (then there is no usable factorisation).
  bool factorize_cholesky(const SparseMatrix& matrix, double relative_shift = 0.0);


  // Solves A x = b by GMRES preconditioned with the last factorisation (of an earlier, nearby matrix):
  // the iteration that lets load steps reuse a factorisation. Returns false (x undefined) when the
  // preconditioned residual does not fall below `tolerance` × its initial value within max_iterations.
  bool solve_preconditioned(const SparseMatrix& matrix, const Eigen::VectorXd& rhs, Eigen::VectorXd& x,
                            double tolerance, int max_iterations);
  // Unsymmetric A (a rolling tangent: friction makes it unsymmetric in the patch only): GMRES on A
  // preconditioned by a new Cholesky factorisation of its symmetric part ½(A + Aᵀ), shifted by at most
  // kMaxSymmetricPartShift if that is indefinite; it stays held for later preconditioned solves. Both the
  // factorisation and its solves are cheaper than UMFPACK's: on the 80 × 46 full model (43 680 equations)
  // 0.9 s and 35 ms against 1.8 s and 230 ms, and GMRES reaches 1e-8 in 9 iterations at α = 2°.
  // False (x undefined) when the symmetric part needs a larger shift or GMRES does not converge within
  // max_iterations: the caller's LU serves then. After n such failures in a row the next 2ⁿ − 1 calls
  // return false at once (n ≤ kMaxSymmetricPartBackoff).
  static constexpr int kMaxSymmetricPartBackoff = 4;
  static constexpr double kMaxSymmetricPartShift = 1e-4;
  bool solve_by_symmetric_part(const SparseMatrix& matrix, const Eigen::VectorXd& rhs, Eigen::VectorXd& x,
                               double tolerance, int max_iterations);
  const LinearSolverStats& stats() const { return stats_; }

 private:
  void analyse_cholesky(const SparseMatrix& matrix);
  bool factorize_schur(const SparseMatrix& matrix);  // once: the pattern never changes
  struct Impl;
  std::unique_ptr<Impl> impl_;
  LinearSolverStats stats_;
};

}  // namespace tirefem
