#pragma once
// The rubber layers of a face at large strain: an incompressible neo-Hookean membrane in plane stress.
// The paper's faces are linear in the Green–Lagrange strain E (St. Venant–Kirchhoff); in compression that
// law loses its stiffness (uniaxially dN/dλ = E t (3λ² − 1)/2, a third of E t at λ = 0.75, none at
// λ = 0.58), which rubber does not. With C = I + 2E (face axes 1, 2 orthonormal in the reference) and the
// thickness stretch λ3² = 1/det C that incompressibility gives, the energy per unit reference area is
//   W = ½ μt (C11 + C22 + 1/det C − 3),
// whose second derivative at E = 0 is the St. Venant–Kirchhoff face of ν = 1/2, E = 3μ (for a layer given
// with ν = 0.49 and μ = E/2(1 + ν), 2% stiffer in A11 than its linear face).
#include <Eigen/Dense>

namespace tirefem {

struct RubberMembraneTerms {
  double energy = 0.0;                                   // W, N/mm
  Eigen::Vector3d resultant = Eigen::Vector3d::Zero();   // ∂W/∂[E11, E22, 2E12]: the face's N, N/mm
  Eigen::Matrix3d stiffness = Eigen::Matrix3d::Zero();   // ∂²W/∂[E11, E22, 2E12]², N/mm
};

// Below det C = kRubberMinDetC (det C is the square of the area ratio: the face squeezed to a tenth of its
// area, which no converged state reaches but a wild Newton iterate may) 1/det C is continued by its
// second-order Taylor expansion, so the energy stays finite and convex in det C.
inline constexpr double kRubberMinDetC = 1e-2;

// `strain`: [E11, E22, 2E12]; `shear_stiffness`: μ t, N/mm.
RubberMembraneTerms rubber_membrane(const Eigen::Vector3d& strain, double shear_stiffness);

}  // namespace tirefem
