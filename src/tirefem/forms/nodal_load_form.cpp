#include "tirefem/forms/nodal_load_form.hpp"

#include "tirefem/element/shape_functions.hpp"

namespace tirefem {

Eigen::VectorXd surface_load_vector(const ShellMesh& mesh, const std::vector<int>& elements, Face face,
                                    const Eigen::Vector3d& traction) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.dof_count());
  const int offset = face == Face::inner ? 0 : 4;
  for (int e : elements) {
    const auto x = mesh.element_reference(e);
    const auto dofs = mesh.element_dofs(e);
    for (const auto& gp : kGauss2x2) {
      const BilinearShape s = bilinear_shape(gp[0], gp[1]);
      Eigen::Vector3d g1 = Eigen::Vector3d::Zero(), g2 = Eigen::Vector3d::Zero();
      for (int a = 0; a < 4; ++a) {
        g1 += s.dn_dxi[a] * x.col(offset + a);
        g2 += s.dn_deta[a] * x.col(offset + a);
      }
      const double area = g1.cross(g2).norm();
      for (int a = 0; a < 4; ++a)
        for (int c = 0; c < 3; ++c) f[dofs[3 * (offset + a) + c]] += s.n[a] * area * traction[c];
    }
  }
  return f;
}

}  // namespace tirefem
