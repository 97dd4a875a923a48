#pragma once
// The element's strains as they were formed before the assembly was sped up (kept for the tests only, as
// the reference the faster element must reproduce to round-off).
// A Green–Lagrange strain component of the three-layer element written as
//   E = ½ (a·b − A·B),   a = Σ α_k x_k,  b = Σ β_k x_k  (current),  A, B the same on the reference,
// over the element's 8 nodes. Every strain of the element (face membrane strains, interlayer covariant
// shears and thickness strain) has this form, so value, gradient and Hessian come from one place and the
// tangent is exact by construction. Linear combinations (assumed-strain interpolation, change of frame)
// stay in the same type.
#include "tirefem/element/element_geometry.hpp"

namespace tirefem::reference {

struct StrainComponent {
  double value = 0.0;
  ElementVector gradient = ElementVector::Zero();  // dE / d(nodal displacement)
  // d²E/dx_k dx_l = hessian(k, l) · I3 (zero in the linear theory)
  Eigen::Matrix<double, kElementNodes, kElementNodes> hessian =
      Eigen::Matrix<double, kElementNodes, kElementNodes>::Zero();

  StrainComponent& add_scaled(const StrainComponent& other, double factor) {
    value += factor * other.value;
    gradient += factor * other.gradient;
    hessian += factor * other.hessian;
    return *this;
  }
};

// E = ½(a·b − A·B). In the linear theory the quadratic part in the displacement is dropped:
// E = ½(A·(u_β) + (u_α)·B) with u_α = Σ α_k u_k.
inline StrainComponent bilinear_strain(const NodeWeights& alpha, const NodeWeights& beta,
                                       const NodeMatrix& reference, const NodeMatrix& current,
                                       Kinematics kinematics) {
  const Eigen::Vector3d A = reference * alpha;
  const Eigen::Vector3d B = reference * beta;
  // The value is formed from the displacements, ½(A·u_β + u_α·B + u_α·u_β), not as a difference of
  // position products, which would lose the digits of a small strain to cancellation.
  const NodeMatrix u = current - reference;
  const Eigen::Vector3d ua = u * alpha;
  const Eigen::Vector3d ub = u * beta;
  StrainComponent e;
  if (kinematics == Kinematics::nonlinear) {
    const Eigen::Vector3d a = A + ua;
    const Eigen::Vector3d b = B + ub;
    e.value = 0.5 * (A.dot(ub) + ua.dot(B) + ua.dot(ub));
    for (int k = 0; k < kElementNodes; ++k)
      e.gradient.segment<3>(3 * k) = 0.5 * (alpha[k] * b + beta[k] * a);
    e.hessian = 0.5 * (alpha * beta.transpose() + beta * alpha.transpose());
  } else {
    e.value = 0.5 * (A.dot(ub) + ua.dot(B));
    for (int k = 0; k < kElementNodes; ++k)
      e.gradient.segment<3>(3 * k) = 0.5 * (alpha[k] * B + beta[k] * A);
  }
  return e;
}

}  // namespace tirefem::reference
