#pragma once
// Follower pressure on the inner (carcass) face of a three-layer element: the load acts along the current
// normal of the face, pointing from the inner towards the outer face, on the current area.
#include "tirefem/element/element_geometry.hpp"

namespace tirefem {

struct PressureLoad {
  ElementVector force = ElementVector::Zero();    // external nodal force (inner-face nodes only)
  ElementMatrix tangent = ElementMatrix::Zero();  // ∂force/∂f (load stiffness; not symmetric)
};

// Linear theory: the load acts on the reference geometry and has no load stiffness.
PressureLoad follower_pressure(const NodeMatrix& reference, const NodeMatrix& current, double pressure,
                               Kinematics kinematics, bool with_tangent = true);

// ⅓ ∫ x·n dA over the inner face (x absolute positions, n oriented like the load): summed over a closed
// surface, the enclosed volume V (MODEL.md §8), whose gradient is the follower load per unit pressure.
// The 2 × 2 Gauss rule integrates this bilinear-surface integrand (degree 2 in each direction) exactly.
double enclosed_volume_part(const NodeMatrix& reference, const NodeMatrix& current);

}  // namespace tirefem
