#include "tirefem/element/element_geometry.hpp"

#include <cmath>

#include "tirefem/element/shape_functions.hpp"

namespace tirefem {
namespace {

struct LocalFrame {
  Eigen::Vector3d e1, e2, e3;
};

// Orthonormal frame with e3 along `normal` and e1 the projection of `axis1` onto the tangent plane.
LocalFrame tangent_frame(const Eigen::Vector3d& normal, const Eigen::Vector3d& axis1) {
  LocalFrame f;
  f.e3 = normal.normalized();
  f.e1 = (axis1 - axis1.dot(f.e3) * f.e3).normalized();
  f.e2 = f.e3.cross(f.e1);
  return f;
}

// Mid-surface tangents and director of the interlayer as weights over the 8 nodes.
struct CoreWeights {
  NodeWeights mid_xi, mid_eta, director;
};

CoreWeights core_weights(double xi, double eta) {
  const BilinearShape s = bilinear_shape(xi, eta);
  CoreWeights w;
  for (int a = 0; a < 4; ++a) {
    w.mid_xi[a] = w.mid_xi[a + 4] = 0.5 * s.dn_dxi[a];
    w.mid_eta[a] = w.mid_eta[a + 4] = 0.5 * s.dn_deta[a];
    w.director[a] = -s.n[a];
    w.director[a + 4] = s.n[a];
  }
  return w;
}

TyingWeights make_tying_weights() {
  TyingWeights t;
  const auto set = [&](int k, const NodeWeights& alpha, const NodeWeights& beta) {
    t.alpha[k] = alpha;
    t.beta[k] = beta;
  };
  const CoreWeights a = core_weights(0.0, 1.0), c = core_weights(0.0, -1.0);
  const CoreWeights b = core_weights(-1.0, 0.0), d = core_weights(1.0, 0.0);
  set(0, a.mid_xi, a.director);
  set(1, c.mid_xi, c.director);
  set(2, b.mid_eta, b.director);
  set(3, d.mid_eta, d.director);
  for (int corner = 0; corner < 4; ++corner) {
    const CoreWeights w = core_weights(kCornerXi[corner], kCornerEta[corner]);
    set(4 + corner, w.director, w.director);
  }
  return t;
}

// EAS-4 of a face at (ξ, η): Ẽ = (j0/j) Σ Ê_ij G0^i ⊗ G0^j with Ê_ξξ = ξ α1, Ê_ηη = η α2,
// 2Ê_ξη = ξ α3 + η α4, in the point's local frame: with c_ai = e_a · G0^i,
// E_ab = Σ_ij c_ai c_bj Ê_ij.
Eigen::Matrix<double, 3, 4> enhanced_strain_map(const Eigen::Vector3d& g1_centre, const Eigen::Vector3d& g2_centre,
                                                const LocalFrame& frame, double xi, double eta, double area_scale) {
  Eigen::Matrix2d metric;
  metric << g1_centre.dot(g1_centre), g1_centre.dot(g2_centre), g2_centre.dot(g1_centre), g2_centre.dot(g2_centre);
  const Eigen::Matrix2d inverse = metric.inverse();
  const Eigen::Vector3d contra1 = inverse(0, 0) * g1_centre + inverse(0, 1) * g2_centre;
  const Eigen::Vector3d contra2 = inverse(1, 0) * g1_centre + inverse(1, 1) * g2_centre;
  const double c11 = frame.e1.dot(contra1), c12 = frame.e1.dot(contra2);
  const double c21 = frame.e2.dot(contra1), c22 = frame.e2.dot(contra2);
  // Local strains per unit Ê_ξξ, Ê_ηη and 2Ê_ξη.
  const Eigen::Vector3d per_xixi(c11 * c11, c21 * c21, 2 * c11 * c21);
  const Eigen::Vector3d per_etaeta(c12 * c12, c22 * c22, 2 * c12 * c22);
  const Eigen::Vector3d per_shear(c11 * c12, c21 * c22, c11 * c22 + c12 * c21);
  const double scale = g1_centre.cross(g2_centre).norm() / area_scale;  // j0 / j
  Eigen::Matrix<double, 3, 4> m;
  m.col(0) = scale * xi * per_xixi;
  m.col(1) = scale * eta * per_etaeta;
  m.col(2) = scale * xi * per_shear;
  m.col(3) = scale * eta * per_shear;
  return m;
}

}  // namespace

const TyingWeights& tying_weights() {
  static const TyingWeights weights = make_tying_weights();  // constants of the element, built once
  return weights;
}

FaceGeometry face_geometry(const NodeMatrix& reference, int offset, double xi, double eta) {
  const BilinearShape s = bilinear_shape(xi, eta);
  const BilinearShape centre = bilinear_shape(0.0, 0.0);
  Eigen::Vector3d g1 = Eigen::Vector3d::Zero(), g2 = Eigen::Vector3d::Zero(),
                  g1_centre = Eigen::Vector3d::Zero(), g2_centre = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) {
    g1 += s.dn_dxi[a] * reference.col(offset + a);
    g2 += s.dn_deta[a] * reference.col(offset + a);
    g1_centre += centre.dn_dxi[a] * reference.col(offset + a);
    g2_centre += centre.dn_deta[a] * reference.col(offset + a);
  }
  const Eigen::Vector3d normal = g1.cross(g2);
  const LocalFrame frame = tangent_frame(normal, g1_centre);
  Eigen::Matrix2d j;  // j(α, i) = G_α · e_i
  j << g1.dot(frame.e1), g1.dot(frame.e2), g2.dot(frame.e1), g2.dot(frame.e2);
  const Eigen::Matrix2d j_inv = j.inverse();
  FaceGeometry g;
  for (int a = 0; a < 4; ++a) {
    const Eigen::Vector2d d = j_inv * Eigen::Vector2d(s.dn_dxi[a], s.dn_deta[a]);
    g.d1[a] = d[0];
    g.d2[a] = d[1];
  }
  g.area_scale = normal.norm();
  g.e1 = frame.e1;
  g.e2 = frame.e2;
  g.enhanced = enhanced_strain_map(g1_centre, g2_centre, frame, xi, eta, g.area_scale);
  return g;
}

CoreGeometry core_geometry(const NodeMatrix& reference, double xi, double eta) {
  const CoreWeights w = core_weights(xi, eta);
  const CoreWeights centre = core_weights(0.0, 0.0);
  Eigen::Matrix3d jac;
  jac.col(0) = reference * w.mid_xi;
  jac.col(1) = reference * w.mid_eta;
  jac.col(2) = reference * w.director;
  const Eigen::Vector3d normal = jac.col(0).cross(jac.col(1));
  const double orientation = normal.dot(jac.col(2)) >= 0.0 ? 1.0 : -1.0;
  const LocalFrame frame = tangent_frame(orientation * normal, reference * centre.mid_xi);
  Eigen::Matrix3d rot;
  rot << frame.e1, frame.e2, frame.e3;
  const Eigen::Matrix3d c = jac.inverse() * rot;  // c(k, i) = G^k · e_i

  // Assumed covariant strains: E_ξζ, E_ηζ interpolated from the edge midpoints, E_ζζ from the corners.
  Eigen::Matrix<double, 3, kTyingStrains> interpolation = Eigen::Matrix<double, 3, kTyingStrains>::Zero();
  interpolation(0, 0) = 0.5 * (1 + eta);
  interpolation(0, 1) = 0.5 * (1 - eta);
  interpolation(1, 2) = 0.5 * (1 - xi);
  interpolation(1, 3) = 0.5 * (1 + xi);
  const BilinearShape s = bilinear_shape(xi, eta);
  for (int a = 0; a < 4; ++a) interpolation(2, 4 + a) = s.n[a];

  // Local transverse components from the covariant ones, E_i3 = Σ c_ki c_l3 E_kl over the transverse
  // covariant components only (the faces carry the in-plane strains); rows γ13, γ23, E33 on E_ξζ, E_ηζ, E_ζζ.
  Eigen::Matrix3d to_local;
  for (int i = 0; i < 2; ++i)
    to_local.row(i) << 2 * (c(0, i) * c(2, 2) + c(2, i) * c(0, 2)), 2 * (c(1, i) * c(2, 2) + c(2, i) * c(1, 2)),
        2 * c(2, i) * c(2, 2);
  to_local.row(2) << 2 * c(0, 2) * c(2, 2), 2 * c(1, 2) * c(2, 2), c(2, 2) * c(2, 2);

  CoreGeometry g;
  g.coefficients = to_local * interpolation;
  g.volume_scale = std::abs(jac.determinant());
  return g;
}

ElementGeometry element_geometry(const NodeMatrix& reference) {
  ElementGeometry g;
  for (int p = 0; p < 4; ++p) {
    const auto& gp = kGauss2x2[p];
    g.inner[p] = face_geometry(reference, 0, gp[0], gp[1]);
    g.outer[p] = face_geometry(reference, 4, gp[0], gp[1]);
    g.core[p] = core_geometry(reference, gp[0], gp[1]);
  }
  return g;
}

}  // namespace tirefem
