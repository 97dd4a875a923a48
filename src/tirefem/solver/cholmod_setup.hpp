#pragma once
// What every CHOLMOD supernodal Cholesky of the project shares: its fill-reducing orderings, its supernode
// sizes, and the lock around the orderings.
#include <cholmod.h>

#include <mutex>

namespace tirefem {

// METIS (behind CHOLMOD's and UMFPACK's nested-dissection orderings) keeps its random generator in
// globals: two analyses at the same time (studies run side by side) would race on it and get orderings
// that differ from run to run, and so different round-off. Every fill-reducing ordering therefore holds
// this lock; they are computed once per solver, so nothing waits long.
inline std::mutex& ordering_mutex() {
  static std::mutex m;
  return m;
}

inline void use_tyre_factor_settings(cholmod_common& common) {
  // Fill-reducing ordering: the best (fewest flops) of minimum degree and two nested dissections. On the
  // tyre's shell meshes nested dissection wins: 120 × 46 half model, AMD 2.2, METIS 1.77, NESDIS 1.71 GFlop
  // per factorisation. The analysis is done once per solver, the factorisations many times.
  common.nmethods = 3;
  common.method[0].ordering = CHOLMOD_AMD;
  common.method[1].ordering = CHOLMOD_METIS;
  common.method[2].ordering = CHOLMOD_NESDIS;
  common.postorder = 1;
  // Larger supernodes than CHOLMOD's default (nrelax 4/16/48: columns merged into a supernode when it has
  // fewer than that many, given few enough explicit zeros): the dense BLAS kernels then work on bigger
  // blocks. Measured on the tangent of the 120 × 46 half model (32 880 equations), standalone, best of 4:
  // factorisation 0.28–0.34 → 0.22 s, factor 8.5 → 9.7 M entries, solve unchanged (8–9 ms); on the
  // symmetric part of the 80 × 46 full model's rolling tangent (43 680): 0.47–0.49 → 0.39–0.44 s.
  common.nrelax[0] = 8;
  common.nrelax[1] = 64;
  common.nrelax[2] = 256;
}

}  // namespace tirefem
