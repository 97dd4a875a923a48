#include "tirefem/element/line_bending.hpp"

#include <cmath>

namespace tirefem {

namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {  // [v]× y = v × y
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// The intermediate vectors a = x_n − x_p, b = x_q − x_m and d as linear maps of the 15 coordinates.
struct LineVectors {
  Eigen::Vector3d a, b, d;
};

LineVectors line_vectors(const std::array<double, 3>& w, const Eigen::Matrix<double, 3, 5>& x) {
  return {x.col(line_after) - x.col(line_before), x.col(across_after) - x.col(across_before),
          w[0] * x.col(line_before) + w[1] * x.col(line_centre) + w[2] * x.col(line_after)};
}

}  // namespace

std::array<double, 3> second_difference_weights(double h1, double h2) {
  const double s = 2.0 / (h1 + h2);
  return {s / h1, -s / h1 - s / h2, s / h2};
}

double line_curvature(const LineBendingStencil& s, const Eigen::Matrix<double, 3, 5>& x) {
  const LineVectors v = line_vectors(s.weights, x);
  const Eigen::Vector3d c = v.a.cross(v.b);
  return c.dot(v.d) / c.norm();
}

LineBendingResponse line_bending(const LineBendingStencil& s, const Eigen::Matrix<double, 3, 5>& x,
                                 bool with_tangent) {
  const LineVectors v = line_vectors(s.weights, x);
  const Eigen::Vector3d c = v.a.cross(v.b);
  const double c_norm = c.norm();
  const Eigen::Vector3d nu = c / c_norm;
  const double kappa = nu.dot(v.d);
  const double rho = kappa - s.reference_curvature;

  // κ = f(c, d) = c·d / |c|: ∂f/∂d = ν, ∂f/∂c = g = (d − κ ν) / |c|; dc = −[b]× da + [a]× db.
  const Eigen::Vector3d g = (v.d - kappa * nu) / c_norm;
  // Gradient of κ over (a, b, d).
  Eigen::Matrix<double, 9, 1> grad_abd;
  grad_abd << v.b.cross(g), g.cross(v.a), nu;
  // (a, b, d) = T x, T a 9 × 15 map with entries ±1 and the weights.
  Eigen::Matrix<double, 9, 15> t = Eigen::Matrix<double, 9, 15>::Zero();
  const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
  t.block<3, 3>(0, 3 * line_after) = id;
  t.block<3, 3>(0, 3 * line_before) = -id;
  t.block<3, 3>(3, 3 * across_after) = id;
  t.block<3, 3>(3, 3 * across_before) = -id;
  for (int k = 0; k < 3; ++k) t.block<3, 3>(6, 3 * k) = s.weights[k] * id;
  const Eigen::Matrix<double, 15, 1> grad = t.transpose() * grad_abd;

  LineBendingResponse r;
  r.energy = 0.5 * s.stiffness * rho * rho;
  r.force = s.stiffness * rho * grad;
  if (!with_tangent) return r;

  // Hessian of κ over (a, b, d):
  //   ∂²f/∂c² = −(ν gᵀ + g νᵀ)/|c| − κ P/|c|²,  ∂²f/∂c∂d = P/|c|,  P = I − ν νᵀ,
  // carried through dc = J (da, db), J = [−[b]×, [a]×], plus c's own second order da × db (g·(da × db)).
  const Eigen::Matrix3d p = id - nu * nu.transpose();
  const Eigen::Matrix3d h_cc = -(nu * g.transpose() + g * nu.transpose()) / c_norm - kappa * p / (c_norm * c_norm);
  Eigen::Matrix<double, 3, 6> j;
  j << -cross_matrix(v.b), cross_matrix(v.a);
  Eigen::Matrix<double, 9, 9> h = Eigen::Matrix<double, 9, 9>::Zero();
  h.topLeftCorner<6, 6>() = j.transpose() * h_cc * j;
  h.block<3, 3>(0, 3) -= cross_matrix(g);  // g·(da × db) = −daᵀ [g]× db
  h.block<3, 3>(3, 0) += cross_matrix(g);
  const Eigen::Matrix<double, 3, 6> h_dc = p * j / c_norm;
  h.block<3, 6>(6, 0) = h_dc;
  h.block<6, 3>(0, 6) = h_dc.transpose();
  r.tangent = s.stiffness * (grad * grad.transpose() + rho * (t.transpose() * h * t));
  return r;
}

}  // namespace tirefem
