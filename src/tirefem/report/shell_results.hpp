#pragma once
// Derived results of the tyre shell at element centres: face strains and stress resultants in the
// meridional/circumferential frame, strain and tension of the cords of every ply, interlayer shear.
#include <vector>

#include "tirefem/case/case.hpp"
#include "tirefem/element/three_layer_element.hpp"
#include "tirefem/tyre/tyre_mesh.hpp"

namespace tirefem {

struct FaceCordResults {
  std::vector<double> strain;   // engineering strain along the cords of each ply of the face
  std::vector<double> force_N;  // tension per cord, N
};

struct ElementResult {
  ElementPointState state;  // at the element centre (ξ = η = 0)
  FaceCordResults inner_cords, outer_cords;
  Eigen::Vector2d core_shear_stress = Eigen::Vector2d::Zero();  // τ13, τ23, MPa
};

std::vector<ElementResult> evaluate_element_results(const TyreMesh& tyre_mesh,
                                                    const TyreDescription& tyre,
                                                    const Eigen::VectorXd& displacement,
                                                    Kinematics kinematics);

// Engineering strain from a Green–Lagrange normal strain (the linear theory's strain is returned as is).
double engineering_strain(double green_strain, Kinematics kinematics);

// Displacement of a node split into the lateral (x), radial and circumferential parts at angle φ.
struct CylindricalDisplacement {
  double lateral, radial, circumferential;
};
CylindricalDisplacement cylindrical_displacement(const Eigen::Vector3d& u, double phi);

}  // namespace tirefem
