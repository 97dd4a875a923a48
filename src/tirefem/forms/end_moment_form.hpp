#pragma once
// A moment about a fixed axis applied to node pairs through the director d = x_outer − x_inner: a couple
// ±(M_k/|d⊥|²)(axis × d) on the two nodes of each pair, d⊥ the projection of d onto the plane normal to
// the axis. It is the gradient of M_k θ(d), θ the angle of d⊥ about the axis, so the load is conservative
// for any motion (out of that plane too) and its stiffness symmetric; it stays a pure moment however far
// the end section turns (the roll-up cantilever of VERIFICATION.md §3).
#include <vector>

#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/solver/form.hpp"

namespace tirefem {

class EndMomentForm final : public Form {
 public:
  EndMomentForm(const ShellMesh& mesh, std::vector<int> pairs, std::vector<double> moments,
                Eigen::Vector3d axis);
  void add_pattern(PatternBuilder& pattern) const override;
  void assemble(const FormInput& input, SparseSystem& system) const override;
  bool has_potential() const override { return true; }
  // −λ Σ M_k Δθ_k, the turn of each director about the axis between the two states (taken as the
  // smaller angle, so a change of state by less than half a turn, as in any Newton step).
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor) const override;

 private:
  const ShellMesh& mesh_;
  std::vector<int> pairs_;
  std::vector<double> moments_;
  Eigen::Vector3d axis_;
};

}  // namespace tirefem
