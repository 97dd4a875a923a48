#include "tirefem/solver/sparse_system.hpp"

#include <stdexcept>

#include <omp.h>

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

void SparseSystem::add_residual(int dof, double value) { residual_[dof] += value; }

void SparseSystem::add_matrix(const SparseMatrix& m) {
  if (m.nonZeros() != tangent_.nonZeros() || m.outerSize() != tangent_.outerSize() ||
      !std::equal(m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros(), tangent_.innerIndexPtr()))
    throw std::invalid_argument("add_matrix: the matrix does not have the system's sparsity pattern");
  Eigen::Map<Eigen::VectorXd>(tangent_.valuePtr(), tangent_.nonZeros()) +=
      Eigen::Map<const Eigen::VectorXd>(m.valuePtr(), m.nonZeros());
}

void BlockBatch::reset(int items) {
  slots_.resize(items);
  for (Slot& s : slots_) s.n = 0;
}

void BlockBatch::set(int item, std::span<const int> dofs, const double* f, const double* k, bool with_tangent) {
  const int n = static_cast<int>(dofs.size());
  if (n > kMaxDofs) throw std::invalid_argument("BlockBatch: block larger than kMaxDofs");
  Slot& s = slots_[item];
  s.n = n;
  s.with_tangent = with_tangent;
  std::copy_n(dofs.data(), n, s.dofs.begin());
  std::copy_n(f, n, s.f.begin());
  if (with_tangent) s.k.assign(k, k + n * n);
}

void SparseSystem::add(std::span<const int> dofs, const double* f, const double* k, bool with_tangent) {
  BlockBatch one;
  one.reset(1);
  one.set(0, dofs, f, k, with_tangent);
  add_slot(one.slots_[0], 0, dofs_.equation_count(), 0, dofs_.dof_count());
}

void SparseSystem::add(const BlockBatch& batch) {
  const int columns = dofs_.equation_count(), dof_count = dofs_.dof_count();
#pragma omp parallel
  {
    const long t = omp_get_thread_num(), threads = omp_get_num_threads();
    const int c0 = static_cast<int>(columns * t / threads), c1 = static_cast<int>(columns * (t + 1) / threads);
    const int d0 = static_cast<int>(dof_count * t / threads), d1 = static_cast<int>(dof_count * (t + 1) / threads);
    for (const BlockBatch::Slot& slot : batch.slots_)
      if (slot.n > 0) add_slot(slot, c0, c1, d0, d1);
  }
}

// The part of a block in columns [first_column, end_column) and residual rows [first_dof, end_dof).
void SparseSystem::add_slot(const BlockBatch::Slot& slot, int first_column, int end_column, int first_dof,
                            int end_dof) {
  const int n = slot.n;
  for (int a = 0; a < n; ++a)
    if (slot.dofs[a] >= first_dof && slot.dofs[a] < end_dof) residual_[slot.dofs[a]] += slot.f[a];
  if (!slot.with_tangent) return;
  const int* outer = tangent_.outerIndexPtr();
  const int* inner = tangent_.innerIndexPtr();
  double* values = tangent_.valuePtr();
  for (int b = 0; b < n; ++b) {
    const int col = dofs_.equation(slot.dofs[b]);
    if (col < first_column || col >= end_column) continue;
    const int* begin = inner + outer[col];
    const int* end = inner + outer[col + 1];
    for (int a = 0; a < n; ++a) {
      const int row = dofs_.equation(slot.dofs[a]);
      if (row < 0) continue;
      const double v = slot.k[a + b * n];
      if (v == 0.0) continue;
      values[std::lower_bound(begin, end, row) - inner] += v;
    }
  }
}

}  // namespace tirefem
