#include "tirefem/element/follower_pressure.hpp"

#include "tirefem/element/shape_functions.hpp"

namespace tirefem {
namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// +1 when the reference normal g1 × g2 of the inner face points towards the outer face.
double load_orientation(const NodeMatrix& reference) {
  const BilinearShape centre = bilinear_shape(0.0, 0.0);
  Eigen::Vector3d g1c = Eigen::Vector3d::Zero(), g2c = Eigen::Vector3d::Zero(),
                  director = Eigen::Vector3d::Zero();
  for (int a = 0; a < 4; ++a) {
    g1c += centre.dn_dxi[a] * reference.col(a);
    g2c += centre.dn_deta[a] * reference.col(a);
    director += centre.n[a] * (reference.col(a + 4) - reference.col(a));
  }
  return g1c.cross(g2c).dot(director) >= 0.0 ? 1.0 : -1.0;
}

}  // namespace

double enclosed_volume_part(const NodeMatrix& reference, const NodeMatrix& current) {
  double volume = 0.0;
  for (const auto& gp : kGauss2x2) {
    const BilinearShape s = bilinear_shape(gp[0], gp[1]);
    Eigen::Vector3d x = Eigen::Vector3d::Zero(), g1 = Eigen::Vector3d::Zero(), g2 = Eigen::Vector3d::Zero();
    for (int a = 0; a < 4; ++a) {
      x += s.n[a] * current.col(a);
      g1 += s.dn_dxi[a] * current.col(a);
      g2 += s.dn_deta[a] * current.col(a);
    }
    volume += x.dot(g1.cross(g2)) / 3.0;
  }
  return load_orientation(reference) * volume;
}

PressureLoad follower_pressure(const NodeMatrix& reference, const NodeMatrix& current, double pressure,
                               Kinematics kinematics, bool with_tangent) {
  // Orientation: the load pushes from the inner face towards the outer face.
  const double sign = load_orientation(reference);
  const NodeMatrix& geometry = kinematics == Kinematics::nonlinear ? current : reference;

  PressureLoad out;
  for (const auto& gp : kGauss2x2) {
    const BilinearShape s = bilinear_shape(gp[0], gp[1]);
    Eigen::Vector3d g1 = Eigen::Vector3d::Zero(), g2 = Eigen::Vector3d::Zero();
    for (int a = 0; a < 4; ++a) {
      g1 += s.dn_dxi[a] * geometry.col(a);
      g2 += s.dn_deta[a] * geometry.col(a);
    }
    const Eigen::Vector3d area_normal = sign * pressure * g1.cross(g2);  // p n dA / (dξ dη)
    for (int a = 0; a < 4; ++a) out.force.segment<3>(3 * a) += s.n[a] * area_normal;
    if (!with_tangent || kinematics == Kinematics::linear) continue;
    // d(g1 × g2)/dx_b = −N_b,ξ [g2×] + N_b,η [g1×]
    const Eigen::Matrix3d c1 = cross_matrix(g1), c2 = cross_matrix(g2);
    for (int b = 0; b < 4; ++b) {
      const Eigen::Matrix3d d = sign * pressure * (s.dn_deta[b] * c1 - s.dn_dxi[b] * c2);
      for (int a = 0; a < 4; ++a) out.tangent.block<3, 3>(3 * a, 3 * b) += s.n[a] * d;
    }
  }
  return out;
}

}  // namespace tirefem
