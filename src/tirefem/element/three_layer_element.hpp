#pragma once
// The 8-node, 24-DOF three-layer shell element (MODEL.md §3, paper Fig. 9): two bilinear membrane faces
// (nodes 0–3 inner face = carcass, 4–7 outer face = breaker; node k + 4 lies above node k) and an
// interlayer with linear displacement through its thickness that works in transverse shear and in
// through-thickness extension. Total Lagrangian, Green–Lagrange strains; the interlayer shears use the
// assumed natural strains of Dvorkin–Bathe (tying points at the edge midpoints) and the thickness strain
// is tied at the corners (Betsch–Stein), so thin interlayers and curved meshes do not lock.
// [Kτ] = diag([Kτ^m1], [Kτ^m2]) + [K3].
#include "tirefem/element/section.hpp"
#include "tirefem/element/element_geometry.hpp"

namespace tirefem {

// Half-width of the cord strain band over which a cord family softer in compression (section.hpp) loses
// its stiffness: from all of it at ε_c = −δ to none at +δ. The force along the cords then differs from the
// bimodular law's by at most k δ / 4 (at ε_c = 0).
inline constexpr double kCordSofteningBand = 2.5e-4;

struct ElementResponse {
  double energy = 0.0;
  ElementVector force = ElementVector::Zero();    // internal force, ∂Π/∂f
  ElementMatrix tangent = ElementMatrix::Zero();  // ∂²Π/∂f²
};

// Reference and current nodal positions (columns 0–3 inner face, 4–7 outer face); `geometry` is
// element_geometry(reference), which a form computes once.
ElementResponse three_layer_element(const ElementGeometry& geometry, const NodeMatrix& reference,
                                    const NodeMatrix& current, const ElementSection& section,
                                    Kinematics kinematics, bool with_tangent = true);
inline ElementResponse three_layer_element(const NodeMatrix& reference, const NodeMatrix& current,
                                           const ElementSection& section, Kinematics kinematics,
                                           bool with_tangent = true) {
  return three_layer_element(element_geometry(reference), reference, current, section, kinematics, with_tangent);
}

// Strains and stresses at one point of the element, in the local frame (1 = ξ direction, 2, 3 = normal).
struct ElementPointState {
  Eigen::Vector3d inner_strain;     // Green–Lagrange [E11, E22, 2E12] of the inner face
  Eigen::Vector3d outer_strain;
  Eigen::Vector3d inner_resultant;  // N = A E, N/mm
  Eigen::Vector3d outer_resultant;
  Eigen::Vector2d core_shear;       // engineering transverse shear strains γ13, γ23 (assumed-strain)
  double core_normal_strain = 0.0;  // E33
  Eigen::Vector3d inner_axis1, inner_axis2;  // local frame of the inner face (reference configuration)
};

ElementPointState three_layer_point_state(const NodeMatrix& reference, const NodeMatrix& current,
                                          const ElementSection& section, Kinematics kinematics,
                                          double xi, double eta);

}  // namespace tirefem
