// The faces' rubber layers under the incompressible neo-Hookean law (element/rubber_membrane.hpp,
// TyreDescription::rubber_law): its resultant and stiffness against central differences of its energy, at
// small strain the St. Venant–Kirchhoff face of ν = 1/2, E = 3μ; a strip in uniaxial tension and
// compression carries the closed-form force μt (λ − λ⁻²) at the lateral stretch λ^(−1/2); the element's
// tangent against differences of its force and its force against differences of its energy with the law
// on; the case reader's key, the rubber layers' share and the field named in an error.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "case_reader_test_support.hpp"
#include "tirefem/element/rubber_membrane.hpp"
#include "tirefem/element/three_layer_element.hpp"
#include "tirefem/tyre/tyre_mesh.hpp"
#include "../element_test_section.hpp"

namespace tirefem {
namespace {

TEST(RubberMembrane, ResultantAndStiffnessMatchFiniteDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> e(-0.45, 0.6), shear(-0.5, 0.5);
  int continued = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Eigen::Vector3d strain(e(rng), e(rng), shear(rng));
    if (trial == 0) strain = Eigen::Vector3d(-0.49, -0.3, 0.1);  // det C below kRubberMinDetC
    const double det = (1 + 2 * strain[0]) * (1 + 2 * strain[1]) - strain[2] * strain[2];
    if (det < kRubberMinDetC) ++continued;
    const double mu_t = 10.0;
    const RubberMembraneTerms t = rubber_membrane(strain, mu_t);
    const double h = 1e-6;
    Eigen::Vector3d grad;
    Eigen::Matrix3d hess;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d p = strain, m = strain;
      p[j] += h;
      m[j] -= h;
      grad[j] = (rubber_membrane(p, mu_t).energy - rubber_membrane(m, mu_t).energy) / (2 * h);
      hess.col(j) = (rubber_membrane(p, mu_t).resultant - rubber_membrane(m, mu_t).resultant) / (2 * h);
    }
    EXPECT_LT((grad - t.resultant).norm(), 1e-7 * (1 + t.resultant.norm())) << strain.transpose();
    EXPECT_LT((hess - t.stiffness).norm(), 1e-7 * t.stiffness.norm()) << strain.transpose();
    EXPECT_LT((t.stiffness - t.stiffness.transpose()).norm(), 1e-14 * t.stiffness.norm());
  }
  EXPECT_GE(continued, 1) << "no strain below kRubberMinDetC: the continuation went untested";
}

TEST(RubberMembrane, AtSmallStrainItIsTheLinearFaceOfPoissonHalf) {
  const double mu = 8.0 / 3.0, t = 4.0;
  const RubberMembraneTerms r = rubber_membrane(Eigen::Vector3d::Zero(), mu * t);
  EXPECT_NEAR(r.energy, 0.0, 1e-14);
  EXPECT_LT(r.resultant.norm(), 1e-13);
  EXPECT_LT((r.stiffness - isotropic_membrane(3 * mu, 0.5, t)).norm(), 1e-12 * r.stiffness.norm());
}

// A strip stretched by λ along axis 1, free across: N22 = 0 fixes the lateral stretch (Newton on E22).
TEST(RubberMembrane, UniaxialStripCarriesTheClosedFormForce) {
  const double mu_t = 32.0 / 3.0;  // E = 8 MPa, 4 mm
  for (double lambda : {0.6, 0.72, 0.9, 1.1, 1.5, 2.0}) {
    const double e11 = 0.5 * (lambda * lambda - 1);
    double e22 = -0.5 * e11;  // linear guess
    for (int it = 0; it < 30; ++it) {
      const RubberMembraneTerms r = rubber_membrane(Eigen::Vector3d(e11, e22, 0.0), mu_t);
      e22 -= r.resultant[1] / r.stiffness(1, 1);
    }
    const RubberMembraneTerms r = rubber_membrane(Eigen::Vector3d(e11, e22, 0.0), mu_t);
    ASSERT_LT(std::abs(r.resultant[1]), 1e-12 * mu_t);
    const double lateral = std::sqrt(1 + 2 * e22);
    EXPECT_NEAR(lateral, 1 / std::sqrt(lambda), 1e-12) << "λ " << lambda;
    // nominal force per unit reference width: P11 = λ S11
    EXPECT_NEAR(lambda * r.resultant[0], mu_t * (lambda - 1 / (lambda * lambda)), 1e-11 * mu_t) << "λ " << lambda;
  }
  // At 40% compression the strip is stiffer than at rest (dP/dλ = μt(1 + 2λ⁻³)), where the linear face of
  // the same small-strain stiffness has lost it all (E t (3λ² − 1)/2 < 0 below λ = 0.577).
  const double lambda = 0.6, h = 1e-6;
  const auto force = [&](double l) {
    const double e11 = 0.5 * (l * l - 1);
    double e22 = 0.0;
    for (int it = 0; it < 40; ++it) {
      const RubberMembraneTerms r = rubber_membrane(Eigen::Vector3d(e11, e22, 0.0), mu_t);
      e22 -= r.resultant[1] / r.stiffness(1, 1);
    }
    return l * rubber_membrane(Eigen::Vector3d(e11, e22, 0.0), mu_t).resultant[0];
  };
  const double slope = (force(lambda + h) - force(lambda - h)) / (2 * h);
  EXPECT_NEAR(slope, mu_t * (1 + 2 / (lambda * lambda * lambda)), 1e-6 * mu_t);
}

// The anisotropic test section with a 4 mm rubber layer (E = 8) in the outer face and a 1 mm one in the
// inner face, under the neo-Hookean law.
ElementSection rubber_section(bool enhanced) {
  ElementSection s = anisotropic_test_section();
  s.enhanced_faces = enhanced;
  const auto layer = [](double e, double nu, double t) {  // μ t with μ = E/2(1 + ν), and its linear face
    return RubberFaceLaw{e / (2 * (1 + nu)) * t, isotropic_membrane(e, nu, t)};
  };
  s.outer_rubber = layer(8.0, 0.49, 4.0);
  s.inner_rubber = layer(4.0, 0.49, 1.0);
  s.outer_face += s.outer_rubber.linear;
  s.inner_face += s.inner_rubber.linear;
  return s;
}

TEST(RubberMembrane, ElementTangentAndForceMatchFiniteDifferences) {
  const NodeMatrix x0 = curved_element();
  for (double amplitude : {2.0, 0.01})
    for (bool enhanced : {false, true})
      for (unsigned seed : {1u, 2u}) {
        const ElementSection s = rubber_section(enhanced);
        const NodeMatrix x = randomly_deformed(x0, amplitude, seed);
        ElementSection linear = s;
        linear.inner_rubber = linear.outer_rubber = {};
        const ElementResponse r = three_layer_element(x0, x, s, Kinematics::nonlinear);
        // the law must act: the energies differ at this deformation
        ASSERT_GT(std::abs(r.energy - three_layer_element(x0, x, linear, Kinematics::nonlinear, false).energy),
                  1e-10 * r.energy);
        const double h = amplitude * 1e-6;
        ElementMatrix fd;
        ElementVector grad;
        for (int j = 0; j < kElementDofs; ++j) {
          NodeMatrix xp = x, xm = x;
          xp(j % 3, j / 3) += h;
          xm(j % 3, j / 3) -= h;
          const ElementResponse p = three_layer_element(x0, xp, s, Kinematics::nonlinear, false);
          const ElementResponse m = three_layer_element(x0, xm, s, Kinematics::nonlinear, false);
          fd.col(j) = (p.force - m.force) / (2 * h);
          grad[j] = (p.energy - m.energy) / (2 * h);
        }
        const std::string what = "amplitude " + std::to_string(amplitude) + ", seed " + std::to_string(seed) +
                                 (enhanced ? ", enhanced faces" : "");
        EXPECT_LT((fd - r.tangent).norm() / r.tangent.norm(), 1e-6) << what;
        EXPECT_LT((grad - r.force).norm() / r.force.norm(), 1e-6) << what;
        EXPECT_LT((r.tangent - r.tangent.transpose()).norm() / r.tangent.norm(), 1e-13) << what;
      }
}

TEST(RubberMembrane, PointStateCarriesTheLawsResultant) {
  ElementSection s = rubber_section(false);
  s.inner_face = s.inner_rubber.linear;  // faces of rubber alone
  s.outer_face = s.outer_rubber.linear;
  NodeMatrix x0, x;
  const double xs[4] = {0, 10, 10, 0}, ys[4] = {0, 0, 10, 10};
  const double a = 0.7, b = 1.2;  // stretches along 1 and 2
  for (int k = 0; k < 4; ++k) {
    x0.col(k) = Eigen::Vector3d(xs[k], ys[k], 0);
    x0.col(k + 4) = Eigen::Vector3d(xs[k], ys[k], 4);
    x.col(k) = Eigen::Vector3d(a * xs[k], b * ys[k], 0);
    x.col(k + 4) = Eigen::Vector3d(a * xs[k], b * ys[k], 4);
  }
  const ElementPointState st = three_layer_point_state(x0, x, s, Kinematics::nonlinear, 0.0, 0.0);
  // S = μt (I − C⁻¹/det C) with C = diag(a², b²)
  const double mu_t = s.outer_rubber.shear_stiffness, det = a * a * b * b;
  EXPECT_NEAR(st.outer_resultant[0], mu_t * (1 - 1 / (a * a * det)), 1e-12 * mu_t);
  EXPECT_NEAR(st.outer_resultant[1], mu_t * (1 - 1 / (b * b * det)), 1e-12 * mu_t);
  EXPECT_NEAR(st.outer_resultant[2], 0.0, 1e-12 * mu_t);
}

TEST(RubberMembrane, CaseReaderTakesTheLawAndTheRubberLayersShare) {
  using namespace case_test;
  const Case plain = parse_case(example_text(), "case.toml");
  EXPECT_EQ(plain.tyre.rubber_law, RubberLaw::saint_venant_kirchhoff);  // the paper's, by default
  const Case c = parse_case(edited("cord_rubber_rule = \"halpin_tsai\"",
                                   "cord_rubber_rule = \"halpin_tsai\"\nrubber_law = \"neo_hookean\""),
                            "case.toml");
  EXPECT_EQ(c.tyre.rubber_law, RubberLaw::neo_hookean);
  // the sidewall's outer face: rubber = { E = 3.0, nu = 0.49, thickness = 3.0 }
  const FaceLayup& side = c.tyre.zones[2].outer;
  EXPECT_NEAR(side.rubber_shear_stiffness, 3.0 / (2 * 1.49) * 3.0, 1e-12);
  EXPECT_LT((side.rubber_stiffness - isotropic_membrane(3.0, 0.49, 3.0)).norm(), 1e-12);
  EXPECT_EQ(c.tyre.zones[0].outer.rubber_shear_stiffness, 0.0);  // the belt face has plies only
  EXPECT_CONTAINS(error_of(edited("cord_rubber_rule = \"halpin_tsai\"",
                                  "cord_rubber_rule = \"halpin_tsai\"\nrubber_law = \"mooney\"")),
                  "tyre.rubber_law");
  // the mesh's sections carry the law only when it is chosen
  const TyreMesh with = build_tyre_mesh(c.tyre, c.mesh), without = build_tyre_mesh(plain.tyre, plain.mesh);
  const int e = with.mesh.element_index(with.mesh.u_elements() - 1, 0);  // next to the bead
  EXPECT_GT(with.sections[e].outer_rubber.shear_stiffness, 0.0);
  EXPECT_EQ(without.sections[e].outer_rubber.shear_stiffness, 0.0);
}

}  // namespace
}  // namespace tirefem
