#include "tirefem/road/rim_flange.hpp"

#include <cmath>
#include <stdexcept>

namespace tirefem {

RimFlange::RimFlange(Eigen::Vector2d centre, double radius, double axis_z, bool mirrored)
    : centre_(centre), radius_(radius), axis_z_(axis_z), mirrored_(mirrored) {
  if (!(radius > 0)) throw std::invalid_argument("rim flange: the curl radius must be > 0");
}

Penetration RimFlange::penetration(const Eigen::Vector3d& x, double) const {
  const double side = mirrored_ && x.x() < 0 ? -1.0 : 1.0;
  const Eigen::Vector3d w(0.0, x.y(), x.z() - axis_z_);
  const double rho = w.norm();
  const Eigen::Vector3d e_rho = w / rho, e_a(side, 0.0, 0.0);
  const Eigen::Vector2d d(side * x.x() - centre_.x(), rho - centre_.y());
  const double distance = d.norm();
  const Eigen::Vector2d n = d / distance;
  Eigen::Matrix<double, 2, 3> jacobian;  // ∂(side·a, ρ)/∂X
  jacobian.row(0) = e_a.transpose();
  jacobian.row(1) = e_rho.transpose();
  Eigen::Matrix3d yz = Eigen::Matrix3d::Zero();
  yz(1, 1) = yz(2, 2) = 1.0;
  Penetration p;
  p.value = radius_ - distance;
  p.gradient = -jacobian.transpose() * n;
  p.hessian = -jacobian.transpose() * (Eigen::Matrix2d::Identity() - n * n.transpose()) * jacobian / distance -
              n.y() * (yz - e_rho * e_rho.transpose()) / rho;
  return p;
}

namespace {
// (axial, radial) of a point about the axis parallel to x at height axis_z.
Eigen::Vector2d meridian_point(const Eigen::Vector3d& x, double axis_z) {
  return {x.x(), std::hypot(x.y(), x.z() - axis_z)};
}
}  // namespace

RimFlange place_rim_flange(const ShellMesh& mesh, double axis_z, bool mirrored, double radius) {
  const int bead = mesh.pair_index(mesh.u_nodes() - 1, 0), next = mesh.pair_index(mesh.u_nodes() - 2, 0);
  Eigen::Vector2d a = meridian_point(mesh.outer_nodes[bead], axis_z);
  Eigen::Vector2d b = meridian_point(mesh.outer_nodes[next], axis_z);
  Eigen::Vector2d inner = meridian_point(mesh.inner_nodes[bead], axis_z);
  if (a.x() < 0) a.x() = -a.x(), b.x() = -b.x(), inner.x() = -inner.x();  // measure on the x ≥ 0 side
  const Eigen::Vector2d chord = (a - b).normalized();
  Eigen::Vector2d normal(-chord.y(), chord.x());
  if (normal.dot(a - inner) < 0) normal = -normal;  // away from the tyre: from the inner to the outer face
  return RimFlange(a + radius * normal, radius, axis_z, mirrored);
}

std::vector<int> elements_near_flange(const ShellMesh& mesh, const RimFlange& flange) {
  std::vector<int> out;
  for (int e = 0; e < mesh.element_count(); ++e)
    for (int pair : mesh.elements[e])
      if (flange.clearance(mesh.outer_nodes[pair]) < flange.radius()) {
        out.push_back(e);
        break;
      }
  return out;
}

}  // namespace tirefem
