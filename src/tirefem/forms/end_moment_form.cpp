#include "tirefem/forms/end_moment_form.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

namespace tirefem {

EndMomentForm::EndMomentForm(const ShellMesh& mesh, std::vector<int> pairs, std::vector<double> moments,
                             Eigen::Vector3d axis)
    : mesh_(mesh), pairs_(std::move(pairs)), moments_(std::move(moments)), axis_(axis.normalized()) {
  if (pairs_.size() != moments_.size()) throw std::invalid_argument("one moment per node pair");
}

static std::array<int, 6> pair_dofs(int p) {
  return {inner_dof(p, 0), inner_dof(p, 1), inner_dof(p, 2),
          outer_dof(p, 0), outer_dof(p, 1), outer_dof(p, 2)};
}

void EndMomentForm::add_pattern(PatternBuilder& pattern) const {
  for (int p : pairs_) pattern.add_block(pair_dofs(p));
}

std::optional<EnergyChange> EndMomentForm::energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                                        double load_factor) const {
  EnergyChange total;
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const auto dofs = pair_dofs(pairs_[k]);
    const Eigen::Vector3d d0 = mesh_.outer_nodes[pairs_[k]] - mesh_.inner_nodes[pairs_[k]];
    Eigen::Vector3d a = d0, b = d0;
    for (int c = 0; c < 3; ++c) {
      a[c] += from[dofs[3 + c]] - from[dofs[c]];
      b[c] += to[dofs[3 + c]] - to[dofs[c]];
    }
    a -= axis_.dot(a) * axis_;  // the turn of the projections onto the plane normal to the axis
    b -= axis_.dot(b) * axis_;
    const double turn = std::atan2(axis_.dot(a.cross(b)), a.dot(b));
    const double work = load_factor * moments_[k] * turn;
    total += {-work, std::abs(work)};
  }
  return total;
}

void EndMomentForm::assemble(const FormInput& input, SparseSystem& system) const {
  Eigen::Matrix3d axis_cross;
  axis_cross << 0, -axis_.z(), axis_.y(), axis_.z(), 0, -axis_.x(), -axis_.y(), axis_.x(), 0;
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const int p = pairs_[k];
    const auto dofs = pair_dofs(p);
    Eigen::Vector3d d = mesh_.outer_nodes[p] - mesh_.inner_nodes[p];
    for (int c = 0; c < 3; ++c) d[c] += input.displacement[dofs[3 + c]] - input.displacement[dofs[c]];
    const double m = input.load_factor * moments_[k];
    // θ is the angle of d's projection d⊥ onto the plane normal to the axis, so M θ is a potential for
    // any motion of d, out of that plane too (its gradient and Hessian have no component along the axis).
    const Eigen::Vector3d normal_part = d - axis_.dot(d) * axis_;
    const double d2 = normal_part.squaredNorm();
    const Eigen::Vector3d g = m * axis_.cross(d) / d2;  // ∂(M θ)/∂d
    const Eigen::Matrix3d h = m * axis_cross / d2 - 2.0 * g * normal_part.transpose() / d2;
    Eigen::Matrix<double, 6, 1> f;
    f << g, -g;  // external force on (inner, outer) is (−g, +g); residual takes the negative
    Eigen::Matrix<double, 6, 6> kk;
    kk << -h, h, h, -h;
    system.add(dofs, f, kk, input.with_tangent);
  }
}

}  // namespace tirefem
