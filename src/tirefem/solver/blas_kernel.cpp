#include "tirefem/solver/blas_kernel.hpp"

#include <dlfcn.h>
#include <sched.h>
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <string>

namespace tirefem {
namespace {

// Looked up at run time: the BLAS behind libblas.so.3 is chosen by the system (Debian's alternatives),
// and only OpenBLAS has these functions.
const char* openblas_string(const char* function) {
  using Getter = char* (*)();
  const auto getter = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, function));
  return getter ? getter() : nullptr;
}

std::string trimmed(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  return s;
}

bool generic_kernel(const std::string& core) {
  std::string lower;
  for (char c : core) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "prescott" || lower == "core2" || lower == "nehalem" || lower.empty();
}

// The processors this process may run on (its affinity mask), 0 if unknown.
int usable_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  return sched_getaffinity(0, sizeof(set), &set) == 0 ? CPU_COUNT(&set) : 0;
}

}  // namespace

BlasKernel blas_kernel() {
  BlasKernel k;
  const char* config = openblas_string("openblas_get_config");
  const char* core = openblas_string("openblas_get_corename");
  k.library = config ? trimmed(std::string("OpenBLAS ") + config) : "unknown BLAS (not OpenBLAS)";
  k.core = core ? core : "";
  k.forced = std::getenv("OPENBLAS_CORETYPE") != nullptr;
  return k;
}

std::string best_kernel_for_this_cpu() {
#if defined(__x86_64__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl"))
    return "SkylakeX";
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return "Haswell";
  if (__builtin_cpu_supports("avx")) return "Sandybridge";
#endif
  return "";
}

int blas_threads() {
  using Getter = int (*)();
  // Looked up once (the library does not change while the program runs): called around every solve.
  static const auto get = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  return get ? get() : 0;
}

void set_blas_threads(int threads) {
  using Setter = void (*)(int);
  static const auto set = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (set && threads > 0) set(threads);
}

void use_fast_blas_kernel(char** argv) {
  bool changed = false;
  // OpenMP's idle threads spin (libgomp's default) while OpenBLAS's own threads factorise, and the
  // other way round: on 2 cores they take the cores from each other. Passive waiting, measured on the
  // inflation of the example (120 × 46): 0.31 → 0.19–0.21 s per factorisation, system time 2.3–3.4 →
  // 0.6–0.7 s, wall 4.8–6.0 → 3.7–4.2 s. It can only be chosen before libgomp loads, like the kernel.
  if (!std::getenv("OMP_WAIT_POLICY")) {
    setenv("OMP_WAIT_POLICY", "passive", 1);
    changed = true;
  }
  // OpenBLAS's idle threads do the same: after each BLAS call they spin on sched_yield for 2^28 cycles
  // (about 0.1 s) before they sleep, and the solver calls BLAS in short bursts (each supernode of each
  // factorisation, each triangular solve), so they hardly ever sleep. 2^4 cycles lets them sleep at once.
  // Measured on the example's plane load curve (120 × 46, 3 paired runs, medians): system time 33.9 →
  // 8.2 s, CPU time 89.6 → 57.4 s, wall 46.6 → 43.8 s.
  if (!std::getenv("OPENBLAS_THREAD_TIMEOUT")) {
    setenv("OPENBLAS_THREAD_TIMEOUT", "4", 1);
    changed = true;
  }
  // CHOLMOD's supernodal factorisation runs small OpenMP loops (scattering each update into its
  // supernode) on a team of 4 threads fixed when Debian built it, whatever the cores or OMP_NUM_THREADS:
  // on 2 cores, with passive waiting, every supernode then wakes 3 sleeping threads. A limit of one
  // OpenMP thread per core the process may use caps those teams (and two studies side by side, each
  // factorising). Measured on 2 cores: the load-curve bench 24.1 → 20.5 s wall, system time 7.3 → 4.5 s
  // (3 paired runs, medians); the example 2.06 M → 0.68 M voluntary context switches in one run each,
  // and 88.5 → 80.9 s wall in 2 paired runs (medians; its runs differ by more than that).
  if (!std::getenv("OMP_THREAD_LIMIT")) {
    if (const int cores = usable_cores(); cores > 0) {
      setenv("OMP_THREAD_LIMIT", std::to_string(cores).c_str(), 1);
      changed = true;
    }
  }
  const BlasKernel k = blas_kernel();
  // The user's (or an earlier pass's) choice of kernel stands.
  if (!std::getenv("OPENBLAS_CORETYPE") && k.library.rfind("OpenBLAS", 0) == 0 && generic_kernel(k.core)) {
    const std::string best = best_kernel_for_this_cpu();
    if (!best.empty()) {
      setenv("OPENBLAS_CORETYPE", best.c_str(), 1);
      changed = true;
    }
  }
  if (changed) execv("/proc/self/exe", argv);
  // execv failed (no /proc): carry on as loaded; the bench and summary.json name the kernel.
}

}  // namespace tirefem
