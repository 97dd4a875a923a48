#include "tirefem/forms/linearized_form.hpp"

namespace tirefem {

LinearizedForm::LinearizedForm(DofMap dofs, SparseMatrix tangent, Eigen::VectorXd residual, Eigen::VectorXd u0)
    : dofs_(std::move(dofs)), tangent_(std::move(tangent)), residual_(std::move(residual)), u0_(std::move(u0)) {}

void LinearizedForm::add_pattern(PatternBuilder& pattern) const { pattern.add_matrix_pattern(tangent_); }

void LinearizedForm::assemble(const FormInput& input, SparseSystem& system) const {
  const Eigen::VectorXd du = dofs_.gather(input.displacement - u0_);
  Eigen::VectorXd r = residual_;
  dofs_.scatter_add(Eigen::VectorXd(tangent_ * du), r);
  for (int d = 0; d < r.size(); ++d)
    if (r[d] != 0.0) system.add_residual(d, r[d]);
  if (input.with_tangent) system.add_matrix(tangent_);
}

std::optional<EnergyChange> LinearizedForm::energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                                         double) const {
  const Eigen::VectorXd r0 = dofs_.gather(residual_);
  const auto energy = [&](const Eigen::VectorXd& u) {
    const Eigen::VectorXd w = dofs_.gather(u - u0_);
    return r0.dot(w) + 0.5 * w.dot(tangent_ * w);
  };
  const double a = energy(from), b = energy(to);
  return EnergyChange{b - a, std::abs(a) + std::abs(b)};
}

}  // namespace tirefem
