#include "tirefem/case/mesh_size_estimate.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace tirefem {

MeshSizeEstimate estimate_mesh_size(const MeshSettings& m) {
  constexpr double kReferenceDof = 33840.0;        // 120 × 46 half model
  constexpr double kReferenceCholesky = 5.8e6;     // its Cholesky factor's nonzeros
  constexpr double kBytesPerNonzero = 12.0;
  constexpr double kWorkspace = 1.5;
  MeshSizeEstimate e;
  const double circumferential = m.circumferential_elements;
  const double meridional = (m.half_model ? 1.0 : 2.0) * m.meridional_elements;
  e.elements = circumferential * meridional;
  e.dof = 6.0 * circumferential * (meridional + 1.0);
  const double n = std::max(e.dof, 2.0);
  const double cholesky = kReferenceCholesky * (n * std::log(n)) / (kReferenceDof * std::log(kReferenceDof));
  e.factor_nonzeros = 2.0 * cholesky;
  e.bytes = kWorkspace * kBytesPerNonzero * e.factor_nonzeros;
  return e;
}

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return 0.0;
  return static_cast<double>(pages) * static_cast<double>(page);
}

}  // namespace tirefem
