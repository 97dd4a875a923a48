#pragma once
// How big the linear systems of a mesh get, before building it: the DOF count (exact) and the memory of a
// sparse factorisation (an estimate), to refuse meshes the machine cannot hold.
#include "tirefem/case/case.hpp"

namespace tirefem {

struct MeshSizeEstimate {
  double elements = 0;        // shell elements
  double dof = 0;             // 6 per node pair (inner and outer face node), constrained ones included
  double factor_nonzeros = 0; // of an LU factor (the rolling tangent is unsymmetric; Cholesky is half)
  double bytes = 0;           // memory of the factorisation and its workspace
};

// Node pairs: circumferential_elements (closed ring) × (meridional elements + 1), the meridional count
// doubled in the full model (bead to bead). The factor is scaled from a measured figure, the 120 × 46
// half model (33 840 DOF, a Cholesky factor of ~5.8e6 nonzeros with nested dissection), by n log n (nested
// dissection on a 2D mesh), doubled for LU; 12 bytes per nonzero (value and row index) and 50% for
// workspace and the assembled matrix.
MeshSizeEstimate estimate_mesh_size(const MeshSettings& m);

// Physical memory of this machine, bytes (0 if unknown).
double physical_memory_bytes();

}  // namespace tirefem
