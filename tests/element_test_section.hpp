#pragma once
// Element tests' shared data (unit and verification): a fully anisotropic section, both faces with coupled
// normal and shear terms, so every stiffness entry of the element takes part; a curved, distorted element
// and random deformations of it.
#include <random>

#include "tirefem/element/element_geometry.hpp"
#include "tirefem/element/section.hpp"

namespace tirefem {

inline ElementSection anisotropic_test_section() {
  ElementSection s;
  s.inner_face << 3000, 300, 50, 300, 900, -40, 50, -40, 400;
  s.outer_face << 5000, 2500, 0, 2500, 2000, 0, 0, 0, 2200;
  s.core_shear_modulus = 1.5;
  s.core_normal_modulus = 100;
  return s;
}

// A curved, distorted element: carcass face on a doubly curved patch, breaker 4 mm above.
inline NodeMatrix curved_element() {
  NodeMatrix x;
  const double xs[4] = {0, 11, 12, -1}, ys[4] = {0, 1, 13, 10};
  for (int a = 0; a < 4; ++a) {
    const double z = 0.01 * (xs[a] * xs[a] + 0.5 * ys[a] * ys[a]);
    x.col(a) = Eigen::Vector3d(xs[a], ys[a], z);
    x.col(a + 4) = Eigen::Vector3d(xs[a] - 0.04 * xs[a], ys[a] - 0.02 * ys[a], z + 4.0);
  }
  return x;
}

// x with every nodal coordinate moved by a uniform random amount in [−amplitude, amplitude].
inline NodeMatrix randomly_deformed(const NodeMatrix& x, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  NodeMatrix y = x;
  for (int k = 0; k < 8; ++k)
    for (int c = 0; c < 3; ++c) y(c, k) += u(rng);
  return y;
}

}  // namespace tirefem
