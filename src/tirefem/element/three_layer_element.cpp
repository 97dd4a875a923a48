#include "tirefem/element/three_layer_element.hpp"

#include "tirefem/element/rubber_membrane.hpp"

namespace tirefem {
namespace {

// Every strain of the element has the form E = ½(a·b − A·B), a = Σ α_k x_k, b = Σ β_k x_k: its gradient
// is ½(α_k b + β_k a) at node k and its Hessian ½(αβᵀ + βαᵀ) ⊗ I3. The value is formed from the
// displacements, ½(A·u_β + u_α·B + u_α·u_β), not as a difference of position products, which would lose
// the digits of a small strain to cancellation. The linear theory drops u_α·u_β and the Hessian.

// ---- membrane faces --------------------------------------------------------------------------
struct FaceStrain {
  Eigen::Vector3d strain;  // [E11, E22, 2 E12] in the face's local frame
  Eigen::Vector3d f1, f2;  // x_,1 and x_,2 (X_,1 and X_,2 in the linear theory): the gradient's vectors
};

FaceStrain face_strain(const FaceGeometry& g, const Eigen::Matrix<double, 3, 4>& x0,
                       const Eigen::Matrix<double, 3, 4>& u, bool nonlinear) {
  const Eigen::Vector3d g1 = x0 * g.d1, g2 = x0 * g.d2, u1 = u * g.d1, u2 = u * g.d2;
  FaceStrain s;
  s.strain << 0.5 * (g1.dot(u1) + u1.dot(g1)), 0.5 * (g2.dot(u2) + u2.dot(g2)), g1.dot(u2) + u1.dot(g2);
  if (!nonlinear) {
    s.f1 = g1;
    s.f2 = g2;
    return s;
  }
  s.strain += Eigen::Vector3d(0.5 * u1.dot(u1), 0.5 * u2.dot(u2), u1.dot(u2));
  s.f1 = g1 + u1;
  s.f2 = g2 + u2;
  return s;
}

// A cord family softer in compression (section.hpp): the energy it loses, −k G(ε_c), with G'' = h the share
// of the family's stiffness lost, 1 for ε_c ≤ −δ, 0 for ε_c ≥ δ and linear between (δ = kCordSofteningBand),
// so the face's tangent stays continuous where a cord passes from tension into compression.
struct CordSofteningTerms {
  double energy = 0.0;  // G
  double force = 0.0;   // G' (→ ε_c in compression)
  double slope = 0.0;   // G'' = h
};

CordSofteningTerms cord_softening(double x) {
  constexpr double d = kCordSofteningBand;
  if (x >= d) return {};
  if (x <= -d) return {0.5 * x * x + d * d / 6.0, x, 1.0};
  const double r = d - x;
  return {r * r * r / (12.0 * d), -r * r / (4.0 * d), r / (2.0 * d)};
}

// One face's enhanced-strain parameters, condensed: the energy ½ Σ_p w_p (E_p + M_p α)ᵀ A (E_p + M_p α)
// is quadratic in α, so its minimiser is α = −H⁻¹ r, H = Σ w Mᵀ A M, r = Σ w Mᵀ A E, exactly.
struct FaceEnhancement {
  Eigen::Vector4d alpha = Eigen::Vector4d::Zero();
  Eigen::LLT<Eigen::Matrix4d> h;  // factor of H
  bool active = false;
};

using FacePoints = std::array<FaceGeometry, 4>;
using FaceStrains = std::array<FaceStrain, 4>;

// A face's compatible strains at its 4 points (face nodes First … First + 3).
template <int First>
FaceStrains face_strains(const FacePoints& points, const NodeMatrix& reference, const NodeMatrix& u, bool nonlinear) {
  FaceStrains strains;
  for (int p = 0; p < 4; ++p)
    strains[p] = face_strain(points[p], reference.middleCols<4>(First), u.middleCols<4>(First), nonlinear);
  return strains;
}

FaceEnhancement face_enhancement(const FacePoints& points, const FaceStrains& strains,
                                 const Eigen::Matrix3d& stiffness, bool enhanced) {
  FaceEnhancement out;
  if (!enhanced) return out;
  Eigen::Matrix4d h = Eigen::Matrix4d::Zero();
  Eigen::Vector4d r = Eigen::Vector4d::Zero();
  for (int p = 0; p < 4; ++p) {
    const Eigen::Matrix<double, 3, 4> am = (points[p].area_scale * stiffness) * points[p].enhanced;
    h.noalias() += points[p].enhanced.transpose() * am;
    r.noalias() += am.transpose() * strains[p].strain;
  }
  out.h.compute(h);
  if (out.h.info() != Eigen::Success) return out;  // a face without in-plane stiffness: nothing to enhance
  out.alpha = -out.h.solve(r);
  out.active = true;
  return out;
}

// Adds a face's energy Σ_p ½ εᵀ A ε w_p, ε = E_p + M_p α (compatible + condensed enhanced strains), its
// gradient Σ w Bᵀ A ε and its Hessian Σ w Bᵀ A B − Lᵀ H⁻¹ L + Σ w (Aε)·∂²E, L = Σ w Mᵀ A B (face nodes only).
// Cord families softer in compression subtract Σ_p w_p k G(m·E_p) on the compatible strains, and rubber
// layers under the neo-Hookean law replace their linear share ½ Eᵀ A_r E there by W(E): α minimises the
// quadratic part alone, so the condensation stays exact and the sum is still a potential of u.
template <int First>
void add_face(const FacePoints& points, const NodeMatrix& reference, const NodeMatrix& u,
              const Eigen::Matrix3d& stiffness, const std::vector<CordSoftening>& cords, const RubberFaceLaw& rubber,
              bool enhanced, bool nonlinear, bool with_tangent, ElementResponse& out) {
  const FaceStrains strains = face_strains<First>(points, reference, u, nonlinear);
  const FaceEnhancement enh = face_enhancement(points, strains, stiffness, enhanced);
  Eigen::Matrix<double, 4, 12> coupling = Eigen::Matrix<double, 4, 12>::Zero();  // L
  for (int p = 0; p < 4; ++p) {
    const FaceGeometry& g = points[p];
    const FaceStrain& s = strains[p];
    const double w = g.area_scale;
    const Eigen::Vector3d strain = enh.active ? Eigen::Vector3d(s.strain + g.enhanced * enh.alpha) : s.strain;
    Eigen::Vector3d stress = stiffness * strain;
    out.energy += 0.5 * w * strain.dot(stress);
    Eigen::Matrix<double, 3, 12> b;  // rows: ∂[E11, E22, 2E12]/∂x_a
    for (int a = 0; a < 4; ++a) {
      b.block<1, 3>(0, 3 * a) = g.d1[a] * s.f1.transpose();
      b.block<1, 3>(1, 3 * a) = g.d2[a] * s.f2.transpose();
      b.block<1, 3>(2, 3 * a) = g.d1[a] * s.f2.transpose() + g.d2[a] * s.f1.transpose();
    }
    // Cords softer in compression (nonlinear theory only): −k G(m·E) on the compatible strain.
    if (nonlinear)
      for (const CordSoftening& c : cords) {
        const CordSofteningTerms t = cord_softening(c.direction.dot(s.strain));
        if (t.slope == 0.0) continue;
        out.energy -= w * c.stiffness * t.energy;
        stress -= (c.stiffness * t.force) * c.direction;
        if (with_tangent) {
          const Eigen::Matrix<double, 1, 12> mb = c.direction.transpose() * b;
          out.tangent.block<12, 12>(3 * First, 3 * First).noalias() -= (w * c.stiffness * t.slope) * mb.transpose() * mb;
        }
      }
    if (nonlinear && rubber.shear_stiffness > 0.0) {  // neo-Hookean rubber layers on the compatible strain
      const RubberMembraneTerms r = rubber_membrane(s.strain, rubber.shear_stiffness);
      const Eigen::Vector3d linear = rubber.linear * s.strain;
      out.energy += w * (r.energy - 0.5 * s.strain.dot(linear));
      stress += r.resultant - linear;
      if (with_tangent)
        out.tangent.block<12, 12>(3 * First, 3 * First).noalias() +=
            b.transpose() * ((w * (r.stiffness - rubber.linear)) * b);
    }
    out.force.segment<12>(3 * First).noalias() += b.transpose() * (w * stress);
    if (!with_tangent) continue;
    const Eigen::Matrix<double, 3, 12> cb = (w * stiffness) * b;
    out.tangent.block<12, 12>(3 * First, 3 * First).noalias() += b.transpose().lazyProduct(cb);
    if (enh.active) coupling.noalias() += g.enhanced.transpose() * cb;
    if (!nonlinear) continue;
    const Eigen::Vector3d ws = w * stress;  // geometric stiffness Σ_c S_c ∂²E_c ⊗ I3
    for (int l = 0; l < 4; ++l)
      for (int k = 0; k < 4; ++k) {
        const double h = ws[0] * g.d1[k] * g.d1[l] + ws[1] * g.d2[k] * g.d2[l] +
                         ws[2] * (g.d1[k] * g.d2[l] + g.d2[k] * g.d1[l]);
        for (int i = 0; i < 3; ++i) out.tangent(3 * (First + k) + i, 3 * (First + l) + i) += h;
      }
  }
  if (with_tangent && enh.active)
    out.tangent.block<12, 12>(3 * First, 3 * First).noalias() -= coupling.transpose() * enh.h.solve(coupling);
}

// ---- interlayer --------------------------------------------------------------------------------
using TyingVector = Eigen::Matrix<double, kTyingStrains, 1>;
using TyingGradient = Eigen::Matrix<double, kTyingStrains, kElementDofs>;

// The tying strains and (optionally) their gradients.
TyingVector tying_strains(const NodeMatrix& reference, const NodeMatrix& u, bool nonlinear,
                          TyingGradient* gradient) {
  const TyingWeights& tw = tying_weights();
  TyingVector e;
  for (int t = 0; t < kTyingStrains; ++t) {
    const NodeWeights& alpha = tw.alpha[t];
    const NodeWeights& beta = tw.beta[t];
    const Eigen::Vector3d a0 = reference * alpha, b0 = reference * beta, ua = u * alpha, ub = u * beta;
    e[t] = nonlinear ? 0.5 * (a0.dot(ub) + ua.dot(b0) + ua.dot(ub)) : 0.5 * (a0.dot(ub) + ua.dot(b0));
    if (!gradient) continue;
    const Eigen::Vector3d a = nonlinear ? Eigen::Vector3d(a0 + ua) : a0;
    const Eigen::Vector3d b = nonlinear ? Eigen::Vector3d(b0 + ub) : b0;
    for (int k = 0; k < kElementNodes; ++k)
      gradient->block<1, 3>(t, 3 * k) = 0.5 * (alpha[k] * b + beta[k] * a).transpose();
  }
  return e;
}

// The interlayer's energy over the Gauss points. Its local strains at a point are ε = C_p e (e the tying
// strains), so Σ_p w_p B_pᵀ D B_p = Gᵀ (Σ_p w_p C_pᵀ D C_p) G with G the tying strains' gradient, the
// force is Gᵀ r with r = Σ_p w_p C_pᵀ D ε_p, and the geometric stiffness is Σ_t r_t ½(α_t β_tᵀ + β_t α_tᵀ):
// the 8 × 24 gradient is formed once per element, not per point and strain.
void add_core(const std::array<CoreGeometry, 4>& points, const NodeMatrix& reference, const NodeMatrix& u,
              const ElementSection& section, bool nonlinear, bool with_tangent, ElementResponse& out) {
  TyingGradient gradient;
  const TyingVector e = tying_strains(reference, u, nonlinear, &gradient);
  const Eigen::Vector3d modulus(section.core_shear_modulus, section.core_shear_modulus, section.core_normal_modulus);
  TyingVector r = TyingVector::Zero();
  Eigen::Matrix<double, kTyingStrains, kTyingStrains> m = Eigen::Matrix<double, kTyingStrains, kTyingStrains>::Zero();
  for (const CoreGeometry& p : points) {
    const Eigen::Vector3d strain = p.coefficients * e;
    const Eigen::Vector3d stress = modulus.cwiseProduct(strain);
    out.energy += 0.5 * p.volume_scale * strain.dot(stress);
    r.noalias() += p.coefficients.transpose() * (p.volume_scale * stress);
    if (with_tangent)
      m.noalias() += p.coefficients.transpose() * (p.volume_scale * modulus).asDiagonal() * p.coefficients;
  }
  out.force.noalias() += gradient.transpose() * r;
  if (!with_tangent) return;
  const TyingGradient mg = m.lazyProduct(gradient);
  out.tangent.noalias() += gradient.transpose().lazyProduct(mg);
  if (!nonlinear) return;
  const TyingWeights& tw = tying_weights();
  Eigen::Matrix<double, kElementNodes, kElementNodes> h = Eigen::Matrix<double, kElementNodes, kElementNodes>::Zero();
  for (int t = 0; t < kTyingStrains; ++t)
    h.noalias() += (0.5 * r[t]) * (tw.alpha[t] * tw.beta[t].transpose() + tw.beta[t] * tw.alpha[t].transpose());
  for (int l = 0; l < kElementNodes; ++l)
    for (int k = 0; k < kElementNodes; ++k) {
      if (h(k, l) == 0.0) continue;
      for (int i = 0; i < 3; ++i) out.tangent(3 * k + i, 3 * l + i) += h(k, l);
    }
}

// A face's condensed enhanced-strain parameters in a given state.
template <int First>
Eigen::Vector4d face_alpha(const FacePoints& points, const NodeMatrix& reference, const NodeMatrix& u,
                           const Eigen::Matrix3d& stiffness, bool nonlinear) {
  return face_enhancement(points, face_strains<First>(points, reference, u, nonlinear), stiffness, true).alpha;
}

}  // namespace

ElementResponse three_layer_element(const ElementGeometry& geometry, const NodeMatrix& reference,
                                    const NodeMatrix& current, const ElementSection& section,
                                    Kinematics kinematics, bool with_tangent) {
  ElementResponse out;
  const bool nonlinear = kinematics == Kinematics::nonlinear;
  const NodeMatrix u = current - reference;
  add_face<0>(geometry.inner, reference, u, section.inner_face, section.inner_cords, section.inner_rubber,
              section.enhanced_faces, nonlinear, with_tangent, out);
  add_face<4>(geometry.outer, reference, u, section.outer_face, section.outer_cords, section.outer_rubber,
              section.enhanced_faces, nonlinear, with_tangent, out);
  add_core(geometry.core, reference, u, section, nonlinear, with_tangent, out);
  return out;
}

ElementPointState three_layer_point_state(const NodeMatrix& reference, const NodeMatrix& current,
                                          const ElementSection& section, Kinematics kinematics,
                                          double xi, double eta) {
  const bool nonlinear = kinematics == Kinematics::nonlinear;
  const NodeMatrix u = current - reference;
  const FaceGeometry inner = face_geometry(reference, 0, xi, eta), outer = face_geometry(reference, 4, xi, eta);
  ElementPointState st;
  const Eigen::Vector3d inner_compatible = face_strain(inner, reference.leftCols<4>(), u.leftCols<4>(), nonlinear).strain;
  const Eigen::Vector3d outer_compatible = face_strain(outer, reference.rightCols<4>(), u.rightCols<4>(), nonlinear).strain;
  st.inner_strain = inner_compatible;
  st.outer_strain = outer_compatible;
  if (section.enhanced_faces) {  // the enhanced strains need the parameters from the Gauss points
    const ElementGeometry at_gauss = element_geometry(reference);
    st.inner_strain += inner.enhanced * face_alpha<0>(at_gauss.inner, reference, u, section.inner_face, nonlinear);
    st.outer_strain += outer.enhanced * face_alpha<4>(at_gauss.outer, reference, u, section.outer_face, nonlinear);
  }
  st.inner_resultant = section.inner_face * st.inner_strain;
  st.outer_resultant = section.outer_face * st.outer_strain;
  if (nonlinear) {  // cords softer in compression and neo-Hookean rubber act on the compatible strains (add_face)
    const auto correct = [](const std::vector<CordSoftening>& cords, const RubberFaceLaw& rubber,
                            const Eigen::Vector3d& compatible, Eigen::Vector3d& resultant) {
      for (const CordSoftening& c : cords)
        resultant -= (c.stiffness * cord_softening(c.direction.dot(compatible)).force) * c.direction;
      if (rubber.shear_stiffness > 0.0)
        resultant += rubber_membrane(compatible, rubber.shear_stiffness).resultant - rubber.linear * compatible;
    };
    correct(section.inner_cords, section.inner_rubber, inner_compatible, st.inner_resultant);
    correct(section.outer_cords, section.outer_rubber, outer_compatible, st.outer_resultant);
  }
  const Eigen::Vector3d core =
      core_geometry(reference, xi, eta).coefficients * tying_strains(reference, u, nonlinear, nullptr);
  st.core_shear = core.head<2>();
  st.core_normal_strain = core[2];
  st.inner_axis1 = inner.e1;
  st.inner_axis2 = inner.e2;
  return st;
}

}  // namespace tirefem
