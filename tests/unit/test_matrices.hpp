#pragma once
// Sparse test matrices for the linear solvers' unit tests.
#include <cmath>
#include <utility>
#include <vector>

#include "tirefem/solver/sparse_system.hpp"

namespace tirefem {

// The 5-point Laplacian of an m × m grid plus `shift` on the diagonal, each row and column scaled by
// `scale`(i) (a symmetric positive definite matrix with supernodes, a fill-reducing permutation and, with
// a scale varying over decades, entries of very different sizes, as the shell's bending and membrane ones).
inline SparseMatrix scaled_grid_laplacian(int m, double shift, double decades) {
  const int n = m * m;
  const auto scale = [&](int i) { return std::pow(10.0, decades * i / (n - 1.0)); };
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int k = i * m + j;
      t.emplace_back(k, k, (4.0 + shift) * scale(k) * scale(k));
      for (const auto [di, dj] : {std::pair{1, 0}, std::pair{0, 1}})
        if (i + di < m && j + dj < m) {
          const int l = (i + di) * m + j + dj;
          t.emplace_back(k, l, -scale(k) * scale(l));
          t.emplace_back(l, k, -scale(k) * scale(l));
        }
    }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

}  // namespace tirefem
