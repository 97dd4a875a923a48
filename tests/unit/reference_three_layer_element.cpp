// The three-layer element as it was before the reference geometry was cached and the interlayer's
// tangent formed from its tying strains (commit 23ee623): every strain a StrainComponent with a full
// 24-gradient and 8 × 8 Hessian. Kept for the tests only, as the reference the faster element must
// reproduce to round-off.
#include "reference_three_layer_element.hpp"

#include <array>
#include <cmath>

#include "reference_strain_component.hpp"
#include "tirefem/element/shape_functions.hpp"

namespace tirefem::reference {
namespace {

using Strain3 = std::array<StrainComponent, 3>;

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

// Adds the energy ½ εᵀ C ε w of one integration point, its gradient and its Hessian. The strains depend
// on nodes [first, first + count) only (a face: its 4 nodes; the interlayer: all 8), so only that block
// of the element's force and tangent is formed.
template <int First, int Count>
void accumulate(const Strain3& strain, const Eigen::Matrix3d& stiffness, double weight, bool with_tangent,
                ElementResponse& out) {
  constexpr int kDofs = 3 * Count;
  const Eigen::Vector3d eps(strain[0].value, strain[1].value, strain[2].value);
  const Eigen::Vector3d stress = stiffness * eps;
  out.energy += 0.5 * weight * eps.dot(stress);
  Eigen::Matrix<double, 3, kDofs> b;
  for (int c = 0; c < 3; ++c) b.row(c) = strain[c].gradient.template segment<kDofs>(3 * First).transpose();
  out.force.template segment<kDofs>(3 * First).noalias() += weight * b.transpose() * stress;
  if (!with_tangent) return;
  const Eigen::Matrix<double, 3, kDofs> cb = (weight * stiffness) * b;
  out.tangent.template block<kDofs, kDofs>(3 * First, 3 * First).noalias() += b.transpose() * cb;
  const Eigen::Matrix<double, Count, Count> geometric =
      weight * (stress[0] * strain[0].hessian.template block<Count, Count>(First, First) +
                stress[1] * strain[1].hessian.template block<Count, Count>(First, First) +
                stress[2] * strain[2].hessian.template block<Count, Count>(First, First));
  for (int k = 0; k < Count; ++k)
    for (int l = 0; l < Count; ++l) {
      const double g = geometric(k, l);
      if (g == 0.0) continue;
      for (int i = 0; i < 3; ++i) out.tangent(3 * (First + k) + i, 3 * (First + l) + i) += g;
    }
}

// ---- membrane faces --------------------------------------------------------------------------
struct FacePoint {
  Strain3 strain;  // [E11, E22, 2 E12] in the face's local frame
  double area_scale = 0.0;  // |G1 × G2|
  LocalFrame frame;
};

FacePoint face_point(const NodeMatrix& reference, const NodeMatrix& current, int offset, double xi,
                     double eta, Kinematics kinematics) {
  const BilinearShape s = bilinear_shape(xi, eta);
  const BilinearShape centre = bilinear_shape(0.0, 0.0);
  Eigen::Vector3d g1 = Eigen::Vector3d::Zero(), g2 = Eigen::Vector3d::Zero(),
                  g1_centre = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) {
    g1 += s.dn_dxi[a] * reference.col(offset + a);
    g2 += s.dn_deta[a] * reference.col(offset + a);
    g1_centre += centre.dn_dxi[a] * reference.col(offset + a);
  }
  const Eigen::Vector3d normal = g1.cross(g2);
  FacePoint p;
  p.area_scale = normal.norm();
  p.frame = tangent_frame(normal, g1_centre);
  Eigen::Matrix2d j;  // j(α, i) = G_α · e_i
  j << g1.dot(p.frame.e1), g1.dot(p.frame.e2), g2.dot(p.frame.e1), g2.dot(p.frame.e2);
  const Eigen::Matrix2d j_inv = j.inverse();
  NodeWeights d1 = NodeWeights::Zero(), d2 = NodeWeights::Zero();  // ∂N/∂X_1, ∂N/∂X_2
  for (int a = 0; a < 4; ++a) {
    const Eigen::Vector2d d = j_inv * Eigen::Vector2d(s.dn_dxi[a], s.dn_deta[a]);
    d1[offset + a] = d[0];
    d2[offset + a] = d[1];
  }
  p.strain[0] = bilinear_strain(d1, d1, reference, current, kinematics);
  p.strain[1] = bilinear_strain(d2, d2, reference, current, kinematics);
  p.strain[2] = bilinear_strain(d1, d2, reference, current, kinematics);
  p.strain[2].add_scaled(p.strain[2], 1.0);  // engineering shear 2 E12
  return p;
}

// ---- interlayer --------------------------------------------------------------------------------
// Covariant strains of the interlayer at its mid-surface: E_ξζ, E_ηζ, E_ζζ with ζ ∈ [0, 1]
// running from the inner to the outer face (so g_ζ is the director d = x_outer − x_inner).
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

struct CoreTying {
  StrainComponent xi_zeta_a, xi_zeta_c;     // E_ξζ at A(0, 1), C(0, −1)
  StrainComponent eta_zeta_b, eta_zeta_d;   // E_ηζ at B(−1, 0), D(1, 0)
  std::array<StrainComponent, 4> zeta_zeta; // E_ζζ at the corners
};

CoreTying core_tying(const NodeMatrix& reference, const NodeMatrix& current, Kinematics kinematics) {
  CoreTying t;
  auto xi_zeta = [&](double xi, double eta) {
    const CoreWeights w = core_weights(xi, eta);
    return bilinear_strain(w.mid_xi, w.director, reference, current, kinematics);
  };
  auto eta_zeta = [&](double xi, double eta) {
    const CoreWeights w = core_weights(xi, eta);
    return bilinear_strain(w.mid_eta, w.director, reference, current, kinematics);
  };
  t.xi_zeta_a = xi_zeta(0.0, 1.0);
  t.xi_zeta_c = xi_zeta(0.0, -1.0);
  t.eta_zeta_b = eta_zeta(-1.0, 0.0);
  t.eta_zeta_d = eta_zeta(1.0, 0.0);
  for (int a = 0; a < 4; ++a) {
    const CoreWeights w = core_weights(kCornerXi[a], kCornerEta[a]);
    t.zeta_zeta[a] = bilinear_strain(w.director, w.director, reference, current, kinematics);
  }
  return t;
}

struct CorePoint {
  Strain3 strain;      // [γ13, γ23, E33] physical, local frame
  double volume_scale; // |det J|, J = [A_ξ A_η D]
  LocalFrame frame;
};

CorePoint core_point(const NodeMatrix& reference, const CoreTying& tying, double xi, double eta) {
  const CoreWeights w = core_weights(xi, eta);
  const CoreWeights centre = core_weights(0.0, 0.0);
  Eigen::Matrix3d jac;
  jac.col(0) = reference * w.mid_xi;
  jac.col(1) = reference * w.mid_eta;
  jac.col(2) = reference * w.director;
  const Eigen::Vector3d normal = jac.col(0).cross(jac.col(1));
  const double orientation = normal.dot(jac.col(2)) >= 0.0 ? 1.0 : -1.0;
  CorePoint p;
  p.frame = tangent_frame(orientation * normal, reference * centre.mid_xi);
  p.volume_scale = std::abs(jac.determinant());
  Eigen::Matrix3d rot;
  rot << p.frame.e1, p.frame.e2, p.frame.e3;
  const Eigen::Matrix3d c = jac.inverse() * rot;  // c(k, i) = G^k · e_i

  // Assumed covariant strains (Dvorkin–Bathe for the shears, Betsch–Stein for the thickness).
  StrainComponent e13, e23, e33;
  e13.add_scaled(tying.xi_zeta_a, 0.5 * (1 + eta)).add_scaled(tying.xi_zeta_c, 0.5 * (1 - eta));
  e23.add_scaled(tying.eta_zeta_b, 0.5 * (1 - xi)).add_scaled(tying.eta_zeta_d, 0.5 * (1 + xi));
  const BilinearShape s = bilinear_shape(xi, eta);
  for (int a = 0; a < 4; ++a) e33.add_scaled(tying.zeta_zeta[a], s.n[a]);

  // Local transverse components from the covariant ones, E_i3 = Σ c_ki c_l3 E_kl over the
  // transverse covariant components only (the faces carry the in-plane strains).
  for (int i = 0; i < 2; ++i) {
    StrainComponent& g = p.strain[i];
    g.add_scaled(e13, 2 * (c(0, i) * c(2, 2) + c(2, i) * c(0, 2)));
    g.add_scaled(e23, 2 * (c(1, i) * c(2, 2) + c(2, i) * c(1, 2)));
    g.add_scaled(e33, 2 * c(2, i) * c(2, 2));
  }
  StrainComponent& n = p.strain[2];
  n.add_scaled(e13, 2 * c(0, 2) * c(2, 2));
  n.add_scaled(e23, 2 * c(1, 2) * c(2, 2));
  n.add_scaled(e33, c(2, 2) * c(2, 2));
  return p;
}

}  // namespace

ElementResponse three_layer_element(const NodeMatrix& reference, const NodeMatrix& current,
                                    const ElementSection& section, Kinematics kinematics,
                                    bool with_tangent) {
  ElementResponse out;
  const CoreTying tying = core_tying(reference, current, kinematics);
  const Eigen::Matrix3d core_stiffness =
      Eigen::Vector3d(section.core_shear_modulus, section.core_shear_modulus,
                      section.core_normal_modulus)
          .asDiagonal();
  for (const auto& gp : kGauss2x2) {
    const FacePoint inner = face_point(reference, current, 0, gp[0], gp[1], kinematics);
    accumulate<0, 4>(inner.strain, section.inner_face, inner.area_scale, with_tangent, out);
    const FacePoint outer = face_point(reference, current, 4, gp[0], gp[1], kinematics);
    accumulate<4, 4>(outer.strain, section.outer_face, outer.area_scale, with_tangent, out);
    const CorePoint core = core_point(reference, tying, gp[0], gp[1]);
    accumulate<0, 8>(core.strain, core_stiffness, core.volume_scale, with_tangent, out);
  }
  return out;
}

}  // namespace tirefem::reference
