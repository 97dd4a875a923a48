#pragma once
// Bilinear shape functions of a quadrilateral face, nodes counter-clockwise from (−1, −1).
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace tirefem {

inline constexpr std::array<double, 4> kCornerXi{-1.0, 1.0, 1.0, -1.0};
inline constexpr std::array<double, 4> kCornerEta{-1.0, -1.0, 1.0, 1.0};

struct BilinearShape {
  Eigen::Vector4d n;       // N_a
  Eigen::Vector4d dn_dxi;  // ∂N_a/∂ξ
  Eigen::Vector4d dn_deta; // ∂N_a/∂η
};

inline BilinearShape bilinear_shape(double xi, double eta) {
  BilinearShape s;
  for (int a = 0; a < 4; ++a) {
    const double xa = kCornerXi[a], ya = kCornerEta[a];
    s.n[a] = 0.25 * (1 + xa * xi) * (1 + ya * eta);
    s.dn_dxi[a] = 0.25 * xa * (1 + ya * eta);
    s.dn_deta[a] = 0.25 * ya * (1 + xa * xi);
  }
  return s;
}

// 2 × 2 Gauss rule on [−1, 1]², unit weights.
inline constexpr double kGauss2 = 0.57735026918962576451;
inline constexpr std::array<std::array<double, 2>, 4> kGauss2x2{
    {{-kGauss2, -kGauss2}, {kGauss2, -kGauss2}, {kGauss2, kGauss2}, {-kGauss2, kGauss2}}};

}  // namespace tirefem

namespace tirefem {

// n-point Gauss–Legendre rule on [−1, 1] (Golub–Welsch: the nodes are the eigenvalues of the Jacobi
// matrix of the Legendre polynomials, the weights 2 × the squared first components of its eigenvectors).
struct GaussRule {
  std::vector<double> points, weights;
};
GaussRule gauss_legendre(int n);

}  // namespace tirefem
