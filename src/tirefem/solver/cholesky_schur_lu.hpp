#pragma once
// Exact factorisation of a matrix that is symmetric but for a small block: a rolling tangent, which
// friction makes unsymmetric among the contact patch's equations only (MODEL.md §5; on the 80 × 46 full
// model 1 752 of 43 680). With U those equations (where a_ij ≠ a_ji beyond round-off), ordered last, and
// V the others,
//     A = [A_VV  A_VU]    A_VV symmetric positive definite, A_UV = A_VUᵀ.
//         [A_UV  A_UU]
// CHOLMOD's supernodal Cholesky of the symmetric M, equal to A but for M_UU = ½(A_UU + A_UUᵀ) + σ·diag|A_UU|
// (σ ≥ 1 keeps M positive definite), gives L_VV, L_UV and L_UU (L_UU L_UUᵀ = M_UU − L_UV L_UVᵀ), and
//     A = [L_VV 0; L_UV I] · [I 0; 0 S] · [L_VVᵀ L_UVᵀ; 0 I],    S = L_UU L_UUᵀ + A_UU − M_UU,
// with LAPACK's LU (partial pivoting) of the dense m × m Schur complement S, in single precision and refined
// to double accuracy in solve() (mixed_precision_lu.hpp). It replaces UMFPACK's LU
// (docs/studies/cholesky-schur-lu.md): on a 43 680-equation rolling tangent, standalone, 0.6 s + 0.16 s for
// S against UMFPACK's 1.9 s in the same process, a solve 24 ms against 40–240 ms, and GMRES on it runs
// in single precision (L_VV in floats). The price is fill: U last makes S dense and the border of the
// patch couples to all of it (18–71 GFlop per factorisation against 3.3 for UMFPACK, but at BLAS-3 speed).
// A_VV can be indefinite (a local buckling-like mode of the static part away from the patch, in hard
// cornering states): the region around CHOLMOD's failing column then joins U (up to three regions per
// factorisation), else the caller's UMFPACK serves.
#include <memory>

#include "tirefem/solver/sparse_system.hpp"

namespace tirefem {

class CholeskySchurLU {
 public:
  // The unsymmetric block is solved densely: beyond this many equations an LU of the whole is cheaper.
  static constexpr int kMaxUnsymmetricEquations = 3000;

  CholeskySchurLU();
  ~CholeskySchurLU();
  CholeskySchurLU(const CholeskySchurLU&) = delete;
  CholeskySchurLU& operator=(const CholeskySchurLU&) = delete;

  // Holds nothing unless `factorized`: `not_applicable` when A is symmetric or its unsymmetric block is
  // larger than kMaxUnsymmetricEquations (found without factorising), `failed` when A_VV is not positive
  // definite or S is singular. The symbolic analysis is redone when U changes (the fill-reducing ordering
  // of the whole pattern is found once).
  enum class Outcome { factorized, not_applicable, failed };
  Outcome factorize(const SparseMatrix& a);
  // x = A⁻¹ b with the factorisation held.
  Eigen::VectorXd solve(const Eigen::VectorXd& b);
  // The same with L_VV and S's LU in single precision (GMRES's preconditioner at loose tolerances).
  // (solve() refines S's single-precision LU to double accuracy: mixed_precision_lu.hpp.)
  Eigen::VectorXd solve_single_precision(const Eigen::VectorXd& b);

  int unsymmetric_equations() const;  // m, of the factorisation held
  double factor_flops() const;        // of it: CHOLMOD's count plus the dense S's
  int analyses() const;               // symbolic analyses so far

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tirefem
