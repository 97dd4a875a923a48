#include "tirefem/analysis/tyre_shell_forms.hpp"

#include "tirefem/forms/face_bending_form.hpp"
#include "tirefem/forms/rim_flange_form.hpp"
#include "tirefem/forms/shell_internal_force.hpp"

namespace tirefem {

const RimFlangeForm* add_tyre_shell_forms(std::vector<std::unique_ptr<Form>>& forms, const TyreMesh& tm,
                                          Kinematics kinematics) {
  forms.push_back(std::make_unique<ShellInternalForce>(tm.mesh, tm.sections, kinematics));
  if (has_face_bending(tm.sections))
    // The bead (u_max, and u_min on the full model) is clamped: held, and the faces' slope with it.
    forms.push_back(std::make_unique<FaceBendingForm>(tm.mesh, tm.sections, kinematics, tm.half_model,
                                                      ClampedUEdges{!tm.half_model, true}));
  std::unique_ptr<RimFlangeForm> flange = make_rim_flange_form(tm);
  const RimFlangeForm* added = flange.get();
  if (flange) forms.push_back(std::move(flange));
  return added;
}

std::unique_ptr<RimFlangeForm> make_rim_flange_form(const TyreMesh& tm) {
  if (!tm.rim_flange) return nullptr;
  return std::make_unique<RimFlangeForm>(
      tm.mesh, place_rim_flange(tm.mesh, tm.axis_z, !tm.half_model, tm.rim_flange->radius), tm.rim_flange->stiffness);
}

}  // namespace tirefem
