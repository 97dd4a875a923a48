// The main of every test program: the process first gets the environment that tirefem and its bench give
// themselves (use_fast_blas_kernel: passive OpenMP waiting, OpenBLAS threads that sleep at once, one
// OpenMP thread per usable core, a named OpenBLAS kernel where the detected one is the generic fallback;
// keep_freed_memory: the allocator's settings), so the solvers are tested as the users run them; then
// GoogleTest runs.
#include <gtest/gtest.h>

#include "tirefem/solver/blas_kernel.hpp"
#include "tirefem/solver/heap_settings.hpp"

int main(int argc, char** argv) {
  tirefem::use_fast_blas_kernel(argv);
  tirefem::keep_freed_memory();
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
