#pragma once
// Dense LU of a general m × m matrix for repeated solves: LAPACK's LU with partial pivoting in single
// precision (twice the double one's speed: 0.16 against 0.31 s at m = 2 710 on one core, Haswell kernel),
// and solves to double accuracy by iterative refinement with the matrix kept in double. Where refinement
// stalls (a matrix too ill-conditioned for floats) or the single-precision LU is singular, the double LU is
// made and serves from then on. The Schur complement of the rolling tangent's patch (cholesky_schur_lu.hpp)
// is such a matrix.
#include <vector>

#include <Eigen/Core>

namespace tirefem {

class MixedPrecisionLU {
 public:
  // Takes the matrix by swapping it in (the caller gets the previous one's storage back to fill again).
  // False if it is singular in double precision too.
  bool factorize(Eigen::MatrixXd& matrix);
  // y ← S⁻¹ y to the backward error of a double-precision LU solve.
  void solve(double* y);
  // y ← S⁻¹ y with the single-precision factors alone (a preconditioner's accuracy).
  void solve_single_precision(float* y) const;

  int size() const { return static_cast<int>(matrix_.rows()); }
  bool double_factors() const { return use_double_; }  // the double LU serves
  int refinement_steps() const { return refinement_steps_; }  // in all solves since factorize

 private:
  bool factorize_double();
  Eigen::MatrixXd matrix_;       // S, kept for the refinement's residuals
  Eigen::MatrixXf single_;       // its LU factors in single precision
  Eigen::MatrixXd double_;       // its LU factors in double, made when needed
  std::vector<int> pivots_, double_pivots_;
  double norm_ = 0.0;            // ‖S‖∞
  bool use_double_ = false;
  int refinement_steps_ = 0;
  Eigen::VectorXd x_, r_;
  Eigen::VectorXf c_;
};

}  // namespace tirefem
