#pragma once
// Internal force and tangent of the three-layer shell elements (MODEL.md §3).
#include <vector>

#include "tirefem/element/three_layer_element.hpp"
#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/solver/form.hpp"

namespace tirefem {

// Current positions of element `e`'s 8 nodes for displacement u.
Eigen::Matrix<double, 3, 8> element_current(const ShellMesh& mesh, int element,
                                            const Eigen::VectorXd& displacement);

// Reference and current positions of an element's nodes relative to its reference centroid (the reference
// alone: centred_reference). The element is translation-invariant, and it recovers u as current −
// reference: with positions near the origin that difference keeps its digits (at tyre coordinates,
// ~300 mm, it would not).
NodeMatrix centred_reference(const ShellMesh& mesh, int element);
struct ElementConfiguration {
  NodeMatrix reference, current;
};
ElementConfiguration element_configuration(const ShellMesh& mesh, int element,
                                           const Eigen::VectorXd& displacement);

class ShellInternalForce final : public Form {
 public:
  ShellInternalForce(const ShellMesh& mesh, const std::vector<ElementSection>& sections,
                     Kinematics kinematics);
  void add_pattern(PatternBuilder& pattern) const override;
  void assemble(const FormInput& input, SparseSystem& system) const override;
  bool has_potential() const override { return true; }
  // The strain energy change, element by element.
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor) const override;

 private:
  const ShellMesh& mesh_;
  const std::vector<ElementSection>& sections_;
  Kinematics kinematics_;
  std::vector<ElementGeometry> geometry_;  // of the centred reference, per element (computed once)
};

}  // namespace tirefem
