#pragma once
// The lower triangle of a square sparse matrix's symmetric part ½(A + Aᵀ), refreshed from A's values. A's
// pattern is fixed (it is a tangent's): the map from each entry to a_ij and a_ji is found once.
#include <array>
#include <vector>

#include "tirefem/solver/sparse_system.hpp"

namespace tirefem {

class SymmetricPart {
 public:
  void update(const SparseMatrix& a);
  const SparseMatrix& lower() const { return lower_; }
  // For lower()'s k-th entry (row i ≥ column j): the positions of a_ij and a_ji in A's value array (−1
  // where A has no such entry).
  const std::vector<std::array<int, 2>>& sources() const { return sources_; }

 private:
  SparseMatrix lower_;
  std::vector<std::array<int, 2>> sources_;
};

// ½(a_ij − a_ji) of A's entry pair at `source`: A's antisymmetric part.
inline double antisymmetric_value(const double* a, const std::array<int, 2>& source) {
  return 0.5 * ((source[0] >= 0 ? a[source[0]] : 0.0) - (source[1] >= 0 ? a[source[1]] : 0.0));
}

}  // namespace tirefem
