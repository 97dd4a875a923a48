#include "tirefem/solver/linear_solver.hpp"

#include "tirefem/solver/blas_kernel.hpp"
#include "tirefem/solver/cholesky_schur_lu.hpp"
#include "tirefem/solver/cholmod_setup.hpp"
#include "tirefem/solver/single_precision_factor.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>
#include <unsupported/Eigen/IterativeSolvers>

namespace tirefem {
namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Eigen's CHOLMOD supernodal Cholesky with its factor readable (for SinglePrecisionFactor).
class CholeskyFactor : public Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
 public:
  const cholmod_factor* factor() const { return m_cholmodFactor; }
};

// GMRES to at least this (relative) tolerance is preconditioned by the Cholesky factor in single precision.
constexpr double kSinglePrecisionTolerance = 1e-4;
}  // namespace

struct SparseDirectSolver::Impl {
  bool symmetric = false;
  bool use_lu = false;
  bool cholesky_analysed = false;
  bool lu_analysed = false;
  bool lu_active = false;  // the last factorisation is the LU one (UMFPACK's, or schur's when schur_active)
  bool schur_active = false;
  int schur_failures = 0;  // in a row
  int schur_skips = 0;     // factorize_lu calls left to go to UMFPACK straight away
  double cholesky_shift = -1.0;  // relative shift of the Cholesky factorisation held; < 0: none held
  bool factorized = false;
  int cholesky_failures = 0;
  double last_relative_shift = 0.0;  // of factorize_inertia_corrected
  std::vector<int> diagonal_index;   // position of each diagonal entry in the matrix's value array
  SparseMatrix shifted;
  CholeskyFactor cholesky;
  SinglePrecisionFactor single;  // of the Cholesky factor held, made when first needed
  bool single_current = false;
  Eigen::UmfPackLU<SparseMatrix> lu;
  CholeskySchurLU schur;  // the LU of a matrix unsymmetric in a small block only
};

SparseDirectSolver::SparseDirectSolver(bool symmetric) : impl_(std::make_unique<Impl>()) {
  // "Not positive definite" is an answer here (inertia correction, LU fallback), not a warning to print.
  impl_->cholesky.cholmod().print = 0;
  impl_->symmetric = symmetric;
  impl_->use_lu = !symmetric;
}

SparseDirectSolver::~SparseDirectSolver() = default;

void SparseDirectSolver::analyse_cholesky(const SparseMatrix& matrix) {
  auto& s = *impl_;
  if (s.cholesky_analysed) return;
  const auto t0 = std::chrono::steady_clock::now();
  cholmod_common& common = s.cholesky.cholmod();
  use_tyre_factor_settings(common);
  {
    const std::lock_guard lock(ordering_mutex());
    s.cholesky.analyzePattern(matrix);
  }
  s.cholesky_analysed = true;
  stats_.factor_flops = common.fl;
  stats_.factor_nonzeros = common.lnz;
  stats_.analysis_s += seconds_since(t0);
}

void SparseDirectSolver::factorize(const SparseMatrix& matrix) {
  auto& s = *impl_;
  if (!s.use_lu) {
    analyse_cholesky(matrix);
    const auto t0 = std::chrono::steady_clock::now();
    s.cholesky.factorize(matrix);
    stats_.factorization_s += seconds_since(t0);
    ++stats_.factorizations;
    s.single_current = false;
    if (s.cholesky.info() == Eigen::Success) {
      s.cholesky_failures = 0;
      s.lu_active = false;
      s.schur_active = false;
      s.factorized = true;
      s.cholesky_shift = 0.0;
      return;
    }
    // Not positive definite: LU for this matrix; after two such matrices in a row, LU from now on.
    ++stats_.failed_cholesky;
    if (++s.cholesky_failures >= 2) s.use_lu = true;
  }
  factorize_lu(matrix);
}

void SparseDirectSolver::factorize_lu(const SparseMatrix& matrix) {
  auto& s = *impl_;
  s.schur_active = false;
  if (!s.symmetric && factorize_schur(matrix)) return;
  if (!s.lu_analysed) {
    // No iterative refinement in UMFPACK's solve: it triples the cost of each solve, and Newton (or
    // GMRES around a reused factorisation) corrects the residual anyway.
    s.lu.umfpackControl()(UMFPACK_IRSTEP) = 0;
    // Nested dissection (METIS on A + Aᵀ) rather than the default AMD: the rolling tangent of the 80 × 46
    // model takes 3.25 instead of 3.77 GFlop per LU (UMFPACK's own count, −14%).
    s.lu.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
    const auto t0 = std::chrono::steady_clock::now();
    {
      const std::lock_guard lock(ordering_mutex());
      s.lu.analyzePattern(matrix);
    }
    s.lu_analysed = true;
    stats_.analysis_s += seconds_since(t0);
  }
  const auto t0 = std::chrono::steady_clock::now();
  s.lu.factorize(matrix);
  stats_.factorization_s += seconds_since(t0);
  ++stats_.factorizations;
  stats_.used_lu = true;
  s.lu_active = true;
  s.cholesky_shift = -1.0;
  s.factorized = s.lu.info() == Eigen::Success;
  if (s.lu.info() != Eigen::Success) throw std::runtime_error("the tangent stiffness matrix is singular");
}

bool SparseDirectSolver::factorize_schur(const SparseMatrix& matrix) {
  auto& s = *impl_;
  // After n failures in a row (A_VV indefinite: an iterate far from a stable state), the next 2ⁿ − 1
  // LUs go to UMFPACK straight away; a success resets n.
  if (s.schur_skips > 0) {
    --s.schur_skips;
    return false;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const int analyses = s.schur.analyses();
  const CholeskySchurLU::Outcome outcome = s.schur.factorize(matrix);
  if (outcome == CholeskySchurLU::Outcome::not_applicable) return false;
  stats_.factorization_s += seconds_since(t0);
  stats_.schur_analyses += s.schur.analyses() - analyses;
  ++stats_.factorizations;
  if (outcome == CholeskySchurLU::Outcome::failed) {
    ++stats_.failed_schur;
    s.schur_failures = std::min(s.schur_failures + 1, kMaxSchurBackoff);
    s.schur_skips = (1 << s.schur_failures) - 1;
    return false;
  }
  s.schur_failures = 0;
  ++stats_.schur_factorizations;
  stats_.schur_flops = s.schur.factor_flops();
  stats_.schur_block = s.schur.unsymmetric_equations();
  stats_.used_lu = true;
  s.lu_active = true;
  s.schur_active = true;
  s.cholesky_shift = -1.0;
  s.factorized = true;
  return true;
}

Eigen::VectorXd SparseDirectSolver::solve(const Eigen::VectorXd& rhs) {
  const auto t0 = std::chrono::steady_clock::now();
  // One BLAS thread: measured with the load curve of the example (120 × 46 half model, 2 cores), a
  // CHOLMOD solve took 10 ms on one thread against 16 ms on two (the factorisations as fast on either).
  const SingleBlasThread one_thread;
  auto& s = *impl_;
  Eigen::VectorXd x = s.schur_active ? s.schur.solve(rhs)
                      : s.lu_active  ? Eigen::VectorXd(s.lu.solve(rhs))
                                     : Eigen::VectorXd(s.cholesky.solve(rhs));
  stats_.solve_s += seconds_since(t0);
  ++stats_.solves;
  return x;
}

Eigen::VectorXd SparseDirectSolver::precondition(const Eigen::VectorXd& rhs, bool single_precision) {
  auto& s = *impl_;
  if (!single_precision || (s.lu_active && !s.schur_active)) return solve(rhs);
  const auto t0 = std::chrono::steady_clock::now();
  const SingleBlasThread one_thread;
  if (s.schur_active) {
    Eigen::VectorXd x = s.schur.solve_single_precision(rhs);
    stats_.solve_s += seconds_since(t0);
    ++stats_.solves;
    ++stats_.single_precision_solves;
    return x;
  }
  if (!s.single_current) {
    s.single_current = true;
    if (const cholmod_factor* factor = s.cholesky.factor()) s.single.assign(*factor);  // empty if not supernodal
    else s.single.clear();
  }
  if (s.single.empty()) return solve(rhs);
  Eigen::VectorXd x = s.single.solve(rhs);
  stats_.solve_s += seconds_since(t0);
  ++stats_.solves;
  ++stats_.single_precision_solves;
  return x;
}

bool SparseDirectSolver::has_factorization() const { return impl_->factorized; }
bool SparseDirectSolver::uses_lu() const { return impl_->use_lu; }
double SparseDirectSolver::held_cholesky_shift() const { return impl_->cholesky_shift; }

bool SparseDirectSolver::factorize_cholesky(const SparseMatrix& matrix, double relative_shift) {
  auto& s = *impl_;
  analyse_cholesky(matrix);
  const SparseMatrix* factored = &matrix;
  if (relative_shift > 0) {
    const int n = static_cast<int>(matrix.cols());
    if (static_cast<int>(s.diagonal_index.size()) != n || s.shifted.nonZeros() != matrix.nonZeros()) {
      s.diagonal_index.assign(n, -1);
      for (int j = 0; j < n; ++j)
        for (int k = matrix.outerIndexPtr()[j]; k < matrix.outerIndexPtr()[j + 1]; ++k)
          if (matrix.innerIndexPtr()[k] == j) s.diagonal_index[j] = k;
      s.shifted = matrix;
    }
    const double* a = matrix.valuePtr();
    std::copy(a, a + matrix.nonZeros(), s.shifted.valuePtr());
    // A DOF without any stiffness of its own still gets a shift, relative to the matrix's scale.
    const double floor = 1e-8 * matrix.diagonal().cwiseAbs().mean();
    for (int j = 0; j < n; ++j) {
      const int k = s.diagonal_index[j];
      if (k >= 0) s.shifted.valuePtr()[k] += relative_shift * std::max(std::abs(a[k]), floor);
    }
    factored = &s.shifted;
  }
  const auto t0 = std::chrono::steady_clock::now();
  s.cholesky.factorize(*factored);
  s.single_current = false;
  stats_.factorization_s += seconds_since(t0);
  ++stats_.factorizations;
  if (s.cholesky.info() != Eigen::Success) {
    ++stats_.failed_cholesky;
    s.factorized = s.lu_active;  // only an earlier LU is left to solve with
    s.cholesky_shift = -1.0;
    return false;
  }
  if (relative_shift > 0) ++stats_.shifted_factorizations;
  s.factorized = true;
  s.lu_active = false;
  s.schur_active = false;
  s.cholesky_shift = relative_shift;
  return true;
}

double SparseDirectSolver::factorize_inertia_corrected(const SparseMatrix& matrix,
                                                       std::optional<double> first_shift) {
  auto& s = *impl_;
  constexpr double kGrowth = 10.0, kLargestShift = 1e4;
  // Start one decade below the last shift that worked (or at 0): the tangent along a path changes slowly.
  double shift = first_shift ? *first_shift
                 : s.last_relative_shift > 10 * kFirstShift ? s.last_relative_shift / kGrowth
                                                              : 0.0;
  while (!factorize_cholesky(matrix, shift)) {
    shift = shift == 0.0 ? kFirstShift : kGrowth * shift;
    if (shift > kLargestShift) throw std::runtime_error("no shift makes the tangent positive definite");
  }
  s.last_relative_shift = shift;
  return shift;
}

namespace {
constexpr double kMaxTrueResidual = 0.1;  // of a preconditioned GMRES solution, relative to the rhs
constexpr int kMaxContinuedIterations = 4;  // see gmres_on_factorization

// Eigen preconditioner interface over a factorisation made elsewhere: compute() does nothing.
class FactorizationPreconditioner {
 public:
  FactorizationPreconditioner() = default;
  void bind(SparseDirectSolver* solver, bool single_precision) {
    solver_ = solver;
    single_precision_ = single_precision;
  }
  template <class M>
  FactorizationPreconditioner& analyzePattern(const M&) { return *this; }
  template <class M>
  FactorizationPreconditioner& factorize(const M&) { return *this; }
  template <class M>
  FactorizationPreconditioner& compute(const M&) { return *this; }
  template <class Rhs>
  Eigen::VectorXd solve(const Rhs& b) const { return solver_->precondition(Eigen::VectorXd(b), single_precision_); }
  Eigen::ComputationInfo info() { return Eigen::Success; }

 private:
  SparseDirectSolver* solver_ = nullptr;
  bool single_precision_ = false;
};
}  // namespace

namespace {
// Matrix: the sparse type GMRES works on; Operand: it or a Map of one (bound without a copy).
template <class Matrix, class Operand>
bool gmres_on_factorization(const Operand& matrix, SparseDirectSolver* solver, const Eigen::VectorXd& rhs,
                            Eigen::VectorXd& x, double tolerance, int max_iterations, int& iterations,
                            bool continue_on_true_residual) {
  Eigen::GMRES<Matrix, FactorizationPreconditioner> gmres;
  gmres.compute(matrix);
  // `relative` to the preconditioned residual at the start (x); `level` that tolerance relative to the
  // rhs's, which decides whether the single-precision factor serves.
  const auto run = [&](double relative, double level, int limit) {
    gmres.preconditioner().bind(solver, level >= kSinglePrecisionTolerance);
    gmres.set_restart(limit);
    gmres.setMaxIterations(limit);
    gmres.setTolerance(relative);
    const Eigen::VectorXd start = x;
    x = gmres.solveWithGuess(rhs, start);
    iterations += static_cast<int>(gmres.iterations());
    return gmres.info() == Eigen::Success && x.allFinite();
  };
  x = Eigen::VectorXd::Zero(rhs.size());
  iterations = 0;
  if (!run(tolerance, tolerance, max_iterations)) return false;
  // GMRES measures the preconditioned residual; a preconditioner from a very different matrix can make
  // that small while the true one is not: accept a step only if it also reduces the true residual well.
  const double true_ratio = (rhs - matrix * x).norm() / rhs.norm();
  if (true_ratio <= kMaxTrueResidual) return true;
  if (!continue_on_true_residual) return false;
  // For a symmetric problem (a Cholesky factorisation, or an LU of an indefinite tangent) GMRES goes on
  // from x, a few iterations at most, to cut its preconditioned residual (its tolerance is relative to the
  // one at its start) by as much as the true one is too large, with a margin, before the caller
  // refactorises. Measured on the load-curve bench (120 × 46 half, 20 points): 33 → 24 factorisations,
  // 116 → 118 assemblies, 246 → 314 GMRES iterations, 22.1–23.1 → 21.7–21.8 s (two alternating runs
  // each). Not on a rolling LU: there a fresh LU's exact step is worth its cost. With the continuation (up
  // to 25 iterations), the cornering bench's α = 2° state took 2 LUs instead of 3 (6.4 → 5.6 s), but the
  // 80 × 46 rig's 5550 N longitudinal series 59 → 113 s (κ −0.11: 28 → 100 Newton iterations), and with
  // at most 4 iterations 72 s: the inexact steps derail Newton in its hard, nonsmooth states. Near a
  // Newton solve's end (`continue_unsymmetric`: NewtonSettings::keep_lu_below_residual) it does not.
  const int left = std::min(max_iterations - iterations, kMaxContinuedIterations);
  if (left <= 0 || !(true_ratio < 1.0)) return false;
  const double reduction = 0.5 * kMaxTrueResidual / true_ratio;
  if (!run(reduction, gmres.error() * reduction, left)) return false;
  return (rhs - matrix * x).norm() <= kMaxTrueResidual * rhs.norm();
}
}  // namespace

bool SparseDirectSolver::solve_preconditioned(const SparseMatrix& matrix, const Eigen::VectorXd& rhs,
                                              Eigen::VectorXd& x, double tolerance, int max_iterations,
                                              bool continue_unsymmetric) {
  if (!has_factorization()) return false;
  const auto t0 = std::chrono::steady_clock::now();
  int iterations = 0;
  bool ok = false;
  if (impl_->symmetric) {
    // A symmetric matrix's column-major arrays are also its row-major ones, and Eigen's row-major
    // sparse × vector product runs on the OpenMP threads (the column-major one on one thread).
    using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
    const Eigen::Map<const RowMajorMatrix> rows(matrix.rows(), matrix.cols(), matrix.nonZeros(),
                                                matrix.outerIndexPtr(), matrix.innerIndexPtr(),
                                                matrix.valuePtr());
    ok = gmres_on_factorization<RowMajorMatrix>(rows, this, rhs, x, tolerance, max_iterations, iterations, true);
  } else {
    ok = gmres_on_factorization<SparseMatrix>(matrix, this, rhs, x, tolerance, max_iterations, iterations,
                                              continue_unsymmetric);
  }
  stats_.krylov_iterations += iterations;
  ++(ok ? stats_.krylov_solves : stats_.krylov_failures);
  stats_.krylov_s += seconds_since(t0);
  return ok;
}

}  // namespace tirefem
