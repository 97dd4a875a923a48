#include "tirefem/element/rubber_membrane.hpp"

namespace tirefem {

RubberMembraneTerms rubber_membrane(const Eigen::Vector3d& e, double mu_t) {
  const double c11 = 1.0 + 2.0 * e[0], c22 = 1.0 + 2.0 * e[1], c12 = e[2];
  const double det = c11 * c22 - c12 * c12;
  // f(det) = 1/det and its first two derivatives (continued below kRubberMinDetC, see the header).
  double f, df, ddf;
  if (det >= kRubberMinDetC) {
    f = 1.0 / det;
    df = -f * f;
    ddf = -2.0 * df * f;
  } else {
    const double d0 = kRubberMinDetC, x = det - d0;
    ddf = 2.0 / (d0 * d0 * d0);
    df = -1.0 / (d0 * d0) + ddf * x;
    f = 1.0 / d0 - x / (d0 * d0) + 0.5 * ddf * x * x;
  }
  const Eigen::Vector3d g(2.0 * c22, 2.0 * c11, -2.0 * c12);  // ∂ det C / ∂[E11, E22, 2E12]
  Eigen::Matrix3d gg;                                          // ∂² det C / ∂[E11, E22, 2E12]²
  gg << 0.0, 4.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0, -2.0;
  const double h = 0.5 * mu_t;
  RubberMembraneTerms t;
  t.energy = h * (c11 + c22 + f - 3.0);
  t.resultant = h * (Eigen::Vector3d(2.0, 2.0, 0.0) + df * g);
  t.stiffness = h * (ddf * g * g.transpose() + df * gg);
  return t;
}

}  // namespace tirefem
