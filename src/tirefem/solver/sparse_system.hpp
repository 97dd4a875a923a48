#pragma once
// Residual and tangent of a nonlinear problem assembled into a sparsity pattern fixed once, so the
// symbolic analysis of the sparse factorisation is done once per run. Element blocks computed in parallel
// loops are stored per item (BlockBatch) and summed in item order, so the result is bit-identical on any
// number of threads.
#include <array>
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
  // Every entry of a matrix over the equations of the DofMap that build() gets; it must outlive build().
  void add_matrix_pattern(const SparseMatrix& matrix) { matrices_.push_back(&matrix); }
  SparseMatrix build(const DofMap& dofs) const;

 private:
  std::vector<std::vector<int>> blocks_;
  std::vector<const SparseMatrix*> matrices_;
};

// The element blocks of one parallel loop, one slot per item (element, tread point, ...): set() may be
// called from any thread for distinct slots; SparseSystem::add(batch) then sums them in slot order.
class BlockBatch {
 public:
  static constexpr int kMaxDofs = 36;
  void reset(int items);  // all slots empty; keeps the storage of earlier batches
  // Slot `item` holds residual f over `dofs` and, with_tangent, the column-major block k (n × n).
  void set(int item, std::span<const int> dofs, const double* f, const double* k_col_major, bool with_tangent);
  template <class Vec, class Mat>
  void set(int item, std::span<const int> dofs, const Vec& f, const Mat& k, bool with_tangent) {
    set(item, dofs, f.data(), k.data(), with_tangent);
  }

 private:
  friend class SparseSystem;
  struct Slot {
    int n = 0;  // 0: empty
    bool with_tangent = false;
    std::array<int, kMaxDofs> dofs;
    std::array<double, kMaxDofs> f;
    std::vector<double> k;
  };
  std::vector<Slot> slots_;
};

class SparseSystem {
 public:
  SparseSystem(const DofMap& dofs, SparseMatrix pattern);

  void clear(bool with_tangent);
  // Adds an element block: residual[d] += f, tangent[eq(d_i), eq(d_j)] += k(i, j). Not thread-safe: a
  // parallel loop fills a BlockBatch instead.
  void add(std::span<const int> dofs, const double* f, const double* k_col_major, bool with_tangent);
  template <class Vec, class Mat>
  void add(std::span<const int> dofs, const Vec& f, const Mat& k, bool with_tangent) {
    add(dofs, f.data(), k.data(), with_tangent);
  }
  // Adds every slot of the batch in slot order (in parallel over ranges of columns and rows, so each
  // entry receives its contributions in the same order whatever the number of threads).
  void add(const BlockBatch& batch);
  // A batch to fill in a parallel loop over `items` (this system's storage, reused between assemblies).
  BlockBatch& batch(int items) {
    batch_.reset(items);
    return batch_;
  }
  void add_residual(int dof, double value);
  // Adds a whole matrix over the equations with the system's own pattern (e.g. a stored tangent of this
  // system). Not thread-safe: call it outside parallel loops. Throws if the pattern differs.
  void add_matrix(const SparseMatrix& matrix);

  const Eigen::VectorXd& residual() const { return residual_; }  // full length, incl. reactions
  const SparseMatrix& tangent() const { return tangent_; }        // equations × equations
  const DofMap& dofs() const { return dofs_; }

 private:
  // Where each entry of a slot's block goes in the tangent's value array (−1: a constrained row or
  // column), with the DOFs it was found for.
  struct SlotPositions {
    int n = 0;
    std::array<int, BlockBatch::kMaxDofs> dofs;
    std::vector<int> positions;
  };
  void find_positions(const BlockBatch::Slot& slot, SlotPositions& p) const;
  void add_slot(const BlockBatch::Slot& slot, const int* positions, int first_column, int end_column,
                int first_dof, int end_dof);
  const DofMap& dofs_;
  Eigen::VectorXd residual_;
  SparseMatrix tangent_;
  BlockBatch batch_;
  // The forms add their batches in the same order at every assembly, and an element's DOFs do not
  // change: so the positions of the k-th batch's slots are found once (by binary search in the pattern)
  // and reused, checked against the slot's DOFs each time.
  std::vector<std::vector<SlotPositions>> positions_;
  int batches_added_ = 0;  // since the last clear()
};

}  // namespace tirefem
