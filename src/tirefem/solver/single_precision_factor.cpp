#include "tirefem/solver/single_precision_factor.hpp"

namespace tirefem {

bool SinglePrecisionFactor::assign(const cholmod_factor& L) {
  n_ = 0;
  if (view_of(L).n == 0) return false;  // not a supernodal LLᵀ factor of real entries with int indices
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

SupernodalFactorView<float> SinglePrecisionFactor::view() const {
  SupernodalFactorView<float> f;
  f.n = n_;
  f.supernodes = static_cast<int>(first_column_.size()) - 1;
  f.permutation = permutation_.data();
  f.first_column = first_column_.data();
  f.row_start = row_start_.data();
  f.value_start = value_start_.data();
  f.rows = rows_.data();
  f.values = values_.data();
  return f;
}

Eigen::VectorXd SinglePrecisionFactor::solve(const Eigen::VectorXd& b) const {
  for (int k = 0; k < n_; ++k) work_[k] = static_cast<float>(b[permutation_[k]]);
  const SupernodalFactorView<float> f = view();
  forward_substitute(f, work_.data(), below_, n_);  // L y = P b
  back_substitute(f, work_.data(), below_, n_);     // Lᵀ z = y
  Eigen::VectorXd x(n_);
  for (int k = 0; k < n_; ++k) x[permutation_[k]] = work_[k];
  return x;
}

}  // namespace tirefem
