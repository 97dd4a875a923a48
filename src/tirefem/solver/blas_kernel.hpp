#pragma once
// Which BLAS the sparse factorisations run on, and the choice of its kernel. OpenBLAS picks its kernel
// (the "core") from the CPU when the library loads; Debian 12's 0.3.21 does not know some newer CPUs and
// then falls back to its slowest generic x86-64 kernel (Prescott, SSE3), ~25% slower per factorisation
// (VERIFICATION of issue 9). The choice can only be changed before the library loads, through the
// environment variable OPENBLAS_CORETYPE, so a program re-executes itself once with it set.
#include <string>

namespace tirefem {

struct BlasKernel {
  std::string library;  // "OpenBLAS 0.3.21 …" as the library describes itself, or "unknown BLAS"
  std::string core;     // the kernel in use, e.g. "Haswell", "SkylakeX", "Prescott"; empty if unknown
  bool forced = false;  // chosen through OPENBLAS_CORETYPE
};

BlasKernel blas_kernel();

// The OpenBLAS kernel this CPU supports best ("SkylakeX" with AVX-512, "Haswell" with AVX2 and FMA,
// "Sandybridge" with AVX), or empty when none of these applies.
std::string best_kernel_for_this_cpu();

// When OpenBLAS fell back to its generic kernel although the CPU supports a faster one, and the user has
// not chosen one: sets OPENBLAS_CORETYPE. Unless the user has chosen one, sets OMP_WAIT_POLICY=passive
// (OpenMP threads that spin take the cores from the BLAS threads), OPENBLAS_THREAD_TIMEOUT and
// OMP_THREAD_LIMIT (one OpenMP thread per usable core; see the definition). If any was set, re-executes
// the program with the same arguments (does not return then); otherwise returns. Call first thing in
// main().
void use_fast_blas_kernel(char** argv);

// OpenBLAS's thread count (0 for another BLAS, whose threads are not ours to set).
int blas_threads();
// Sets OpenBLAS's thread count (nothing for another BLAS).
void set_blas_threads(int threads);

// OpenBLAS on one thread while this lives, then as before. For the triangular solves of a sparse
// factorisation: per supernode they call BLAS-2 kernels (a few hundred rows), which two threads only
// slow down by waking each other (see SparseDirectSolver::solve). Only where no other thread changes the
// count meanwhile: studies side by side run with one BLAS thread already (parallel_chains), and then this
// changes nothing.
class SingleBlasThread {
 public:
  SingleBlasThread() : previous_(blas_threads()) {
    if (previous_ > 1) set_blas_threads(1);
  }
  ~SingleBlasThread() {
    if (previous_ > 1) set_blas_threads(previous_);
  }
  SingleBlasThread(const SingleBlasThread&) = delete;
  SingleBlasThread& operator=(const SingleBlasThread&) = delete;

 private:
  int previous_;
};

}  // namespace tirefem
