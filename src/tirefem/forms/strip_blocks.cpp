#include "tirefem/forms/strip_blocks.hpp"

#include <algorithm>
#include <array>
#include <span>

namespace tirefem {

StripSlots::StripSlots(std::vector<std::vector<ElementPair>> pairs) : pairs_(std::move(pairs)) {
  first_slot_.assign(pairs_.size() + 1, 0);
  for (std::size_t s = 0; s < pairs_.size(); ++s) {
    std::vector<ElementPair>& p = pairs_[s];
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
    first_slot_[s + 1] = first_slot_[s] + static_cast<int>(p.size());
  }
}

void StripBlocks::reset(const StripSlots& slots, int strip) {
  pairs_ = &slots.pairs(strip);
  first_slot_ = slots.first_slot(strip);
  tangents_.assign(pairs_->size(), Eigen::Matrix<double, 12, 12>::Zero());
  residuals_.assign(pairs_->size(), Eigen::Matrix<double, 12, 1>::Zero());
}

int StripBlocks::slot(int row, int column) const {
  const auto it = std::lower_bound(pairs_->begin(), pairs_->end(), ElementPair(row, column));
  return it == pairs_->end() || *it != ElementPair(row, column) ? -1 : static_cast<int>(it - pairs_->begin());
}

void StripBlocks::add_residual(int element, const Eigen::Vector4d& shape, const Eigen::Vector3d& residual) {
  const int k = slot(element, element);
  if (k < 0) return;
  for (int a = 0; a < 4; ++a) residuals_[k].segment<3>(3 * a) += shape[a] * residual;
}

void StripBlocks::add_tangent(int row_element, const Eigen::Vector4d& row_shape, int column_element,
                              const Eigen::Vector4d& column_shape, const Eigen::Matrix3d& block) {
  const int k = slot(row_element, column_element);
  if (k < 0) return;
  Eigen::Matrix<double, 12, 12>& t = tangents_[k];
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) t.block<3, 3>(3 * a, 3 * b) += row_shape[a] * column_shape[b] * block;
}

void StripBlocks::flush(const ShellMesh& mesh, BlockBatch& batch, bool with_tangent) const {
  using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 24, 24>;
  Block tangent;
  Eigen::Matrix<double, 24, 1> f;
  std::array<int, 24> dofs{};
  for (int k = 0; k < static_cast<int>(pairs_->size()); ++k) {
    const auto [row, column] = (*pairs_)[k];
    const bool own = row == column;
    const int m = own ? 12 : 24, column0 = own ? 0 : 12;
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 3; ++c) {
        dofs[3 * a + c] = outer_dof(mesh.elements[row][a], c);
        dofs[column0 + 3 * a + c] = outer_dof(mesh.elements[column][a], c);
      }
    f.setZero();
    f.head<12>() = residuals_[k];
    if (with_tangent) {
      tangent.setZero(m, m);
      tangent.block<12, 12>(0, column0) = tangents_[k];
    }
    const double* residual = f.data();
    const double* block = with_tangent ? tangent.data() : nullptr;
    batch.set(first_slot_ + k, std::span<const int>(dofs.data(), m), residual, block, with_tangent);
  }
}

}  // namespace tirefem
