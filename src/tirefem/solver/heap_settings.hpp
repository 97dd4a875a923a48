#pragma once
// How the C library's allocator treats the large blocks the solvers allocate and free at every step
// (GMRES workspaces, UMFPACK's numeric objects, CHOLMOD's transposes and workspaces, assembly buffers).
#include <string>

namespace tirefem {

// Unless the user tunes the allocator (GLIBC_TUNABLES): blocks up to 512 MiB come from the heap rather
// than from fresh mappings, and up to 1 GiB of freed memory is kept rather than handed back to the
// system, so a block freed by one step is reused by the next without the system clearing its pages
// again. Call first thing in main(), before threads start. Nothing on other C libraries. Returns
// what it did, in a few words (the bench prints it).
std::string keep_freed_memory();

}  // namespace tirefem
