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
  // GMRES's preconditioner: solve(), or with `single_precision` and a Cholesky factorisation or a
  // CholeskySchurLU held, the same solve with the Cholesky factor in single precision
  // (SinglePrecisionFactor: twice as fast, about 4e-7 relative off; for GMRES to a loose tolerance).
  Eigen::VectorXd precondition(const Eigen::VectorXd& rhs, bool single_precision);
  bool has_factorization() const;
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
  // `continue_unsymmetric`: an LU's GMRES solve whose true residual is too large goes on a few iterations
  // as a Cholesky's does (gmres_on_factorization), rather than being given up.
  bool solve_preconditioned(const SparseMatrix& matrix, const Eigen::VectorXd& rhs, Eigen::VectorXd& x,
                            double tolerance, int max_iterations, bool continue_unsymmetric = false);
  const LinearSolverStats& stats() const { return stats_; }

 private:
  void analyse_cholesky(const SparseMatrix& matrix);
  // factorize_lu's CholeskySchurLU attempt: after n failures in a row the next 2ⁿ − 1 LUs go to UMFPACK
  // straight away (n ≤ kMaxSchurBackoff).
  static constexpr int kMaxSchurBackoff = 4;
  bool factorize_schur(const SparseMatrix& matrix);  // once: the pattern never changes
  struct Impl;
  std::unique_ptr<Impl> impl_;
  LinearSolverStats stats_;
};

}  // namespace tirefem
