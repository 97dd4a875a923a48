#include "tirefem/report/shell_results.hpp"

#include <cmath>

#include "tirefem/forms/shell_internal_force.hpp"
#include "tirefem/tyre/ply_stiffness.hpp"

namespace tirefem {

double engineering_strain(double green_strain, Kinematics kinematics) {
  if (kinematics == Kinematics::linear) return green_strain;
  return std::sqrt(1.0 + 2.0 * green_strain) - 1.0;
}

CylindricalDisplacement cylindrical_displacement(const Eigen::Vector3d& u, double phi) {
  // Radial direction at φ: (0, sin φ, −cos φ); circumferential: (0, cos φ, sin φ).
  return {u.x(), u.y() * std::sin(phi) - u.z() * std::cos(phi), u.y() * std::cos(phi) + u.z() * std::sin(phi)};
}

namespace {
FaceCordResults cord_results(const FaceLayup& face, const Eigen::Vector3d& strain, Kinematics kinematics) {
  FaceCordResults r;
  for (const Ply& ply : face.plies) {
    const double e = engineering_strain(cord_strain(strain, ply.angle_deg), kinematics);
    r.strain.push_back(e);
    r.force_N.push_back(cord_force(ply, e, kinematics == Kinematics::nonlinear));
  }
  return r;
}
}  // namespace

std::vector<ElementResult> evaluate_element_results(const TyreMesh& tm, const TyreDescription& tyre,
                                                    const Eigen::VectorXd& u, Kinematics kinematics) {
  const int n = tm.mesh.element_count();
  std::vector<ElementResult> out(n);
#pragma omp parallel for schedule(static)
  for (int e = 0; e < n; ++e) {
    ElementResult& r = out[e];
    const ElementConfiguration x = element_configuration(tm.mesh, e, u);
    r.state = three_layer_point_state(x.reference, x.current, tm.sections[e], kinematics, 0.0, 0.0);
    const Zone& zone = tyre.zones[tm.element_zone[e]];
    r.inner_cords = cord_results(zone.inner, r.state.inner_strain, kinematics);
    r.outer_cords = cord_results(zone.outer, r.state.outer_strain, kinematics);
    r.core_shear_stress = tm.sections[e].core_shear_modulus * r.state.core_shear;
  }
  return out;
}

}  // namespace tirefem
