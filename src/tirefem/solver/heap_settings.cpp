#include "tirefem/solver/heap_settings.hpp"

#include <cstdlib>

#include <fmt/format.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace tirefem {

namespace {
// glibc maps each block above its mmap threshold (128 KB at first, raised as such blocks are freed, to
// at most 32 MB) afresh and unmaps it when freed, and it gives the free top of a heap back to the system
// above its trim threshold. Every Newton step allocates blocks of that size (e.g. GMRES's Krylov basis,
// n × 26 doubles; each LU's numeric object), so every step faulted its pages in again, and a page fault
// is expensive on a virtual machine. Measured on the whole example (2 cores, studies side by side on two
// worker threads), 3 paired runs against glibc's defaults, medians: wall 70.6 → 57.7 s, system time
// 16.2 → 6.5 s, peak memory 611 → 652 MiB; page faults 1.9 M → 0.32 M in one run each
// (docs/benchmark-log.md, "The allocator keeps freed memory").
constexpr int kMiB = 1 << 20;
constexpr int kKeptBlockBytes = 512 * kMiB;  // the mmap threshold
constexpr int kKeptFreeBytes = 1024 * kMiB;  // the trim threshold
bool tuned_by_user() { return std::getenv("GLIBC_TUNABLES") != nullptr; }
}  // namespace

std::string keep_freed_memory() {
#if defined(__GLIBC__)
  if (tuned_by_user()) return "glibc as GLIBC_TUNABLES sets it";
  if (mallopt(M_MMAP_THRESHOLD, kKeptBlockBytes) == 1 && mallopt(M_TRIM_THRESHOLD, kKeptFreeBytes) == 1)
    return fmt::format("glibc, blocks up to {} MiB from the heap, freed memory kept up to {} MiB",
                       kKeptBlockBytes / kMiB, kKeptFreeBytes / kMiB);
  return "glibc's defaults (its settings were refused)";
#else
  return "the C library's defaults";
#endif
}

}  // namespace tirefem
