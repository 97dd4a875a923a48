#pragma once
// Shared set-up of the rolling and cornering tests: the example tyre with a stiffened structure (the
// brush-model limits), and the rim's reaction (the residual of shell and pressure at the clamped bead DOFs,
// plus the rim flange's contact forces when the tyre leans on one) as a force and a moment about the axle
// centre.
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "contact_support.hpp"
#include "tirefem/forms/pressure_form.hpp"
#include "tirefem/analysis/tyre_shell_forms.hpp"
#include "tirefem/forms/rim_flange_form.hpp"
#include "tirefem/forms/shell_internal_force.hpp"

namespace tirefem::verification {

// The example tyre with every structural stiffness × factor (plies' cord and rubber moduli, direct face
// stiffnesses, core shear and normal moduli); the tread (kp, G, hp) unchanged.
inline TyreDescription stiffened_tyre(double factor) {
  TyreDescription t = example_case().tyre;
  auto stiffen = [factor](FaceLayup& f) {
    for (Ply& p : f.plies) p.cord_modulus *= factor, p.rubber_modulus *= factor;
    if (f.direct_stiffness) *f.direct_stiffness *= factor;
  };
  for (Zone& z : t.zones) {
    stiffen(z.inner);
    stiffen(z.outer);
    z.core_shear_modulus *= factor;
    z.core_normal_modulus *= factor;
  }
  return t;
}

struct RimReaction {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // the rim's force on the tyre
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // about the axle centre (0, 0, axis_z)
};

inline RimReaction rim_reaction(const TyreMesh& tm, double pressure, const Eigen::VectorXd& u) {
  DofMap dofs(tm.mesh.dof_count());
  dofs.fix(tm.fixed_dofs);
  std::vector<std::unique_ptr<Form>> forms;
  forms.push_back(std::make_unique<ShellInternalForce>(tm.mesh, tm.sections, Kinematics::nonlinear));
  forms.push_back(std::make_unique<PressureForm>(tm.mesh, tm.pressure_elements, pressure, Kinematics::nonlinear, true));
  // The flange is part of the rim: its forces on the tyre count, and so does what the clamp supplies
  // against the share of them that the bead's elements pass on to the bead nodes.
  std::unique_ptr<RimFlangeForm> f = make_rim_flange_form(tm);
  const RimFlangeForm* flange = f.get();
  if (f) forms.push_back(std::move(f));
  NonlinearProblem problem(dofs, std::move(forms));
  problem.evaluate(u, 1.0, false);
  const Eigen::VectorXd& r = problem.system().residual();
  const Eigen::Vector3d centre(0.0, 0.0, tm.axis_z);
  RimReaction out;
  for (int d : tm.fixed_dofs) {
    const int pair = d / 6;
    const bool outer = d % 6 >= 3;
    const Eigen::Vector3d x = (outer ? tm.mesh.outer_nodes[pair] : tm.mesh.inner_nodes[pair]) +
                              u.segment<3>(6 * pair + (outer ? 3 : 0));
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    f[d % 3] = r[d];  // the rim's force on the tyre: the residual (internal − applied) it has to supply
    out.force += f;
    out.moment += (x - centre).cross(f);
  }
  // The form hands a point's force to its element's outer nodes as N_k f, so on the tyre it acts at the
  // nodes' interpolated position (the point's lift onto the round wall is a fixed offset, like the tread
  // height, and carries no moment to the shell).
  if (flange) {
    const std::vector<TreadPointState> states = flange->evaluate(u);
    for (std::size_t q = 0; q < states.size(); ++q) {
      const TreadPoint& p = flange->points()[q];
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k) x += p.shape[k] * (tm.mesh.outer_nodes[p.pairs[k]] + u.segment<3>(6 * p.pairs[k] + 3));
      out.force += states[q].force;
      out.moment += (x - centre).cross(states[q].force);
    }
  }
  return out;
}

}  // namespace tirefem::verification
