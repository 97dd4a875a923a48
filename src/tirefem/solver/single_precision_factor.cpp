#include "tirefem/solver/single_precision_factor.hpp"

extern "C" {  // the reference BLAS interface (OpenBLAS behind it)
void strsv_(const char* uplo, const char* trans, const char* diag, const int* n, const float* a, const int* lda,
            float* x, const int* incx);
void sgemv_(const char* trans, const int* m, const int* n, const float* alpha, const float* a, const int* lda,
            const float* x, const int* incx, const float* beta, float* y, const int* incy);
}

namespace tirefem {

bool SinglePrecisionFactor::assign(const cholmod_factor& L) {
  n_ = 0;
  if (!L.is_super || !L.is_ll || L.xtype != CHOLMOD_REAL || L.itype != CHOLMOD_INT || L.n == 0) return false;
  const int n = static_cast<int>(L.n), supernodes = static_cast<int>(L.nsuper);
  const auto copy = [](const void* from, std::size_t count, std::vector<int>& to) {
    const int* p = static_cast<const int*>(from);
    to.assign(p, p + count);
  };
  copy(L.Perm, n, permutation_);
  copy(L.super, supernodes + 1, first_column_);
  copy(L.pi, supernodes + 1, row_start_);
  copy(L.px, supernodes + 1, value_start_);
  copy(L.s, row_start_.back(), rows_);
  const double* x = static_cast<const double*>(L.x);
  const long entries = value_start_.back();
  values_.resize(entries);
#pragma omp parallel for schedule(static)
  for (long k = 0; k < entries; ++k) values_[k] = static_cast<float>(x[k]);
  work_.resize(n);
  below_.resize(L.maxesize);
  n_ = n;
  return true;
}

// Supernode by supernode, as CHOLMOD's own solve with one right-hand side: a supernode's columns k1 … k2−1
// have their rows (the first k2 − k1 of them the diagonal block) listed in rows_, and their entries stored
// column by column with those rows as the leading dimension.
Eigen::VectorXd SinglePrecisionFactor::solve(const Eigen::VectorXd& b) const {
  for (int k = 0; k < n_; ++k) work_[k] = static_cast<float>(b[permutation_[k]]);
  const int one = 1;
  const float plus = 1.0f, minus = -1.0f, zero = 0.0f;
  const int supernodes = static_cast<int>(first_column_.size()) - 1;
  for (int s = 0; s < supernodes; ++s) {  // L y = P b
    const int k1 = first_column_[s], columns = first_column_[s + 1] - k1;
    const int rows = row_start_[s + 1] - row_start_[s], below = rows - columns;
    const float* l = values_.data() + value_start_[s];
    strsv_("L", "N", "N", &columns, l, &rows, work_.data() + k1, &one);
    if (below == 0) continue;
    sgemv_("N", &below, &columns, &plus, l + columns, &rows, work_.data() + k1, &one, &zero, below_.data(), &one);
    const int* r = rows_.data() + row_start_[s] + columns;
    for (int i = 0; i < below; ++i) work_[r[i]] -= below_[i];
  }
  for (int s = supernodes - 1; s >= 0; --s) {  // Lᵀ z = y
    const int k1 = first_column_[s], columns = first_column_[s + 1] - k1;
    const int rows = row_start_[s + 1] - row_start_[s], below = rows - columns;
    const float* l = values_.data() + value_start_[s];
    if (below > 0) {
      const int* r = rows_.data() + row_start_[s] + columns;
      for (int i = 0; i < below; ++i) below_[i] = work_[r[i]];
      sgemv_("T", &below, &columns, &minus, l + columns, &rows, below_.data(), &one, &plus, work_.data() + k1, &one);
    }
    strsv_("L", "T", "N", &columns, l, &rows, work_.data() + k1, &one);
  }
  Eigen::VectorXd x(n_);
  for (int k = 0; k < n_; ++k) x[permutation_[k]] = work_[k];
  return x;
}

}  // namespace tirefem
