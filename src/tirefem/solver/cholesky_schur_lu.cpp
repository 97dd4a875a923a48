#include "tirefem/solver/cholesky_schur_lu.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/CholmodSupport>

#include "tirefem/solver/cholmod_setup.hpp"
#include "tirefem/solver/mixed_precision_lu.hpp"
#include "tirefem/solver/single_precision_factor.hpp"
#include "tirefem/solver/supernodal_solve.hpp"
#include "tirefem/solver/symmetric_part.hpp"

extern "C" {  // the reference BLAS and LAPACK interfaces (OpenBLAS behind them)
void dlauum_(const char* uplo, const int* n, double* a, const int* lda, int* info);
}

namespace tirefem {
namespace {
// a_ij and a_ji differ "beyond round-off" when by more than this relative to √(|a_ii| |a_jj|). Measured on
// a 43 680-equation rolling tangent: the follower pressure's element sums leave differences below 1e-16
// of the largest diagonal entry, the friction's are above 1e-10 (U: 1 766 equations at 1e-16, 1 752 from
// 1e-15 to 1e-12, 1 751 at 1e-10).
constexpr double kAsymmetry = 1e-12;
constexpr double kFirstShift = 1.0, kLargestShift = 1e4;  // σ
constexpr double kMaxBlockGrowth = 1.25;  // the block ordered last may be this much larger than U
constexpr int kUnstableRings = 2;         // see add_unstable_region
// Regions added within one factorisation, each costing another analysis and factorisation (then UMFPACK
// serves, its first LU 2.5–5.5 s on 44k equations, and the next LU is UMFPACK's too). Measured on the
// cornering bench (80 × 46 full, rim flange), the α sweep's first iterate at 4°: after one region the rest
// was still indefinite, a second made it positive definite (m 2 135 → 2 850), 3.4 s for the three
// attempts; with one region allowed that state took 16.3 s (two UMFPACK LUs and 48 of its solves), with
// three 9.2 s, the sweep 25.5 → 16.5 s. (Earlier, with smaller first angle steps, an iterate of that
// bench's needed more than three.)
constexpr int kMaxUnstableRegions = 3;

cholmod_sparse lower_view(const SparseMatrix& lower) {
  cholmod_sparse view = Eigen::viewAsCholmod(lower);
  view.stype = -1;  // the lower triangle of a symmetric matrix
  return view;
}
}  // namespace

struct CholeskySchurLU::Impl {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  int analyses = 0;
  SymmetricPart symmetric;
  SparseMatrix shifted;             // M's lower triangle
  std::vector<int> diagonal;        // position of each diagonal entry in symmetric.lower()
  std::vector<int> whole_order;     // fill-reducing ordering of the whole pattern
  std::vector<char> in_u, analysed_u;
  std::vector<char> unstable;       // equations of A_VV's negative modes found so far, kept in the block
  std::vector<int> u_position;      // equation → its place in U (the last m of the factor's order), or −1
  int n = 0, m = 0;
  double shift = kFirstShift;
  double flops = 0.0;
  bool held = false;
  Eigen::MatrixXd schur;            // S while it is formed (swapped into schur_lu, storage reused)
  MixedPrecisionLU schur_lu;        // its LU
  std::vector<double> work, below;
  SinglePrecisionFactor single;
  bool single_current = false;
  std::vector<float> single_work, single_below;

  Impl() {
    cholmod_start(&common);
    common.print = 0;  // "not positive definite" is an answer here
    common.supernodal = CHOLMOD_SUPERNODAL;
  }
  ~Impl() {
    cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  bool find_unsymmetric(const SparseMatrix& a);
  void analyse();
  void choose_block();
  // The Cholesky of M: `factorized`, or `indefinite_rest` (A_VV not positive definite at the factor's
  // column `failed_column`), or `failed`.
  enum class Cholesky { factorized, indefinite_rest, failed };
  Cholesky factorize_shifted();
  int failed_column = -1;
  bool add_unstable_region(const SparseMatrix& a);
  int reversed(int position_in_u) const { return m - 1 - position_in_u; }  // S's order
  void form_schur(const SparseMatrix& a);
  void solve_schur(double* y);
  void solve_schur(float* y);
};

bool CholeskySchurLU::Impl::find_unsymmetric(const SparseMatrix& a) {
  n = static_cast<int>(a.rows());
  const SparseMatrix& lower = symmetric.lower();
  if (static_cast<int>(diagonal.size()) != n) {
    diagonal.assign(n, -1);
    for (int j = 0; j < n; ++j)
      for (int k = lower.outerIndexPtr()[j]; k < lower.outerIndexPtr()[j + 1]; ++k)
        if (lower.innerIndexPtr()[k] == j) diagonal[j] = k;
  }
  const double* v = lower.valuePtr();
  const auto diag = [&](int j) { return diagonal[j] >= 0 ? std::abs(v[diagonal[j]]) : 0.0; };
  in_u.assign(n, 0);
  for (int j = 0; j < n; ++j)
    for (int k = lower.outerIndexPtr()[j]; k < lower.outerIndexPtr()[j + 1]; ++k) {
      const int i = lower.innerIndexPtr()[k];
      if (std::abs(antisymmetric_value(a.valuePtr(), symmetric.sources()[k])) > kAsymmetry * std::sqrt(diag(i) * diag(j)))
        in_u[i] = in_u[j] = 1;
    }
  if (std::count(in_u.begin(), in_u.end(), 1) == 0) return false;
  if (static_cast<int>(unstable.size()) == n) {
    std::vector<char> with_unstable = in_u;
    for (int i = 0; i < n; ++i) with_unstable[i] = in_u[i] || unstable[i];
    if (std::count(with_unstable.begin(), with_unstable.end(), 1) <= kMaxUnsymmetricEquations) in_u.swap(with_unstable);
    else unstable.clear();  // the patch has grown: its regions found so far give way
  }
  m = static_cast<int>(std::count(in_u.begin(), in_u.end(), 1));
  return m <= kMaxUnsymmetricEquations && m < n;
}

// A_VV indefinite: its negative mode is a local one (measured on a rolling tangent at α = 4°, 80 × 46 full
// model: −3e-5 relative to the diagonal, in the shoulder some 60° ahead of the patch; a buckling-like mode
// of the static part that the converged state carries), and CHOLMOD fails at a column within it. The
// equations within kUnstableRings couplings of that column join the block (there the dense LU serves, as
// for the friction); on that tangent one such region of 234 equations made the rest positive definite.
// False when the block would grow beyond kMaxUnsymmetricEquations.
bool CholeskySchurLU::Impl::add_unstable_region(const SparseMatrix& a) {
  if (static_cast<int>(unstable.size()) != n) unstable.assign(n, 0);
  std::vector<int> region{failed_column};
  std::vector<char> in_region(n, 0);
  in_region[failed_column] = 1;
  for (int ring = 0, begin = 0; ring < kUnstableRings; ++ring) {
    const int end = static_cast<int>(region.size());
    for (int r = begin; r < end; ++r)
      for (int k = a.outerIndexPtr()[region[r]]; k < a.outerIndexPtr()[region[r] + 1]; ++k)
        if (const int i = a.innerIndexPtr()[k]; !in_region[i]) in_region[i] = 1, region.push_back(i);
    begin = end;
  }
  int added = 0;
  for (int i : region) added += !in_u[i];
  if (m + added > kMaxUnsymmetricEquations) {
    unstable.assign(n, 0);
    return false;
  }
  for (int i : region) unstable[i] = in_u[i] = 1;
  m += added;
  return true;
}

// The block ordered last: U, or the one analysed if it holds U and is not much larger (a new analysis costs
// about half a factorisation, with the first factorisation after it allocating the factor anew).
void CholeskySchurLU::Impl::choose_block() {
  if (factor == nullptr || analysed_u.size() != in_u.size()) {
    analyse();
    return;
  }
  int union_size = 0;
  bool contained = true;
  for (int i = 0; i < n; ++i) {
    union_size += in_u[i] || analysed_u[i];
    contained = contained && (!in_u[i] || analysed_u[i]);
  }
  if (contained && union_size <= kMaxBlockGrowth * m) {
    in_u = analysed_u;
    m = union_size;
    return;
  }
  if (union_size <= kMaxBlockGrowth * m && union_size <= kMaxUnsymmetricEquations)
    for (int i = 0; i < n; ++i) in_u[i] = in_u[i] || analysed_u[i];
  m = static_cast<int>(std::count(in_u.begin(), in_u.end(), 1));
  analyse();
}

// CHOLMOD's symbolic analysis in the order of the whole pattern's fill-reducing ordering, U moved last
// (measured, flops per factorisation with U last: that order 17.9 G, V's own best ordering 18.2 G, a
// minimum degree with U constrained last 19.0 G; M alone 7.9 G). No postordering: it could interleave U.
void CholeskySchurLU::Impl::analyse() {
  cholmod_sparse lower = lower_view(symmetric.lower());
  if (whole_order.empty()) {
    use_tyre_factor_settings(common);
    const std::lock_guard lock(ordering_mutex());
    cholmod_factor* whole = cholmod_analyze(&lower, &common);
    if (!whole) throw std::runtime_error("CHOLMOD could not analyse the tangent");
    const int* p = static_cast<const int*>(whole->Perm);
    whole_order.assign(p, p + n);
    cholmod_free_factor(&whole, &common);
  }
  std::vector<int> order;
  order.reserve(n);
  for (int i : whole_order)
    if (!in_u[i]) order.push_back(i);
  for (int i : whole_order)
    if (in_u[i]) order.push_back(i);
  cholmod_free_factor(&factor, &common);
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_GIVEN;
  common.postorder = 0;
  factor = cholmod_analyze_p(&lower, order.data(), nullptr, 0, &common);
  if (!factor) throw std::runtime_error("CHOLMOD could not analyse the tangent");
  flops = common.fl + std::pow(static_cast<double>(m), 3);  // S = L_UU L_UUᵀ and its LU: m³/3 + 2m³/3
  ++analyses;
  analysed_u = in_u;
  const int* p = static_cast<const int*>(factor->Perm);
  u_position.assign(n, -1);
  for (int k = n - m; k < n; ++k) {
    if (!in_u[p[k]]) throw std::logic_error("CHOLMOD reordered the unsymmetric block");
    u_position[p[k]] = k - (n - m);
  }
}

// Cholesky of M at the current σ, σ raised tenfold while only M_UU's part fails: `indefinite_rest` when
// A_VV is not positive definite, `failed` when σ would exceed kLargestShift or CHOLMOD fails otherwise.
CholeskySchurLU::Impl::Cholesky CholeskySchurLU::Impl::factorize_shifted() {
  const SparseMatrix& lower = symmetric.lower();
  if (shifted.nonZeros() != lower.nonZeros()) shifted = lower;
  for (;;) {
    std::copy(lower.valuePtr(), lower.valuePtr() + lower.nonZeros(), shifted.valuePtr());
    const double* v = lower.valuePtr();
    for (int i = 0; i < n; ++i)
      if (in_u[i] && diagonal[i] >= 0) shifted.valuePtr()[diagonal[i]] += shift * std::abs(v[diagonal[i]]);
    cholmod_sparse view = lower_view(shifted);
    cholmod_factorize(&view, factor, &common);
    if (common.status == CHOLMOD_OK) return Cholesky::factorized;
    if (common.status != CHOLMOD_NOT_POSDEF) return Cholesky::failed;
    if (static_cast<int>(factor->minor) < n - m) {
      failed_column = static_cast<const int*>(factor->Perm)[factor->minor];
      return Cholesky::indefinite_rest;
    }
    shift *= 10;
    if (shift > kLargestShift) {
      shift = kFirstShift;
      return Cholesky::failed;
    }
  }
}

// S = L_UU L_UUᵀ + A_UU − M_UU, held in the reverse of U's order (u_position): there L_UU becomes upper
// triangular, U' = J L_UU J with J the reversal, and LAPACK's dlauum forms U'U'ᵀ = J L_UU L_UUᵀ J in m³/3
// flops, where a dsyrk of the triangle as a full matrix takes m³ (at m = 2 710, 20 of the factorisation's
// 48 GFlop).
void CholeskySchurLU::Impl::form_schur(const SparseMatrix& a) {
  const SupernodalFactorView<double> f = view_of(*factor);
  const int first = n - m;
  schur.setZero(m, m);
  for (int s = 0; s < f.supernodes; ++s) {
    const int k1 = f.first_column[s], k2 = f.first_column[s + 1];
    if (k2 <= first) continue;
    const int rows = f.row_start[s + 1] - f.row_start[s];
    const int* r = f.rows + f.row_start[s];
    for (int col = std::max(k1, first); col < k2; ++col) {
      const double* l = f.values + f.value_start[s] + static_cast<long>(col - k1) * rows;
      double* out = schur.data() + static_cast<long>(reversed(col - first)) * m;
      for (int i = col - k1; i < rows; ++i) out[reversed(r[i] - first)] = l[i];
    }
  }
  int info = 0;
  dlauum_("U", &m, schur.data(), &m, &info);
  schur.triangularView<Eigen::StrictlyLower>() = schur.transpose();
  const SparseMatrix& lower = symmetric.lower();
  for (int j = 0; j < n; ++j) {
    if (u_position[j] < 0) continue;
    const int q = reversed(u_position[j]);
    for (int k = lower.outerIndexPtr()[j]; k < lower.outerIndexPtr()[j + 1]; ++k) {
      if (u_position[lower.innerIndexPtr()[k]] < 0) continue;
      const int p = reversed(u_position[lower.innerIndexPtr()[k]]);
      if (p == q) {
        schur(p, p) -= shift * std::abs(lower.valuePtr()[k]);
        continue;
      }
      const double d = antisymmetric_value(a.valuePtr(), symmetric.sources()[k]);  // ½(a_ij − a_ji)
      schur(p, q) += d;
      schur(q, p) -= d;
    }
  }
}

void CholeskySchurLU::Impl::solve_schur(double* y) {
  std::reverse(y, y + m);  // into S's order
  schur_lu.solve(y);
  std::reverse(y, y + m);
}

void CholeskySchurLU::Impl::solve_schur(float* y) {
  std::reverse(y, y + m);
  schur_lu.solve_single_precision(y);
  std::reverse(y, y + m);
}

CholeskySchurLU::CholeskySchurLU() : impl_(std::make_unique<Impl>()) {}
CholeskySchurLU::~CholeskySchurLU() = default;

CholeskySchurLU::Outcome CholeskySchurLU::factorize(const SparseMatrix& a) {
  auto& s = *impl_;
  s.held = false;
  s.single_current = false;
  s.symmetric.update(a);
  if (!s.find_unsymmetric(a)) return Outcome::not_applicable;
  s.choose_block();
  for (int round = 0;; ++round) {
    const Impl::Cholesky c = s.factorize_shifted();
    if (c == Impl::Cholesky::factorized) break;
    if (c == Impl::Cholesky::failed || round == kMaxUnstableRegions || !s.add_unstable_region(a))
      return Outcome::failed;
    s.analyse();
  }
  s.form_schur(a);
  if (!s.schur_lu.factorize(s.schur)) return Outcome::failed;
  s.work.resize(s.n);
  s.held = true;
  return Outcome::factorized;
}

Eigen::VectorXd CholeskySchurLU::solve(const Eigen::VectorXd& b) {
  auto& s = *impl_;
  const SupernodalFactorView<double> f = view_of(*s.factor);
  const int first = s.n - s.m;
  for (int k = 0; k < s.n; ++k) s.work[k] = b[f.permutation[k]];
  forward_substitute(f, s.work.data(), s.below, first);
  s.solve_schur(s.work.data() + first);
  back_substitute(f, s.work.data(), s.below, first);
  Eigen::VectorXd x(s.n);
  for (int k = 0; k < s.n; ++k) x[f.permutation[k]] = s.work[k];
  return x;
}

Eigen::VectorXd CholeskySchurLU::solve_single_precision(const Eigen::VectorXd& b) {
  auto& s = *impl_;
  if (!s.single_current) {
    s.single_current = s.single.assign(*s.factor);
    if (!s.single_current) return solve(b);
    s.single_work.resize(s.n);
  }
  const SupernodalFactorView<float> f = s.single.view();
  const int first = s.n - s.m;
  for (int k = 0; k < s.n; ++k) s.single_work[k] = static_cast<float>(b[f.permutation[k]]);
  forward_substitute(f, s.single_work.data(), s.single_below, first);
  s.solve_schur(s.single_work.data() + first);
  back_substitute(f, s.single_work.data(), s.single_below, first);
  Eigen::VectorXd x(s.n);
  for (int k = 0; k < s.n; ++k) x[f.permutation[k]] = s.single_work[k];
  return x;
}

int CholeskySchurLU::unsymmetric_equations() const { return impl_->held ? impl_->m : 0; }
double CholeskySchurLU::factor_flops() const { return impl_->flops; }
int CholeskySchurLU::analyses() const { return impl_->analyses; }

}  // namespace tirefem
