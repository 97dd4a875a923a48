// The BLAS the factorisations run on is identified, and the kernel chosen for an unrecognised CPU is one
// this CPU can run.
#include <gtest/gtest.h>

#include "tirefem/solver/blas_kernel.hpp"
#include "tirefem/solver/linear_solver.hpp"

namespace tirefem {
namespace {

TEST(BlasKernel, NamesTheLibraryAndItsKernel) {
  // A factorisation, so that this test program loads the BLAS behind CHOLMOD as the solvers do.
  SparseMatrix a(2, 2);
  a.insert(0, 0) = 2.0, a.insert(1, 1) = 3.0, a.insert(1, 0) = 1.0, a.insert(0, 1) = 1.0;
  SparseDirectSolver solver(true);
  solver.factorize(a);
  EXPECT_NEAR(solver.solve(Eigen::Vector2d(3.0, 4.0))[0], 1.0, 1e-12);
  const BlasKernel k = blas_kernel();
  // The project links OpenBLAS (scripts/install-deps.sh); its configuration string and core are read.
  EXPECT_EQ(k.library.rfind("OpenBLAS", 0), 0u) << k.library;
  EXPECT_FALSE(k.core.empty());
}

TEST(BlasKernel, FallbackChoiceIsSupportedByThisCpu) {
  const std::string best = best_kernel_for_this_cpu();
#if defined(__x86_64__)
  __builtin_cpu_init();
  if (best == "SkylakeX") EXPECT_TRUE(__builtin_cpu_supports("avx512f"));
  if (best == "Haswell") EXPECT_TRUE(__builtin_cpu_supports("avx2"));
  if (best == "Sandybridge") EXPECT_TRUE(__builtin_cpu_supports("avx"));
  // Every x86-64 machine these builds run on (Debian 12's baseline plus AVX) gets a named kernel.
  if (__builtin_cpu_supports("avx")) EXPECT_FALSE(best.empty());
#else
  EXPECT_TRUE(best.empty());
#endif
}

}  // namespace
}  // namespace tirefem
