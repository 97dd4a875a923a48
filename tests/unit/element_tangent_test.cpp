// Tangent stiffness of every element-level term against central finite differences of its force
// (reference: the definition K = ∂F/∂f; tolerance 1e-6 relative, what central differences with
// h = 1e-6 of a smooth function give in double precision).

#include <gtest/gtest.h>

#include "tirefem/element/follower_pressure.hpp"
#include "tirefem/element/three_layer_element.hpp"
#include "../element_test_section.hpp"

namespace tirefem {
namespace {

template <class ForceOf>
double max_relative_tangent_error(const NodeMatrix& x, const ElementMatrix& k, ForceOf force_of) {
  const double h = 1e-6;
  ElementMatrix fd;
  for (int j = 0; j < kElementDofs; ++j) {
    NodeMatrix xp = x, xm = x;
    xp(j % 3, j / 3) += h;
    xm(j % 3, j / 3) -= h;
    fd.col(j) = (force_of(xp) - force_of(xm)) / (2 * h);
  }
  return (fd - k).norm() / k.norm();
}

// Both face formulations: the paper's compatible faces and the enhanced ones (EAS-4, condensed).
ElementSection test_section(bool enhanced) {
  ElementSection s = anisotropic_test_section();
  s.enhanced_faces = enhanced;
  return s;
}

TEST(ElementTangent, NonlinearInternalForceMatchesFiniteDifferences) {
  const NodeMatrix x0 = curved_element();
  for (bool enhanced : {false, true})
    for (unsigned seed : {1u, 2u, 3u}) {
      const ElementSection s = test_section(enhanced);
      const NodeMatrix x = randomly_deformed(x0, 1.5, seed);
      const ElementResponse r = three_layer_element(x0, x, s, Kinematics::nonlinear);
      const double err = max_relative_tangent_error(x, r.tangent, [&](const NodeMatrix& y) {
        return ElementVector(three_layer_element(x0, y, s, Kinematics::nonlinear, false).force);
      });
      EXPECT_LT(err, 1e-6) << "seed " << seed << (enhanced ? ", enhanced faces" : "");
    }
}

TEST(ElementTangent, EachLayerSeparately) {
  const NodeMatrix x0 = curved_element();
  const NodeMatrix x = randomly_deformed(x0, 1.0, 7);
  for (int layer = 0; layer < 5; ++layer) {
    ElementSection s;
    s.enhanced_faces = layer >= 3;  // layers 3, 4: the faces again, enhanced
    if (layer == 0 || layer == 3) s.inner_face = anisotropic_test_section().inner_face;
    if (layer == 1 || layer == 4) s.outer_face = anisotropic_test_section().outer_face;
    if (layer == 2) {
      s.core_shear_modulus = 1.0;
      s.core_normal_modulus = 50.0;
    }
    const ElementResponse r = three_layer_element(x0, x, s, Kinematics::nonlinear);
    const double err = max_relative_tangent_error(x, r.tangent, [&](const NodeMatrix& y) {
      return ElementVector(three_layer_element(x0, y, s, Kinematics::nonlinear, false).force);
    });
    EXPECT_LT(err, 1e-6) << "layer " << layer;
  }
}

TEST(ElementTangent, ForceIsGradientOfEnergy) {
  const NodeMatrix x0 = curved_element();
  const NodeMatrix x = randomly_deformed(x0, 1.0, 11);
  for (bool enhanced : {false, true}) {
    const ElementSection s = test_section(enhanced);
    const ElementResponse r = three_layer_element(x0, x, s, Kinematics::nonlinear, false);
    const double h = 1e-5;
    ElementVector fd;
    for (int j = 0; j < kElementDofs; ++j) {
      NodeMatrix xp = x, xm = x;
      xp(j % 3, j / 3) += h;
      xm(j % 3, j / 3) -= h;
      fd[j] = (three_layer_element(x0, xp, s, Kinematics::nonlinear, false).energy -
               three_layer_element(x0, xm, s, Kinematics::nonlinear, false).energy) /
              (2 * h);
    }
    EXPECT_LT((fd - r.force).norm() / r.force.norm(), 1e-7) << (enhanced ? "enhanced faces" : "");
  }
}

TEST(ElementTangent, LinearTheoryIsLinear) {
  const NodeMatrix x0 = curved_element();
  for (bool enhanced : {false, true}) {
    const ElementSection s = test_section(enhanced);
    const NodeMatrix x = randomly_deformed(x0, 1.0, 5);
    const ElementResponse r = three_layer_element(x0, x, s, Kinematics::linear);
    ElementVector u;
    for (int k = 0; k < 8; ++k) u.segment<3>(3 * k) = x.col(k) - x0.col(k);
    EXPECT_LT((r.tangent * u - r.force).norm() / r.force.norm(), 1e-12);
    EXPECT_LT((r.tangent - r.tangent.transpose()).norm() / r.tangent.norm(), 1e-13);
  }
}

TEST(ElementTangent, FollowerPressureMatchesFiniteDifferences) {
  const NodeMatrix x0 = curved_element();
  const NodeMatrix x = randomly_deformed(x0, 1.5, 3);
  const PressureLoad p = follower_pressure(x0, x, 0.2, Kinematics::nonlinear);
  const double err = max_relative_tangent_error(x, p.tangent, [&](const NodeMatrix& y) {
    return ElementVector(follower_pressure(x0, y, 0.2, Kinematics::nonlinear, false).force);
  });
  EXPECT_LT(err, 1e-6);
}

}  // namespace
}  // namespace tirefem
