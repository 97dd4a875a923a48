#include "tirefem/forms/linearized_form.hpp"

namespace tirefem {

LinearizedForm::LinearizedForm(const ShellMesh& mesh, DofMap dofs, SparseMatrix tangent,
                               Eigen::VectorXd residual, Eigen::VectorXd u0)
    : mesh_(mesh), dofs_(std::move(dofs)), tangent_(std::move(tangent)), residual_(std::move(residual)), u0_(std::move(u0)) {}

void LinearizedForm::add_pattern(PatternBuilder& pattern) const {
  for (int e = 0; e < mesh_.element_count(); ++e) pattern.add_block(mesh_.element_dofs(e));
}

void LinearizedForm::assemble(const FormInput& input, SparseSystem& system) const {
  const Eigen::VectorXd du = dofs_.gather(input.displacement - u0_);
  Eigen::VectorXd r = residual_;
  dofs_.scatter_add(Eigen::VectorXd(tangent_ * du), r);
  for (int d = 0; d < r.size(); ++d)
    if (r[d] != 0.0) system.add_residual(d, r[d]);
  if (input.with_tangent) system.add_matrix(tangent_);
}

}  // namespace tirefem
