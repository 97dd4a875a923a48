// The main of every test program: the process first gets the environment that tirefem and its bench give
// themselves (use_fast_blas_kernel: passive OpenMP waiting, OpenBLAS threads that sleep at once, one
// OpenMP thread per usable core, a named OpenBLAS kernel where the detected one is the generic fallback),
// so the solvers are tested as the users run them; then GoogleTest runs.
#include <gtest/gtest.h>

#include "tirefem/solver/blas_kernel.hpp"

int main(int argc, char** argv) {
  tirefem::use_fast_blas_kernel(argv);
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
