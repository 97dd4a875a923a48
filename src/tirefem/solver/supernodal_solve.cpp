#include "tirefem/solver/supernodal_solve.hpp"

#include <algorithm>

extern "C" {  // the reference BLAS interface (OpenBLAS behind it)
void strsv_(const char* uplo, const char* trans, const char* diag, const int* n, const float* a, const int* lda,
            float* x, const int* incx);
void dtrsv_(const char* uplo, const char* trans, const char* diag, const int* n, const double* a, const int* lda,
            double* x, const int* incx);
void sgemv_(const char* trans, const int* m, const int* n, const float* alpha, const float* a, const int* lda,
            const float* x, const int* incx, const float* beta, float* y, const int* incy);
void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a, const int* lda,
            const double* x, const int* incx, const double* beta, double* y, const int* incy);
}

namespace tirefem {
namespace {
void trsv(const char* trans, int n, const float* a, int lda, float* x) {
  const int one = 1;
  strsv_("L", trans, "N", &n, a, &lda, x, &one);
}
void trsv(const char* trans, int n, const double* a, int lda, double* x) {
  const int one = 1;
  dtrsv_("L", trans, "N", &n, a, &lda, x, &one);
}
// y ← α op(A) x + β y
void gemv(const char* trans, int m, int n, float alpha, const float* a, int lda, const float* x, float beta, float* y) {
  const int one = 1;
  sgemv_(trans, &m, &n, &alpha, a, &lda, x, &one, &beta, y, &one);
}
void gemv(const char* trans, int m, int n, double alpha, const double* a, int lda, const double* x, double beta,
          double* y) {
  const int one = 1;
  dgemv_(trans, &m, &n, &alpha, a, &lda, x, &one, &beta, y, &one);
}
}  // namespace

SupernodalFactorView<double> view_of(const cholmod_factor& L) {
  SupernodalFactorView<double> f;
  if (!L.is_super || !L.is_ll || L.xtype != CHOLMOD_REAL || L.itype != CHOLMOD_INT || L.n == 0) return f;
  f.n = static_cast<int>(L.n);
  f.supernodes = static_cast<int>(L.nsuper);
  f.permutation = static_cast<const int*>(L.Perm);
  f.first_column = static_cast<const int*>(L.super);
  f.row_start = static_cast<const int*>(L.pi);
  f.value_start = static_cast<const int*>(L.px);
  f.rows = static_cast<const int*>(L.s);
  f.values = static_cast<const double*>(L.x);
  return f;
}

// A supernode straddling `end` is used over its columns before it: its later columns' rows of the
// diagonal block then count as rows below.
template <class T>
void forward_substitute(const SupernodalFactorView<T>& f, T* y, std::vector<T>& below, int end) {
  for (int s = 0; s < f.supernodes && f.first_column[s] < end; ++s) {
    const int k1 = f.first_column[s];
    const int columns = std::min(f.first_column[s + 1], end) - k1;
    const int rows = f.row_start[s + 1] - f.row_start[s], rest = rows - columns;
    const T* l = f.values + f.value_start[s];
    trsv("N", columns, l, rows, y + k1);
    if (rest == 0) continue;
    if (static_cast<int>(below.size()) < rest) below.resize(rest);
    gemv("N", rest, columns, T(1), l + columns, rows, y + k1, T(0), below.data());
    const int* r = f.rows + f.row_start[s] + columns;
    for (int i = 0; i < rest; ++i) y[r[i]] -= below[i];
  }
}

template <class T>
void back_substitute(const SupernodalFactorView<T>& f, T* y, std::vector<T>& below, int end) {
  for (int s = f.supernodes - 1; s >= 0; --s) {
    const int k1 = f.first_column[s];
    if (k1 >= end) continue;
    const int columns = std::min(f.first_column[s + 1], end) - k1;
    const int rows = f.row_start[s + 1] - f.row_start[s], rest = rows - columns;
    const T* l = f.values + f.value_start[s];
    if (rest > 0) {
      if (static_cast<int>(below.size()) < rest) below.resize(rest);
      const int* r = f.rows + f.row_start[s] + columns;
      for (int i = 0; i < rest; ++i) below[i] = y[r[i]];
      gemv("T", rest, columns, T(-1), l + columns, rows, below.data(), T(1), y + k1);
    }
    trsv("T", columns, l, rows, y + k1);
  }
}

template void forward_substitute(const SupernodalFactorView<float>&, float*, std::vector<float>&, int);
template void forward_substitute(const SupernodalFactorView<double>&, double*, std::vector<double>&, int);
template void back_substitute(const SupernodalFactorView<float>&, float*, std::vector<float>&, int);
template void back_substitute(const SupernodalFactorView<double>&, double*, std::vector<double>&, int);

}  // namespace tirefem
