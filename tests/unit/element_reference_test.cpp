// The element with its reference geometry cached and the interlayer formed from its tying strains gives
// the force, tangent and energy of the element as it was before (reference_three_layer_element.cpp, the
// paper's compatible bilinear faces: enhanced_faces = false) to round-off, in both theories, on curved,
// distorted and strongly deformed elements.
#include <random>

#include <gtest/gtest.h>

#include "reference_three_layer_element.hpp"
#include "../element_test_section.hpp"

namespace tirefem {
namespace {

NodeMatrix random_element(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-1.5, 1.5);
  NodeMatrix x;
  const double xs[4] = {0, 11, 12, -1}, ys[4] = {0, 1, 13, 10};
  for (int a = 0; a < 4; ++a) {
    const double z = 0.01 * (xs[a] * xs[a] + 0.5 * ys[a] * ys[a]);
    x.col(a) = Eigen::Vector3d(xs[a] + jitter(rng), ys[a] + jitter(rng), z);
    x.col(a + 4) = x.col(a) + Eigen::Vector3d(0.3 * jitter(rng), 0.3 * jitter(rng), 4.0 + jitter(rng));
  }
  return x;
}

TEST(ElementReference, ForceTangentAndEnergyEqualTheFormerElementToRoundOff) {
  for (Kinematics kinematics : {Kinematics::nonlinear, Kinematics::linear}) {
    for (unsigned seed = 1; seed <= 6; ++seed) {
      const NodeMatrix x0 = random_element(seed);
      std::mt19937 rng(100 + seed);
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      NodeMatrix x = x0;
      for (int k = 0; k < 8; ++k)
        for (int c = 0; c < 3; ++c) x(c, k) += u(rng);
      const ElementSection section = anisotropic_test_section();
      const ElementResponse now = three_layer_element(element_geometry(x0), x0, x, section, kinematics);
      const ElementResponse before = reference::three_layer_element(x0, x, section, kinematics);
      const char* theory = kinematics == Kinematics::nonlinear ? "nonlinear" : "linear";
      EXPECT_LE((now.force - before.force).norm(), 1e-13 * before.force.norm()) << theory << " seed " << seed;
      EXPECT_LE((now.tangent - before.tangent).norm(), 1e-13 * before.tangent.norm()) << theory << " seed " << seed;
      EXPECT_NEAR(now.energy, before.energy, 1e-13 * std::abs(before.energy)) << theory << " seed " << seed;
    }
  }
}

}  // namespace
}  // namespace tirefem
