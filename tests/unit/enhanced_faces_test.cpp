// The faces' enhanced assumed strains (EAS-4, condensed per element): a rectangular face bent in its own
// plane stores exactly the beam energy (the compatible bilinear face adds the parasitic shear energy
// ∫ ½ A66 (κ y)² dA); a constant strain state is not changed; the condensed energy is never above the
// compatible one; and the point state reports the enhanced strain.
#include <random>

#include <gtest/gtest.h>

#include "tirefem/element/three_layer_element.hpp"
#include "../element_test_section.hpp"

namespace tirefem {
namespace {

constexpr double kHalfLength = 7.0, kHalfWidth = 3.0, kCore = 2.0;

// A flat rectangular element 2a × 2b in the x–y plane, the outer face kCore above the inner one.
NodeMatrix flat_rectangle() {
  NodeMatrix x;
  const double xs[4] = {-kHalfLength, kHalfLength, kHalfLength, -kHalfLength};
  const double ys[4] = {-kHalfWidth, -kHalfWidth, kHalfWidth, kHalfWidth};
  for (int a = 0; a < 4; ++a) {
    x.col(a) = Eigen::Vector3d(xs[a], ys[a], 0.0);
    x.col(a + 4) = Eigen::Vector3d(xs[a], ys[a], kCore);
  }
  return x;
}

// Both faces isotropic with ν = 0 (A = E t diag(1, 1, ½)); a stiff interlayer that the test's motions do
// not strain (both faces move alike in their planes).
ElementSection rubber_faces(bool enhanced) {
  ElementSection s;
  s.inner_face = isotropic_membrane(10.0, 0.0, 2.0);
  s.outer_face = isotropic_membrane(30.0, 0.0, 1.0);
  s.core_shear_modulus = 1.0;
  s.core_normal_modulus = 50.0;
  s.enhanced_faces = enhanced;
  return s;
}

// In-plane bending about the normal: u_y = κ x y at the corners (the exact field's u_x = −κ y²/2 is the
// same at all four corners: a translation, left out), so each face's exact strain is E22 = κ x, without
// shear, and its energy ½ A22 κ² ∫ x² dA = ½ A22 κ² (2a)³ (2b) / 12.
NodeMatrix bent_in_plane(const NodeMatrix& x0, double kappa) {
  NodeMatrix x = x0;
  for (int k = 0; k < kElementNodes; ++k) x(1, k) += kappa * x0(0, k) * x0(1, k);
  return x;
}

double beam_energy(const ElementSection& s, double kappa) {
  const double second_moment = std::pow(2 * kHalfLength, 3) * (2 * kHalfWidth) / 12.0;
  return 0.5 * (s.inner_face(1, 1) + s.outer_face(1, 1)) * kappa * kappa * second_moment;
}

TEST(EnhancedFaces, RectangleBentInItsPlaneStoresTheBeamEnergyWithoutParasiticShear) {
  const NodeMatrix x0 = flat_rectangle();
  const double kappa = 1e-4;
  const NodeMatrix x = bent_in_plane(x0, kappa);
  const double exact = beam_energy(rubber_faces(true), kappa);
  const double enhanced = three_layer_element(x0, x, rubber_faces(true), Kinematics::linear, false).energy;
  const double compatible = three_layer_element(x0, x, rubber_faces(false), Kinematics::linear, false).energy;
  // The compatible face adds the parasitic shear γ12 = ∂u_y/∂x = κ y: ½ A66 κ² ∫ y² dA per face.
  const ElementSection s = rubber_faces(false);
  const double second_moment = (2 * kHalfLength) * std::pow(2 * kHalfWidth, 3) / 12.0;
  const double parasitic = 0.5 * (s.inner_face(2, 2) + s.outer_face(2, 2)) * kappa * kappa * second_moment;
  EXPECT_NEAR(enhanced, exact, 1e-12 * exact);
  EXPECT_NEAR(compatible, exact + parasitic, 1e-12 * exact);
  // The same in the nonlinear theory for a small bending (its quadratic terms are O(κ²) smaller).
  const double nonlinear = three_layer_element(x0, x, rubber_faces(true), Kinematics::nonlinear, false).energy;
  EXPECT_NEAR(nonlinear, exact, 1e-3 * exact);
}

TEST(EnhancedFaces, ConstantStrainIsNotChangedByTheEnhancement) {
  // A homogeneous stretch and shear of both faces (and the interlayer) of a distorted flat element (the
  // patch test of EAS: the enhanced strains are orthogonal to constant stresses through j0/j).
  NodeMatrix x0 = flat_rectangle();
  x0(0, 2) += 1.5;
  x0(1, 3) -= 0.8;
  x0(0, 6) += 1.5;
  x0(1, 7) -= 0.8;
  Eigen::Matrix3d f;
  f << 1.01, 0.004, 0.0, -0.002, 0.995, 0.0, 0.0, 0.0, 1.0;
  const NodeMatrix x = f * x0;
  for (Kinematics k : {Kinematics::linear, Kinematics::nonlinear}) {
    ElementSection on = anisotropic_test_section(), off = anisotropic_test_section();
    on.enhanced_faces = true;
    const ElementResponse a = three_layer_element(x0, x, on, k);
    const ElementResponse b = three_layer_element(x0, x, off, k);
    EXPECT_NEAR(a.energy, b.energy, 1e-12 * b.energy);
    EXPECT_LE((a.force - b.force).norm(), 1e-11 * b.force.norm());
  }
}

TEST(EnhancedFaces, CondensedEnergyIsNeverAboveTheCompatibleOne) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    NodeMatrix x0 = flat_rectangle();
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d d(jitter(rng), jitter(rng), 0.3 * jitter(rng));
      x0.col(k) += d;
      x0.col(k + 4) += d;
    }
    NodeMatrix x = x0;
    for (int k = 0; k < kElementNodes; ++k)
      for (int c = 0; c < 3; ++c) x(c, k) += 0.05 * jitter(rng);
    ElementSection on = anisotropic_test_section(), off = anisotropic_test_section();
    on.enhanced_faces = true;
    for (Kinematics k : {Kinematics::linear, Kinematics::nonlinear}) {
      const double enhanced = three_layer_element(x0, x, on, k, false).energy;
      const double compatible = three_layer_element(x0, x, off, k, false).energy;
      EXPECT_LE(enhanced, compatible * (1 + 1e-12)) << "trial " << trial;
      EXPECT_GT(enhanced, 0.0);
    }
  }
}

TEST(EnhancedFaces, PointStateReportsTheEnhancedStrain) {
  // Bent in its plane: the enhanced E22 is the exact κ x at any point, and the shear vanishes.
  const NodeMatrix x0 = flat_rectangle();
  const double kappa = 1e-4;
  const NodeMatrix x = bent_in_plane(x0, kappa);
  for (double xi : {-0.6, 0.0, 0.9})
    for (double eta : {-0.5, 0.7}) {
      const ElementPointState st = three_layer_point_state(x0, x, rubber_faces(true), Kinematics::linear, xi, eta);
      EXPECT_NEAR(st.inner_strain[1], kappa * xi * kHalfLength, 1e-12);
      EXPECT_NEAR(st.inner_strain[2], 0.0, 1e-12);
      EXPECT_NEAR(st.outer_strain[2], 0.0, 1e-12);
    }
}

}  // namespace
}  // namespace tirefem
