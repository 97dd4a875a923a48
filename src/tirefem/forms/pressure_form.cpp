#include "tirefem/forms/pressure_form.hpp"

#include "tirefem/forms/shell_internal_force.hpp"

namespace tirefem {

PressureForm::PressureForm(const ShellMesh& mesh, std::vector<int> elements, double pressure,
                           Kinematics kinematics, bool symmetrize)
    : mesh_(mesh), elements_(std::move(elements)), pressure_(pressure), kinematics_(kinematics),
      symmetrize_(symmetrize) {}

void PressureForm::add_pattern(PatternBuilder& pattern) const {
  for (int e : elements_) pattern.add_block(mesh_.element_dofs(e));
}

void PressureForm::assemble(const FormInput& input, SparseSystem& system) const {
  const int n = static_cast<int>(elements_.size());
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    const int e = elements_[i];
    const ElementConfiguration x = element_configuration(mesh_, e, input.displacement);
    PressureLoad load = follower_pressure(x.reference, x.current, input.load_factor * pressure_, kinematics_, input.with_tangent);
    // Residual = internal − external: the load enters with a minus sign, and so does its stiffness.
    const ElementVector f = -load.force;
    ElementMatrix k = -load.tangent;
    if (symmetrize_) k = 0.5 * (k + k.transpose()).eval();
    system.add(mesh_.element_dofs(e), f, k, input.with_tangent);
  }
}

}  // namespace tirefem
