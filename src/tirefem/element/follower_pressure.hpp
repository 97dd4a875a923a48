#pragma once
// Follower pressure on the inner (carcass) face of a three-layer element: the load acts along the current
// normal of the face, pointing from the inner towards the outer face, on the current area.
#include "tirefem/element/strain_component.hpp"

namespace tirefem {

struct PressureLoad {
  ElementVector force = ElementVector::Zero();    // external nodal force (inner-face nodes only)
  ElementMatrix tangent = ElementMatrix::Zero();  // ∂force/∂f (load stiffness; not symmetric)
};

// Linear theory: the load acts on the reference geometry and has no load stiffness.
PressureLoad follower_pressure(const NodeMatrix& reference, const NodeMatrix& current, double pressure,
                               Kinematics kinematics, bool with_tangent = true);

}  // namespace tirefem
