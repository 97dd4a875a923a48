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
  for (const SparseMatrix* m : matrices_) {
    if (m->rows() != n || m->cols() != n) throw std::invalid_argument("add_matrix_pattern: the matrix is not over the equations");
    for (int j = 0; j < n; ++j)
      for (SparseMatrix::InnerIterator it(*m, j); it; ++it) rows_of_column[j].push_back(static_cast<int>(it.row()));
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
  batches_added_ = 0;
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
  SlotPositions p;
  if (with_tangent) find_positions(one.slots_[0], p);
  add_slot(one.slots_[0], p.positions.data(), 0, dofs_.equation_count(), 0, dofs_.dof_count());
}

void SparseSystem::find_positions(const BlockBatch::Slot& slot, SlotPositions& p) const {
  const int n = slot.n;
  p.n = n;
  std::copy_n(slot.dofs.begin(), n, p.dofs.begin());
  p.positions.assign(n * n, -1);
  const int* outer = tangent_.outerIndexPtr();
  const int* inner = tangent_.innerIndexPtr();
  for (int b = 0; b < n; ++b) {
    const int col = dofs_.equation(slot.dofs[b]);
    if (col < 0) continue;
    const int* begin = inner + outer[col];
    const int* end = inner + outer[col + 1];
    for (int a = 0; a < n; ++a) {
      const int row = dofs_.equation(slot.dofs[a]);
      if (row < 0) continue;
      const int* at = std::lower_bound(begin, end, row);
      if (at == end || *at != row) throw std::logic_error("SparseSystem: a block outside the sparsity pattern");
      p.positions[a + b * n] = static_cast<int>(at - inner);
    }
  }
}

void SparseSystem::add(const BlockBatch& batch) {
  const int columns = dofs_.equation_count(), dof_count = dofs_.dof_count();
  if (static_cast<int>(positions_.size()) <= batches_added_) positions_.resize(batches_added_ + 1);
  std::vector<SlotPositions>& cache = positions_[batches_added_++];
  const int slots = static_cast<int>(batch.slots_.size());
  if (static_cast<int>(cache.size()) < slots) cache.resize(slots);
#pragma omp parallel
  {
#pragma omp for schedule(dynamic, 64)
    for (int i = 0; i < slots; ++i) {
      const BlockBatch::Slot& slot = batch.slots_[i];
      SlotPositions& p = cache[i];
      if (slot.n > 0 && slot.with_tangent &&
          (p.n != slot.n || !std::equal(slot.dofs.begin(), slot.dofs.begin() + slot.n, p.dofs.begin())))
        find_positions(slot, p);
    }
    const long t = omp_get_thread_num(), threads = omp_get_num_threads();
    const int c0 = static_cast<int>(columns * t / threads), c1 = static_cast<int>(columns * (t + 1) / threads);
    const int d0 = static_cast<int>(dof_count * t / threads), d1 = static_cast<int>(dof_count * (t + 1) / threads);
    for (int i = 0; i < slots; ++i)
      if (batch.slots_[i].n > 0) add_slot(batch.slots_[i], cache[i].positions.data(), c0, c1, d0, d1);
  }
}

// The part of a block in columns [first_column, end_column) and residual rows [first_dof, end_dof).
void SparseSystem::add_slot(const BlockBatch::Slot& slot, const int* positions, int first_column, int end_column,
                            int first_dof, int end_dof) {
  const int n = slot.n;
  for (int a = 0; a < n; ++a)
    if (slot.dofs[a] >= first_dof && slot.dofs[a] < end_dof) residual_[slot.dofs[a]] += slot.f[a];
  if (!slot.with_tangent) return;
  double* values = tangent_.valuePtr();
  for (int b = 0; b < n; ++b) {
    const int col = dofs_.equation(slot.dofs[b]);
    if (col < first_column || col >= end_column) continue;
    const int* column_positions = positions + b * n;
    const double* k = slot.k.data() + b * n;
    for (int a = 0; a < n; ++a)
      if (column_positions[a] >= 0) values[column_positions[a]] += k[a];
  }
}

}  // namespace tirefem
