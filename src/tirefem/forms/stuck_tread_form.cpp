#include "tirefem/forms/stuck_tread_form.hpp"

#include <stdexcept>

namespace tirefem {

StuckTreadForm::StuckTreadForm(std::vector<TreadPoint> points, std::vector<Eigen::Vector3d> anchors,
                               std::vector<Eigen::Vector3d> normals, double shear_modulus)
    : points_(std::move(points)), anchors_(std::move(anchors)), normals_(std::move(normals)),
      shear_modulus_(shear_modulus) {
  if (anchors_.size() != points_.size() || normals_.size() != points_.size())
    throw std::invalid_argument("StuckTreadForm: one anchor and one normal per point");
  if (!(shear_modulus > 0)) throw std::invalid_argument("StuckTreadForm: the tread shear modulus must be > 0");
  for (const TreadPoint& p : points_)
    if (!(p.height > 0)) throw std::invalid_argument("StuckTreadForm: a point without tread height");
  for (Eigen::Vector3d& n : normals_) n.normalize();
}

void StuckTreadForm::add_pattern(PatternBuilder& pattern) const {
  for (const TreadPoint& p : points_) pattern.add_block(tread_point_dofs(p));
}

Eigen::Vector3d StuckTreadForm::position(int q, const Eigen::VectorXd& u) const {
  return tread_point_position(points_[q], u);
}

Eigen::Vector3d StuckTreadForm::road_displacement(int q) const {
  return motion_.translation + motion_.turn * normals_[q].cross(anchors_[q] - motion_.centre);
}

Eigen::Vector3d StuckTreadForm::point_force(int q, const Eigen::VectorXd& u) const {
  return spring(q) * projector(q) * (anchors_[q] + road_displacement(q) - position(q, u));
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> StuckTreadForm::resultant(const Eigen::VectorXd& u,
                                                                      const Eigen::Vector3d& about) const {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  for (int q = 0; q < static_cast<int>(points_.size()); ++q) {
    const Eigen::Vector3d f = point_force(q, u);
    force += f;
    moment += (anchors_[q] - about).cross(f);
  }
  return {force, moment};
}

void StuckTreadForm::assemble(const FormInput& input, SparseSystem& system) const {
  const int n = static_cast<int>(points_.size());
  BlockBatch& batch = system.batch(n);
#pragma omp parallel for schedule(static)
  for (int q = 0; q < n; ++q) {
    const TreadPoint& p = points_[q];
    // The residual is the force of the tyre on the road spring, −point_force.
    const Eigen::Vector3d point_residual = -point_force(q, input.displacement);
    const Eigen::Matrix3d point_tangent = spring(q) * projector(q);
    Eigen::Matrix<double, 12, 1> f;
    Eigen::Matrix<double, 12, 12> k;
    for (int a = 0; a < 4; ++a) {
      f.segment<3>(3 * a) = p.shape[a] * point_residual;
      for (int b = 0; b < 4; ++b) k.block<3, 3>(3 * a, 3 * b) = p.shape[a] * p.shape[b] * point_tangent;
    }
    batch.set(q, tread_point_dofs(p), f, k, input.with_tangent);
  }
  system.add(batch);
}

std::optional<EnergyChange> StuckTreadForm::energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                                          double) const {
  const auto energy = [&](int q, const Eigen::VectorXd& u) {
    const Eigen::Vector3d s = projector(q) * (position(q, u) - anchors_[q] - road_displacement(q));
    return 0.5 * spring(q) * s.squaredNorm();
  };
  EnergyChange total;
  for (int q = 0; q < static_cast<int>(points_.size()); ++q) {
    const double a = energy(q, from), b = energy(q, to);
    total += {b - a, a + b};
  }
  return total;
}

}  // namespace tirefem
