#include "tirefem/analysis/tyre_shell_forms.hpp"

#include "tirefem/forms/face_bending_form.hpp"
#include "tirefem/forms/shell_internal_force.hpp"

namespace tirefem {

void add_tyre_shell_forms(std::vector<std::unique_ptr<Form>>& forms, const TyreMesh& tm, Kinematics kinematics) {
  forms.push_back(std::make_unique<ShellInternalForce>(tm.mesh, tm.sections, kinematics));
  if (has_face_bending(tm.sections))
    forms.push_back(std::make_unique<FaceBendingForm>(tm.mesh, tm.sections, kinematics, tm.half_model));
}

}  // namespace tirefem
