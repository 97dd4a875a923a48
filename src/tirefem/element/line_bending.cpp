#include "tirefem/element/line_bending.hpp"

#include <cmath>

#include <unsupported/Eigen/AutoDiff>

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

// The geodesic curvature κ_g(a, b, d) and its gradient over (a, b, d), for any scalar type (the Hessian is
// the gradient's forward-mode derivative). With N = (a·a)(b·d) − (a·b)(a·d), D = |a| |c|, c = a × b:
//   ∂N/∂a = 2a(b·d) − b(a·d) − d(a·b),  ∂N/∂b = d(a·a) − a(a·d),  ∂N/∂d = b(a·a) − a(a·b),
//   ∂D/∂a = |c| a/|a| + |a| (b × c)/|c|,  ∂D/∂b = |a| (c × a)/|c|,  ∂κ_g = (∂N − κ_g ∂D)/D.
template <class T>
Eigen::Matrix<T, 9, 1> geodesic_gradient(const Eigen::Matrix<T, 3, 1>& a, const Eigen::Matrix<T, 3, 1>& b,
                                         const Eigen::Matrix<T, 3, 1>& d, T& kappa) {
  using std::sqrt;
  const Eigen::Matrix<T, 3, 1> c = a.cross(b);
  const T aa = a.dot(a), ab = a.dot(b), ad = a.dot(d), bd = b.dot(d);
  const T a_norm = sqrt(aa), c_norm = sqrt(c.dot(c));
  const T denominator = a_norm * c_norm;
  kappa = (aa * bd - ab * ad) / denominator;
  Eigen::Matrix<T, 9, 1> g;
  g.template segment<3>(0) = (T(2) * bd) * a - ad * b - ab * d -
                             kappa * ((c_norm / a_norm) * a + (a_norm / c_norm) * b.cross(c));
  g.template segment<3>(3) = aa * d - ad * a - kappa * ((a_norm / c_norm) * c.cross(a));
  g.template segment<3>(6) = aa * b - ab * a;
  return g / denominator;
}

// κ_g, its gradient and its Hessian over (a, b, d).
double geodesic_curvature(const LineVectors& v, Eigen::Matrix<double, 9, 1>* gradient,
                          Eigen::Matrix<double, 9, 9>* hessian) {
  if (!hessian) {
    double kappa = 0.0;
    const Eigen::Matrix<double, 9, 1> g = geodesic_gradient<double>(v.a, v.b, v.d, kappa);
    if (gradient) *gradient = g;
    return kappa;
  }
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, 9, 1>>;
  Eigen::Matrix<Dual, 3, 1> a, b, d;
  for (int k = 0; k < 3; ++k) {
    a[k] = Dual(v.a[k], 9, k);
    b[k] = Dual(v.b[k], 9, 3 + k);
    d[k] = Dual(v.d[k], 9, 6 + k);
  }
  Dual kappa;
  const Eigen::Matrix<Dual, 9, 1> g = geodesic_gradient<Dual>(a, b, d, kappa);
  for (int i = 0; i < 9; ++i) {
    (*gradient)[i] = g[i].value();
    hessian->row(i) = g[i].derivatives().transpose();
  }
  return kappa.value();
}

// (a, b, d) = T x, T a 9 × 15 map with entries ±1 and the weights.
Eigen::Matrix<double, 9, 15> line_map(const std::array<double, 3>& w) {
  Eigen::Matrix<double, 9, 15> t = Eigen::Matrix<double, 9, 15>::Zero();
  const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
  t.block<3, 3>(0, 3 * line_after) = id;
  t.block<3, 3>(0, 3 * line_before) = -id;
  t.block<3, 3>(3, 3 * across_after) = id;
  t.block<3, 3>(3, 3 * across_before) = -id;
  for (int k = 0; k < 3; ++k) t.block<3, 3>(6, 3 * k) = w[k] * id;
  return t;
}

LineBendingResponse in_plane_bending(const LineBendingStencil& s, const LineVectors& v, bool with_tangent) {
  Eigen::Matrix<double, 9, 1> grad_abd;
  Eigen::Matrix<double, 9, 9> h;
  const double kappa = geodesic_curvature(v, &grad_abd, with_tangent ? &h : nullptr);
  const double rho = kappa - s.reference_curvature;
  const Eigen::Matrix<double, 9, 15> t = line_map(s.weights);
  const Eigen::Matrix<double, 15, 1> grad = t.transpose() * grad_abd;
  LineBendingResponse r;
  r.energy = 0.5 * s.stiffness * rho * rho;
  r.force = s.stiffness * rho * grad;
  if (with_tangent) r.tangent = s.stiffness * (grad * grad.transpose() + rho * (t.transpose() * h * t));
  return r;
}

}  // namespace

std::array<double, 3> second_difference_weights(double h1, double h2) {
  const double s = 2.0 / (h1 + h2);
  return {s / h1, -s / h1 - s / h2, s / h2};
}

double line_curvature(const LineBendingStencil& s, const Eigen::Matrix<double, 3, 5>& x) {
  const LineVectors v = line_vectors(s.weights, x);
  if (s.in_plane) return geodesic_curvature(v, nullptr, nullptr);
  const Eigen::Vector3d c = v.a.cross(v.b);
  return c.dot(v.d) / c.norm();
}

LineBendingResponse line_bending(const LineBendingStencil& s, const Eigen::Matrix<double, 3, 5>& x,
                                 bool with_tangent) {
  const LineVectors v = line_vectors(s.weights, x);
  if (s.in_plane) return in_plane_bending(s, v, with_tangent);
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
  const Eigen::Matrix<double, 9, 15> t = line_map(s.weights);
  const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
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
