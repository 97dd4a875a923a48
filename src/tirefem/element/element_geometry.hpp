#pragma once
// What the three-layer element (MODEL.md §3) needs of its reference configuration at an integration
// point: the faces' shape-function derivatives in their local frames and area scales, and the interlayer's
// map from the covariant tying strains to the local transverse strains with its volume scale. It depends
// on the reference positions only, so the internal-force form computes it once per element, not at every
// assembly.
#include <array>

#include <Eigen/Dense>

namespace tirefem {

inline constexpr int kElementNodes = 8;
inline constexpr int kElementDofs = 24;

using ElementVector = Eigen::Matrix<double, kElementDofs, 1>;
using ElementMatrix = Eigen::Matrix<double, kElementDofs, kElementDofs>;
using NodeWeights = Eigen::Matrix<double, kElementNodes, 1>;
using NodeMatrix = Eigen::Matrix<double, 3, kElementNodes>;  // columns: node positions

enum class Kinematics { nonlinear, linear };

// A face at one point: E_ij = ½(x_,i · x_,j − X_,i · X_,j) with x_,i = Σ d_i[a] x_a over the face's 4 nodes.
struct FaceGeometry {
  Eigen::Vector4d d1, d2;      // ∂N_a/∂X_1, ∂N_a/∂X_2 in the face's local frame
  double area_scale = 0.0;     // |G1 × G2|
  Eigen::Vector3d e1, e2;      // the local frame's in-plane axes (1 along ξ)
  // The face's enhanced assumed strains (Simo–Rifai EAS-4) at this point: local [E11, E22, 2E12] per unit
  // enhanced parameter, (j0/j) G0^i ⊗ G0^j components of Ê_ξξ = ξ α1, Ê_ηη = η α2, 2Ê_ξη = ξ α3 + η α4
  // (G0^i the contravariant base at the face centre). They integrate to zero over the face.
  Eigen::Matrix<double, 3, 4> enhanced = Eigen::Matrix<double, 3, 4>::Zero();
};

// The interlayer's 8 covariant tying strains E_t = ½(a_t · b_t − A_t · B_t), a_t = Σ α_t[k] x_k,
// b_t = Σ β_t[k] x_k (Dvorkin–Bathe for the shears, Betsch–Stein for the thickness strain): E_ξζ at
// A(0, 1), C(0, −1); E_ηζ at B(−1, 0), D(1, 0); E_ζζ at the 4 corners. ζ ∈ [0, 1] runs from the inner to
// the outer face, so g_ζ is the director x_outer − x_inner.
inline constexpr int kTyingStrains = 8;
struct TyingWeights {
  std::array<NodeWeights, kTyingStrains> alpha, beta;
};
const TyingWeights& tying_weights();

// The interlayer at one point: its local strains [γ13, γ23, E33] = coefficients · tying strains.
struct CoreGeometry {
  Eigen::Matrix<double, 3, kTyingStrains> coefficients;
  double volume_scale = 0.0;  // |det J|, J = [A_ξ A_η D]
};

FaceGeometry face_geometry(const NodeMatrix& reference, int offset, double xi, double eta);
CoreGeometry core_geometry(const NodeMatrix& reference, double xi, double eta);

// Both faces and the interlayer at the 2 × 2 Gauss points.
struct ElementGeometry {
  std::array<FaceGeometry, 4> inner, outer;
  std::array<CoreGeometry, 4> core;
};
ElementGeometry element_geometry(const NodeMatrix& reference);

}  // namespace tirefem
