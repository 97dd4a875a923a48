#pragma once
// A moment about a fixed axis applied to node pairs through the director d = x_outer − x_inner: a couple
// ±(M_k/|d|²)(axis × d) on the two nodes of each pair. It is the gradient of M_k θ(d), θ the angle of d
// about the axis, so the load is conservative and its stiffness symmetric; it stays a pure moment however
// far the end section turns (the roll-up cantilever of VERIFICATION.md §3). d must stay normal to the axis.
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

 private:
  const ShellMesh& mesh_;
  std::vector<int> pairs_;
  std::vector<double> moments_;
  Eigen::Vector3d axis_;
};

}  // namespace tirefem
