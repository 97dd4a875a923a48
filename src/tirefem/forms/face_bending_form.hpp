#pragma once
// The faces' own bending stiffness (an extension of the paper's element, whose faces are membranes).
//
// A face without bending stiffness, compressed and held only by the interlayer (a foundation of stiffness
// k ≈ E33/h), wrinkles at the shortest wave the mesh can carry, so such an instability moves with the
// mesh (docs/studies/belt-edge-mode.md). A real belt or sidewall layer has a bending stiffness D that
// fixes the wrinkling load, 2√(kD), and its wavelength, 2π(D/k)^¼. This form adds it, rotation-free, as
// the bending energy ½ D ρ² of the mesh lines through each node of each face with D > 0
// (element/line_bending.hpp): meridional lines with the face's D11, circumferential lines with its D22.
// The twist and cross terms (D12, D66) are left out.
//
// Mesh edges: a line is bent only at nodes with a neighbour on both sides along it, so a free edge of the
// grid is a hinge for the face; across a line one-sided differences give the normal at an edge. With
// `symmetric_u_min` the u_min edge lies on the symmetry plane x = 0 (the half tyre's equator): its nodes
// see the mirror image of their neighbours and carry half of their full-model energy. A clamped u edge
// (the tyre's bead, `clamped_u_edges`: held, and its faces' slope with it) bends its meridional lines at
// the edge node too: the node beyond is the mirror image of the first one inside in the plane normal to
// the edge element's reference chord t, x_g = x_e + Q (x_1 − x_e), Q = I − 2 t tᵀ, so the second
// difference there is 2 (I − t tᵀ)(x_1 − x_e)/h², the turn of the first element away from t; the edge
// node carries half of that line's energy (its tributary length is h/2).
#include <array>
#include <vector>

#include "tirefem/element/element_geometry.hpp"
#include "tirefem/element/line_bending.hpp"
#include "tirefem/element/section.hpp"
#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/solver/form.hpp"

namespace tirefem {

// Whether any section gives a face a bending stiffness (else the form has nothing to do).
bool has_face_bending(const std::vector<ElementSection>& sections);

// Which u edges (equator / bead) of the grid are clamped; u_min only when it is not the symmetry plane.
struct ClampedUEdges {
  bool u_min = false, u_max = false;
};

class FaceBendingForm final : public Form {
 public:
  FaceBendingForm(const ShellMesh& mesh, const std::vector<ElementSection>& sections, Kinematics kinematics,
                  bool symmetric_u_min, ClampedUEdges clamped_u_edges = {});
  void add_pattern(PatternBuilder& pattern) const override;
  void assemble(const FormInput& input, SparseSystem& system) const override;
  bool has_potential() const override { return true; }
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor) const override;
  int stencil_count() const { return static_cast<int>(stencils_.size()); }

 private:
  struct Stencil {
    LineBendingStencil bending;
    Eigen::Matrix<double, 3, 5> reference;  // node positions relative to the centre node (mirrored ones mirrored)
    std::array<int, 15> dofs;
    std::array<double, 15> signs;  // −1 on the x DOF of a mirrored node
    // At a clamped edge: x = reference + J u(dofs), J the identity but for the node beyond the edge
    // (its dofs are the edge node's, unused: its rows are Q on the first node inside, I − Q on the edge node).
    bool clamped = false;
    Eigen::Matrix<double, 15, 15> transform;
  };
  Eigen::Matrix<double, 15, 1> local_displacement(const Stencil& s, const Eigen::VectorXd& u) const;
  Eigen::Matrix<double, 3, 5> current(const Stencil& s, const Eigen::VectorXd& u) const;
  LineBendingResponse response(const Stencil& s, const Eigen::VectorXd& u, bool with_tangent) const;

  std::vector<Stencil> stencils_;
  Kinematics kinematics_;
};

}  // namespace tirefem
