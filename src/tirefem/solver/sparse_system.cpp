#include "tirefem/solver/sparse_system.hpp"

#include <stdexcept>

#include <algorithm>

namespace tirefem {

SparseMatrix PatternBuilder::build(const DofMap& dofs) const {
  const int n = dofs.equation_count();
  std::vector<std::vector<int>> rows_of_column(n);
  for (const auto& block : blocks_) {
    for (int dj : block) {
      const int j = dofs.equation(dj);
      if (j < 0) continue;
      for (int di : block) {
        const int i = dofs.equation(di);
        if (i >= 0) rows_of_column[j].push_back(i);
      }
    }
  }
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j) {
    auto& rows = rows_of_column[j];
    rows.push_back(j);  // keep the diagonal even for a DOF no block touches
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (int i : rows) entries.emplace_back(i, j, 0.0);
  }
  SparseMatrix m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  m.makeCompressed();
  return m;
}

SparseSystem::SparseSystem(const DofMap& dofs, SparseMatrix pattern)
    : dofs_(dofs), residual_(Eigen::VectorXd::Zero(dofs.dof_count())), tangent_(std::move(pattern)) {}

void SparseSystem::clear(bool with_tangent) {
  residual_.setZero();
  if (with_tangent) std::fill_n(tangent_.valuePtr(), tangent_.nonZeros(), 0.0);
}

void SparseSystem::add_residual(int dof, double value) {
#pragma omp atomic
  residual_[dof] += value;
}

void SparseSystem::add_matrix(const SparseMatrix& m) {
  if (m.nonZeros() != tangent_.nonZeros() || m.outerSize() != tangent_.outerSize() ||
      !std::equal(m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros(), tangent_.innerIndexPtr()))
    throw std::invalid_argument("add_matrix: the matrix does not have the system's sparsity pattern");
  Eigen::Map<Eigen::VectorXd>(tangent_.valuePtr(), tangent_.nonZeros()) +=
      Eigen::Map<const Eigen::VectorXd>(m.valuePtr(), m.nonZeros());
}

void SparseSystem::add(std::span<const int> dofs, const double* f, const double* k, bool with_tangent) {
  const int n = static_cast<int>(dofs.size());
  for (int a = 0; a < n; ++a) {
#pragma omp atomic
    residual_[dofs[a]] += f[a];
  }
  if (!with_tangent) return;
  const int* outer = tangent_.outerIndexPtr();
  const int* inner = tangent_.innerIndexPtr();
  double* values = tangent_.valuePtr();
  for (int b = 0; b < n; ++b) {
    const int col = dofs_.equation(dofs[b]);
    if (col < 0) continue;
    const int* begin = inner + outer[col];
    const int* end = inner + outer[col + 1];
    for (int a = 0; a < n; ++a) {
      const int row = dofs_.equation(dofs[a]);
      if (row < 0) continue;
      const double v = k[a + b * n];
      if (v == 0.0) continue;
      const int* pos = std::lower_bound(begin, end, row);
#pragma omp atomic
      values[pos - inner] += v;
    }
  }
}

}  // namespace tirefem
