#include "tirefem/forms/face_bending_form.hpp"

#include <optional>
#include <stdexcept>
#include <utility>

namespace tirefem {

namespace {

enum class Face { inner, outer };
enum class Direction { u, v };  // along the meridian, along the circumference

const Eigen::Vector2d& face_bending(const ElementSection& s, Face f, bool in_plane) {
  if (in_plane) return f == Face::inner ? s.inner_face_in_plane_bending : s.outer_face_in_plane_bending;
  return f == Face::inner ? s.inner_face_bending : s.outer_face_bending;
}

// A grid node as a stencil sees it: its node pair, and whether it is the mirror image of that pair in the
// symmetry plane x = 0.
struct GridNode {
  int pair = -1;
  bool mirrored = false;
  bool valid() const { return pair >= 0; }
};

struct Grid {
  const ShellMesh& mesh;
  bool symmetric_u_min;

  GridNode node(int i, int j) const {
    if (mesh.closed_v) j = (j % mesh.v_nodes() + mesh.v_nodes()) % mesh.v_nodes();
    if (j < 0 || j >= mesh.v_nodes()) return {};
    if (i == -1 && symmetric_u_min && mesh.u_nodes() > 1) return {mesh.pair_index(1, j), true};
    if (i < 0 || i >= mesh.u_nodes()) return {};
    return {mesh.pair_index(i, j), false};
  }
  Eigen::Vector3d position(GridNode n, Face f) const {
    Eigen::Vector3d x = f == Face::inner ? mesh.inner_nodes[n.pair] : mesh.outer_nodes[n.pair];
    if (n.mirrored) x.x() = -x.x();
    return x;
  }
  // Mean D along `d` of face f over the elements at node (i, j).
  double stiffness(const std::vector<ElementSection>& sections, int i, int j, Face f, Direction d,
                   bool in_plane) const {
    double sum = 0.0;
    int count = 0;
    const int ne_v = mesh.v_elements();
    for (int ei = i - 1; ei <= i; ++ei)
      for (int ej = j - 1; ej <= j; ++ej) {
        if (ei < 0 || ei >= mesh.u_elements()) continue;
        int ejw = ej;
        if (mesh.closed_v) ejw = (ej % ne_v + ne_v) % ne_v;
        if (ejw < 0 || ejw >= ne_v) continue;
        sum += face_bending(sections[mesh.element_index(ei, ejw)], f, in_plane)[d == Direction::u ? 0 : 1];
        ++count;
      }
    return count ? sum / count : 0.0;
  }
};

}  // namespace

bool has_face_bending(const std::vector<ElementSection>& sections) {
  for (const ElementSection& s : sections)
    for (Face f : {Face::inner, Face::outer})
      if (face_bending(s, f, false).maxCoeff() > 0.0 || face_bending(s, f, true).maxCoeff() > 0.0) return true;
  return false;
}

FaceBendingForm::FaceBendingForm(const ShellMesh& mesh, const std::vector<ElementSection>& sections,
                                 Kinematics kinematics, bool symmetric_u_min, ClampedUEdges clamped_u_edges)
    : kinematics_(kinematics) {
  if (symmetric_u_min && clamped_u_edges.u_min)
    throw std::invalid_argument("face bending: the u_min edge is either the symmetry plane or clamped");
  const Grid grid{mesh, symmetric_u_min};
  // The stencil of one line (face f, direction d, normal or in-plane bending) at node (i, j), if it bends.
  const auto add_stencil = [&](int i, int j, Face f, Direction d, bool in_plane) {
    const double stiffness = grid.stiffness(sections, i, j, f, d, in_plane);
    if (!(stiffness > 0.0)) return;
    const int di = d == Direction::u ? 1 : 0, dj = 1 - di;
    std::array<GridNode, 5> nodes;
    nodes[line_before] = grid.node(i - di, j - dj);
    nodes[line_centre] = grid.node(i, j);
    nodes[line_after] = grid.node(i + di, j + dj);
    // At a clamped edge the missing node is the mirror image of the first one inside (set below);
    // at any other edge the line is a hinge there.
    const bool clamped = d == Direction::u && ((i == 0 && clamped_u_edges.u_min) ||
                                               (i == mesh.u_nodes() - 1 && clamped_u_edges.u_max));
    const int beyond = !nodes[line_before].valid() ? line_before : line_after;
    const int inside = beyond == line_before ? line_after : line_before;
    if (!nodes[line_before].valid() || !nodes[line_after].valid()) {
      if (!clamped || !nodes[inside].valid()) return;
      nodes[beyond] = nodes[line_centre];
    }
    nodes[across_before] = grid.node(i - dj, j - di);
    nodes[across_after] = grid.node(i + dj, j + di);
    for (int k : {across_before, across_after})
      if (!nodes[k].valid()) nodes[k] = nodes[line_centre];  // one-sided across an edge

    Stencil s;
    const Eigen::Vector3d centre = grid.position(nodes[line_centre], f);
    for (int k = 0; k < 5; ++k) {
      s.reference.col(k) = grid.position(nodes[k], f) - centre;
      for (int c = 0; c < 3; ++c) {
        s.dofs[3 * k + c] = f == Face::inner ? inner_dof(nodes[k].pair, c) : outer_dof(nodes[k].pair, c);
        s.signs[3 * k + c] = nodes[k].mirrored && c == 0 ? -1.0 : 1.0;
      }
    }
    s.clamped = clamped;  // (past the test above, a clamped node lacks its node beyond)
    if (clamped) {
      // x_g − x_e = Q (x_1 − x_e), t along the edge element's reference chord: in the reference,
      // X_g − X_e = −(X_1 − X_e) (no reference curvature at the edge).
      s.reference.col(beyond) = -s.reference.col(inside);
      const Eigen::Vector3d t = s.reference.col(inside).normalized();
      const Eigen::Matrix3d q = Eigen::Matrix3d::Identity() - 2.0 * t * t.transpose();
      s.transform.setIdentity();
      s.transform.block<3, 3>(3 * beyond, 3 * beyond) = Eigen::Matrix3d::Identity() - q;
      s.transform.block<3, 3>(3 * beyond, 3 * inside) = q;
    }
    const double h1 = s.reference.col(line_before).norm(), h2 = s.reference.col(line_after).norm();
    const double across = 0.5 * (s.reference.col(across_before).norm() + s.reference.col(across_after).norm());
    // A node on the symmetry plane carries half of its full-model energy.
    // So does a clamped edge node (half of the two elements' length is its own).
    const double share = (symmetric_u_min && i == 0) || clamped ? 0.5 : 1.0;
    s.bending.weights = second_difference_weights(h1, h2);
    s.bending.in_plane = in_plane;
    s.bending.reference_curvature = line_curvature(s.bending, s.reference);
    s.bending.stiffness = share * stiffness * 0.5 * (h1 + h2) * across;
    stencils_.push_back(s);
  };
  for (const auto& [in_plane, f] : {std::pair{false, Face::inner}, std::pair{false, Face::outer},
                                    std::pair{true, Face::inner}, std::pair{true, Face::outer}})
    for (int j = 0; j < mesh.v_nodes(); ++j)
      for (int i = 0; i < mesh.u_nodes(); ++i)
        for (Direction d : {Direction::u, Direction::v}) add_stencil(i, j, f, d, in_plane);
}

void FaceBendingForm::add_pattern(PatternBuilder& pattern) const {
  for (const Stencil& s : stencils_) pattern.add_block(s.dofs);
}

Eigen::Matrix<double, 15, 1> FaceBendingForm::local_displacement(const Stencil& s, const Eigen::VectorXd& u) const {
  Eigen::Matrix<double, 15, 1> local;
  for (int k = 0; k < 15; ++k) local[k] = s.signs[k] * u[s.dofs[k]];
  if (s.clamped) local = s.transform * local;
  return local;
}

Eigen::Matrix<double, 3, 5> FaceBendingForm::current(const Stencil& s, const Eigen::VectorXd& u) const {
  Eigen::Matrix<double, 3, 5> x = s.reference;
  x.reshaped() += local_displacement(s, u);
  return x;
}

LineBendingResponse FaceBendingForm::response(const Stencil& s, const Eigen::VectorXd& u, bool with_tangent) const {
  if (kinematics_ == Kinematics::nonlinear) return line_bending(s.bending, current(s, u), with_tangent);
  // Linear theory: ½ k (∇κ0 · u)², with ∇κ0 at the reference.
  LineBendingResponse r = line_bending(s.bending, s.reference, true);
  const Eigen::Matrix<double, 15, 1> local = local_displacement(s, u);
  r.force = r.tangent * local;
  r.energy = 0.5 * local.dot(r.force);
  return r;
}

void FaceBendingForm::assemble(const FormInput& input, SparseSystem& system) const {
  const int n = static_cast<int>(stencils_.size());
  BlockBatch& batch = system.batch(n);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    const Stencil& s = stencils_[i];
    LineBendingResponse r = response(s, input.displacement, input.with_tangent);
    if (s.clamped) {  // back to the stencil's DOFs: Jᵀ f, Jᵀ K J (J has no mirrored x: signs are 1)
      r.force = s.transform.transpose() * r.force;
      if (input.with_tangent) r.tangent = s.transform.transpose() * r.tangent * s.transform;
    }
    for (int k = 0; k < 15; ++k) {
      r.force[k] *= s.signs[k];
      if (input.with_tangent)
        for (int l = 0; l < 15; ++l) r.tangent(k, l) *= s.signs[k] * s.signs[l];
    }
    batch.set(i, s.dofs, r.force, r.tangent, input.with_tangent);
  }
  system.add(batch);
}

std::optional<EnergyChange> FaceBendingForm::energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                                          double) const {
  const int n = static_cast<int>(stencils_.size());
  std::vector<EnergyChange> parts(n);  // summed in order: the same on any thread count
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    const double a = response(stencils_[i], from, false).energy, b = response(stencils_[i], to, false).energy;
    parts[i] = {b - a, std::abs(a) + std::abs(b)};
  }
  EnergyChange total;
  for (const EnergyChange& p : parts) total += p;
  return total;
}

}  // namespace tirefem
