#pragma once
// The tyre wall's forms: the three-layer shell (MODEL.md §3) and, where the case gives its faces a
// bending stiffness, their bending (forms/face_bending_form.hpp), and where the tyre leans on a rim flange,
// that contact (forms/rim_flange_form.hpp).
#include <memory>
#include <vector>

#include "tirefem/element/element_geometry.hpp"
#include "tirefem/forms/rim_flange_form.hpp"
#include "tirefem/solver/form.hpp"
#include "tirefem/tyre/tyre_mesh.hpp"

namespace tirefem {

// The rim flange's contact of the tyre's mesh (none if the tyre has no flange).
std::unique_ptr<RimFlangeForm> make_rim_flange_form(const TyreMesh& tm);

// Returns the rim flange's form among those added (null without a flange), to report its load.
const RimFlangeForm* add_tyre_shell_forms(std::vector<std::unique_ptr<Form>>& forms, const TyreMesh& tm,
                                          Kinematics kinematics);

}  // namespace tirefem
