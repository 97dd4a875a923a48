#include "tirefem/solver/symmetric_part.hpp"

#include <algorithm>

namespace tirefem {

void SymmetricPart::update(const SparseMatrix& a) {
  if (lower_.rows() != a.rows() || sources_.empty()) {
    const auto position = [&](int row, int col) {  // of a_row,col in A's value array, or −1
      const int* begin = a.innerIndexPtr() + a.outerIndexPtr()[col];
      const int* end = a.innerIndexPtr() + a.outerIndexPtr()[col + 1];
      const int* it = std::lower_bound(begin, end, row);
      return it != end && *it == row ? static_cast<int>(it - a.innerIndexPtr()) : -1;
    };
    const SparseMatrix transposed = a.transpose();
    lower_ = SparseMatrix(a + transposed).triangularView<Eigen::Lower>();
    lower_.makeCompressed();
    sources_.resize(lower_.nonZeros());
    for (int j = 0; j < lower_.cols(); ++j)
      for (int k = lower_.outerIndexPtr()[j]; k < lower_.outerIndexPtr()[j + 1]; ++k)
        sources_[k] = {position(lower_.innerIndexPtr()[k], j), position(j, lower_.innerIndexPtr()[k])};
  }
  const double* values = a.valuePtr();
  double* sym = lower_.valuePtr();
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    const auto [ij, ji] = sources_[k];
    sym[k] = 0.5 * ((ij >= 0 ? values[ij] : 0.0) + (ji >= 0 ? values[ji] : 0.0));
  }
}

}  // namespace tirefem
