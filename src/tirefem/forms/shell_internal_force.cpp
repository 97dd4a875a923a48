#include "tirefem/forms/shell_internal_force.hpp"

#include <stdexcept>

namespace tirefem {

Eigen::Matrix<double, 3, 8> element_current(const ShellMesh& mesh, int element,
                                            const Eigen::VectorXd& u) {
  Eigen::Matrix<double, 3, 8> x = mesh.element_reference(element);
  const auto dofs = mesh.element_dofs(element);
  for (int k = 0; k < 8; ++k)
    for (int c = 0; c < 3; ++c) x(c, k) += u[dofs[3 * k + c]];
  return x;
}

NodeMatrix centred_reference(const ShellMesh& mesh, int element) {
  NodeMatrix x = mesh.element_reference(element);
  const Eigen::Vector3d centroid = x.rowwise().mean();
  x.colwise() -= centroid;
  return x;
}

ElementConfiguration element_configuration(const ShellMesh& mesh, int element, const Eigen::VectorXd& u) {
  ElementConfiguration c;
  c.reference = centred_reference(mesh, element);
  c.current = c.reference;
  const auto dofs = mesh.element_dofs(element);
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) c.current(i, k) += u[dofs[3 * k + i]];
  return c;
}

ShellInternalForce::ShellInternalForce(const ShellMesh& mesh, const std::vector<ElementSection>& sections,
                                       Kinematics kinematics)
    : mesh_(mesh), sections_(sections), kinematics_(kinematics) {
  if (static_cast<int>(sections.size()) != mesh.element_count())
    throw std::invalid_argument("one section per element is required");
  geometry_.resize(mesh.element_count());
#pragma omp parallel for schedule(static)
  for (int e = 0; e < mesh.element_count(); ++e) geometry_[e] = element_geometry(centred_reference(mesh, e));
}

void ShellInternalForce::add_pattern(PatternBuilder& pattern) const {
  for (int e = 0; e < mesh_.element_count(); ++e) pattern.add_block(mesh_.element_dofs(e));
}

void ShellInternalForce::assemble(const FormInput& input, SparseSystem& system) const {
  const int n = mesh_.element_count();
  BlockBatch& batch = system.batch(n);
#pragma omp parallel for schedule(static)
  for (int e = 0; e < n; ++e) {
    const auto dofs = mesh_.element_dofs(e);
    const ElementConfiguration x = element_configuration(mesh_, e, input.displacement);
    const ElementResponse r =
        three_layer_element(geometry_[e], x.reference, x.current, sections_[e], kinematics_, input.with_tangent);
    batch.set(e, dofs, r.force, r.tangent, input.with_tangent);
  }
  system.add(batch);
}

std::optional<EnergyChange> ShellInternalForce::energy_change(const Eigen::VectorXd& from,
                                                             const Eigen::VectorXd& to, double) const {
  const int n = mesh_.element_count();
  std::vector<EnergyChange> parts(n);  // summed in order afterwards: the same result on any thread count
#pragma omp parallel for schedule(static)
  for (int e = 0; e < n; ++e) {
    const ElementConfiguration a = element_configuration(mesh_, e, from), b = element_configuration(mesh_, e, to);
    const double ea = three_layer_element(geometry_[e], a.reference, a.current, sections_[e], kinematics_, false).energy;
    const double eb = three_layer_element(geometry_[e], b.reference, b.current, sections_[e], kinematics_, false).energy;
    parts[e] = {eb - ea, std::abs(ea) + std::abs(eb)};
  }
  EnergyChange total;
  for (const EnergyChange& part : parts) total += part;
  return total;
}

}  // namespace tirefem
