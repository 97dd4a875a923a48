#pragma once
// A CHOLMOD supernodal Cholesky factor copied to single precision, for the triangular solves that
// precondition GMRES. A solve reads the whole factor twice and is bound by memory bandwidth: half the bytes
// make it about twice as fast (measured on the 80 × 46 full model's rolling tangent, 43 680 equations,
// 12.7 M entries in L, one thread: 15.3 → 8.0 ms; GMRES took the same iterations to 1e-3 and 1e-8).
// Its solution differs from the double one by about 4e-7 relative, and GMRES preconditioned by it reaches
// a true residual of only about 1e-4 relative: for inexact Newton steps, not for exact ones.
#include <cholmod.h>

#include <vector>

#include <Eigen/Core>

#include "tirefem/solver/supernodal_solve.hpp"

namespace tirefem {

class SinglePrecisionFactor {
 public:
  // Copies L, a supernodal LLᵀ factor of real entries with int indices; false (and empty) for any other.
  bool assign(const cholmod_factor& L);
  bool empty() const { return n_ == 0; }
  void clear() { n_ = 0; }
  // x = A⁻¹ b, where Pᵀ L Lᵀ P = A (P: L's fill-reducing permutation).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // The copy, for partial substitutions (CholeskySchurLU); valid while this object is unchanged.
  SupernodalFactorView<float> view() const;

 private:
  int n_ = 0;
  std::vector<int> permutation_, first_column_, row_start_, value_start_, rows_;  // first_column_: supernodes + 1
  std::vector<float> values_;
  mutable std::vector<float> work_, below_;  // the permuted vector; a supernode's rows below its diagonal block
};

}  // namespace tirefem
