#include "tirefem/solver/mixed_precision_lu.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

extern "C" {  // the reference LAPACK and BLAS interfaces (OpenBLAS behind them)
void sgetrf_(const int* m, const int* n, float* a, const int* lda, int* pivots, int* info);
void sgetrs_(const char* trans, const int* n, const int* nrhs, const float* a, const int* lda, const int* pivots,
             float* b, const int* ldb, int* info);
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* pivots, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* pivots,
             double* b, const int* ldb, int* info);
void dgemv_(const char* trans, const int* m, const int* n, const double* alpha, const double* a, const int* lda,
            const double* x, const int* incx, const double* beta, double* y, const int* incy);
}

namespace tirefem {
namespace {
// Refinement gains about log10(1 / (cond(S) · 6e-8)) digits per step; a step that does not halve the residual
// means the floats cannot resolve S, and the double LU takes over.
constexpr int kMaxRefinementSteps = 10;
// The normwise backward error a double LU solve reaches, in units of ε (its worst-case bound grows with m;
// in practice it is a few ε).
constexpr double kBackwardError = 2.0;
constexpr double kStall = 0.5;
}  // namespace

bool MixedPrecisionLU::factorize(Eigen::MatrixXd& matrix) {
  matrix_.swap(matrix);
  const int m = size();
  norm_ = m > 0 ? matrix_.cwiseAbs().rowwise().sum().maxCoeff() : 0.0;
  use_double_ = false;
  refinement_steps_ = 0;
  single_ = matrix_.cast<float>();
  pivots_.resize(m);
  int info = 0;
  sgetrf_(&m, &m, single_.data(), &m, pivots_.data(), &info);
  if (info == 0 && single_.allFinite()) return true;
  return factorize_double();
}

bool MixedPrecisionLU::factorize_double() {
  const int m = size();
  double_ = matrix_;
  double_pivots_.resize(m);
  int info = 0;
  dgetrf_(&m, &m, double_.data(), &m, double_pivots_.data(), &info);
  use_double_ = info == 0;
  return use_double_;
}

void MixedPrecisionLU::solve_single_precision(float* y) const {
  const int m = size(), one = 1;
  int info = 0;
  if (use_double_) {
    Eigen::Map<Eigen::VectorXf> v(y, m);
    Eigen::VectorXd d = v.cast<double>();
    dgetrs_("N", &m, &one, double_.data(), &m, double_pivots_.data(), d.data(), &m, &info);
    v = d.cast<float>();
    return;
  }
  sgetrs_("N", &m, &one, single_.data(), &m, pivots_.data(), y, &m, &info);
}

void MixedPrecisionLU::solve(double* y) {
  const int m = size(), one = 1;
  int info = 0;
  if (!use_double_) {
    // x ← x + S_f⁻¹ r, r = y − S x, until r is at the round-off of a backward-stable double solve:
    // ‖r‖∞ ≤ kBackwardError · ε (‖S‖∞ ‖x‖∞ + ‖y‖∞).
    const Eigen::Map<const Eigen::VectorXd> b(y, m);
    const double eps = std::numeric_limits<double>::epsilon();
    x_.setZero(m);
    r_ = b;
    double last = std::numeric_limits<double>::infinity();
    for (int step = 0; step < kMaxRefinementSteps; ++step) {
      c_ = r_.cast<float>();
      sgetrs_("N", &m, &one, single_.data(), &m, pivots_.data(), c_.data(), &m, &info);
      x_ += c_.cast<double>();
      ++refinement_steps_;
      r_ = b;
      const double minus_one = -1.0, plus_one = 1.0;
      dgemv_("N", &m, &m, &minus_one, matrix_.data(), &m, x_.data(), &one, &plus_one, r_.data(), &one);
      const double residual = r_.lpNorm<Eigen::Infinity>();
      if (!std::isfinite(residual)) break;
      if (residual <= kBackwardError * eps * (norm_ * x_.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>())) {
        std::copy_n(x_.data(), m, y);
        return;
      }
      if (residual > kStall * last) break;
      last = residual;
    }
    if (!factorize_double()) {
      std::fill_n(y, m, std::numeric_limits<double>::quiet_NaN());
      return;
    }
  }
  dgetrs_("N", &m, &one, double_.data(), &m, double_pivots_.data(), y, &m, &info);
}

}  // namespace tirefem
