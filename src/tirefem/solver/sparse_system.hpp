#pragma once
// Residual and tangent of a nonlinear problem assembled into a sparsity pattern fixed once, so the
// symbolic analysis of the sparse factorisation is done once per run. Element blocks are added from
// parallel loops (atomic adds).
#include <span>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "tirefem/solver/dof_map.hpp"

namespace tirefem {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// Collects the DOF blocks that forms couple, then builds the pattern over the equations.
class PatternBuilder {
 public:
  void add_block(std::span<const int> dofs) { blocks_.emplace_back(dofs.begin(), dofs.end()); }
  SparseMatrix build(const DofMap& dofs) const;

 private:
  std::vector<std::vector<int>> blocks_;
};

class SparseSystem {
 public:
  SparseSystem(const DofMap& dofs, SparseMatrix pattern);

  void clear(bool with_tangent);
  // Adds an element block: residual[d] += f, tangent[eq(d_i), eq(d_j)] += k(i, j). Thread-safe.
  void add(std::span<const int> dofs, const double* f, const double* k_col_major, bool with_tangent);
  template <class Vec, class Mat>
  void add(std::span<const int> dofs, const Vec& f, const Mat& k, bool with_tangent) {
    add(dofs, f.data(), k.data(), with_tangent);
  }
  void add_residual(int dof, double value);
  // Adds a whole matrix over the equations with the system's own pattern (e.g. a stored tangent of this
  // system). Not thread-safe: call it outside parallel loops. Throws if the pattern differs.
  void add_matrix(const SparseMatrix& matrix);

  const Eigen::VectorXd& residual() const { return residual_; }  // full length, incl. reactions
  const SparseMatrix& tangent() const { return tangent_; }        // equations × equations
  const DofMap& dofs() const { return dofs_; }

 private:
  const DofMap& dofs_;
  Eigen::VectorXd residual_;
  SparseMatrix tangent_;
};

}  // namespace tirefem
