#pragma once
// Carrying a displacement field from one mesh of a tyre to another with the same meridional stations (node
// columns) and other circumferential ones (node rows): the inflated state (axisymmetric) onto any such
// mesh, and a deformed state (a footprint) onto a mesh of the same kind by interpolation round the axis.
#include <Eigen/Dense>

#include "tirefem/tyre/tyre_mesh.hpp"

namespace tirefem {

// The displacement of `from`'s first node row turned onto every node row of `to` (meshes of one tyre with
// the same meridional stations; throws otherwise): an axisymmetric state carried to another mesh. A half
// model's state goes onto the full model of its stations as itself and its mirror image (a state symmetric
// about the wheel plane, as the inflated one is).
Eigen::VectorXd turned_onto(const TyreMesh& from, const Eigen::VectorXd& displacement, const TyreMesh& to);
// Whether turned_onto carries a state of `from` onto `to`.
bool turns_onto(const TyreMesh& from, const TyreMesh& to);
// A state of `from` interpolated onto `to`, both half models or both full models with the same meridional
// stations (throws otherwise): each node of `to` takes the displacements of the two nodes of its column in
// `from` on either side of its angle round the axis, each turned about the axis to that angle, weighted
// linearly in the angle. A start for Newton on `to` near the state of `from`, not a solution of its own.
Eigen::VectorXd interpolated_onto(const TyreMesh& from, const Eigen::VectorXd& displacement, const TyreMesh& to);
// Whether interpolated_onto carries a state of `from` onto `to`.
bool interpolates_onto(const TyreMesh& from, const TyreMesh& to);
// A half model's state (any, not only an axisymmetric one) onto the full model of the same meridional and
// circumferential stations: each node takes its own node's displacement, the mirror side its mirror image
// (x → −x). Exact: a state of the half model is the symmetric state of the full model. Throws when
// mirrors_onto is false.
Eigen::VectorXd mirrored_onto(const TyreMesh& from, const Eigen::VectorXd& displacement, const TyreMesh& to);
bool mirrors_onto(const TyreMesh& from, const TyreMesh& to);

}  // namespace tirefem
