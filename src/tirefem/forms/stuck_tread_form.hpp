#pragma once
// The tread of a standing tyre glued to the road (the tyre's static tangential stiffness, read by
// analysis/standing_stiffness.hpp): every tread point in contact at a loaded state is held by its shear
// spring, G/hp per unit of breaker-face area (the stick law of eq. 15 without a friction limit: a small
// motion), to the point of the road it stands on, while the road moves rigidly in its own plane by
//     d(a) = t + ψ n × (a − c)      (translation t, a small turn ψ about the road normal n through c).
// Only the shear counts, in the road's tangent plane at the point (P = I − n nᵀ); the normal contact is
// the Winkler form's. Energy Σ ½ (G/hp) w |P (x − a − d(a))|², x the tread point (forms/winkler_contact_form.hpp)
// and a its position in the loaded state: residual (G/hp) w P (x − a − d) spread by the shape functions,
// tangent (G/hp) w P (linear and symmetric).
#include <vector>

#include "tirefem/forms/winkler_contact_form.hpp"

namespace tirefem {

struct RoadMotion {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // t, mm
  double turn = 0.0;                                      // ψ, rad, about the normal through `centre`
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();       // c
};

class StuckTreadForm final : public Form {
 public:
  // `points` (each with its anchor a, where it stands, and the road's unit normal n there) and G.
  StuckTreadForm(std::vector<TreadPoint> points, std::vector<Eigen::Vector3d> anchors,
                 std::vector<Eigen::Vector3d> normals, double shear_modulus);

  void add_pattern(PatternBuilder& pattern) const override;
  void assemble(const FormInput& input, SparseSystem& system) const override;
  bool has_potential() const override { return true; }
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor) const override;

  void set_road_motion(const RoadMotion& motion) { motion_ = motion; }
  // The road's displacement at the anchor of point q.
  Eigen::Vector3d road_displacement(int q) const;
  // The force of the road on the tyre at point q: (G/hp) w P (a + d − x).
  Eigen::Vector3d point_force(int q, const Eigen::VectorXd& u) const;
  // Σ of point_force, and its moment about `about`, Σ (a − about) × f.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> resultant(const Eigen::VectorXd& u, const Eigen::Vector3d& about) const;

  const std::vector<TreadPoint>& points() const { return points_; }
  double spring(int q) const { return shear_modulus_ * points_[q].weight / points_[q].height; }  // (G/hp) w, N/mm

 private:
  Eigen::Vector3d position(int q, const Eigen::VectorXd& u) const;
  Eigen::Matrix3d projector(int q) const { return Eigen::Matrix3d::Identity() - normals_[q] * normals_[q].transpose(); }

  std::vector<TreadPoint> points_;
  std::vector<Eigen::Vector3d> anchors_, normals_;
  double shear_modulus_;
  RoadMotion motion_;
};

}  // namespace tirefem
