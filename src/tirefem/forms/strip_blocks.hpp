#pragma once
// Tangent blocks of a form whose points couple only the elements of one strip (the tread friction: a
// point's force depends on points of its own line, MODEL.md §5 eq. 16), summed per pair (row element,
// column element) of the strip instead of per point: with the 4 × 4 rule 16 points share an element, so
// far fewer blocks reach the sparse tangent. Sums run in strip, line and point order (deterministic).
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/solver/sparse_system.hpp"

namespace tirefem {

using ElementPair = std::pair<int, int>;  // (row element, column element)

// The slots of one assembly: per strip its pairs (sorted, unique), numbered strip by strip.
class StripSlots {
 public:
  explicit StripSlots(std::vector<std::vector<ElementPair>> pairs);
  int slots() const { return first_slot_.back(); }
  int strips() const { return static_cast<int>(pairs_.size()); }
  const std::vector<ElementPair>& pairs(int strip) const { return pairs_[strip]; }
  int first_slot(int strip) const { return first_slot_[strip]; }

 private:
  std::vector<std::vector<ElementPair>> pairs_;
  std::vector<int> first_slot_;
};

// The sums of one strip (one per thread, reused from strip to strip).
class StripBlocks {
 public:
  void reset(const StripSlots& slots, int strip);
  // Residual of the row element's DOFs += Σ_a shape[a] · force at node a.
  void add_residual(int element, const Eigen::Vector4d& shape, const Eigen::Vector3d& residual);
  // Tangent (row element, column element) += row_shape ⊗ column_shape ⊗ block (3 × 3 per node pair).
  // A pair the strip's slots do not hold is skipped (the caller's dependencies define the slots).
  void add_tangent(int row_element, const Eigen::Vector4d& row_shape, int column_element,
                   const Eigen::Vector4d& column_shape, const Eigen::Matrix3d& block);
  // Moves the sums into the batch: per pair the row element's 12 outer-face DOFs, then the column
  // element's unless the same.
  void flush(const ShellMesh& mesh, BlockBatch& batch, bool with_tangent) const;

 private:
  int slot(int row, int column) const;
  const std::vector<ElementPair>* pairs_ = nullptr;
  int first_slot_ = 0;
  std::vector<Eigen::Matrix<double, 12, 12>> tangents_;
  std::vector<Eigen::Matrix<double, 12, 1>> residuals_;
};

}  // namespace tirefem
