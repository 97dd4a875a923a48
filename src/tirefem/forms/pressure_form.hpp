#pragma once
// Inflation pressure λ p on the inner face of chosen elements, as a follower load with its load
// stiffness. The element load stiffness is not symmetric, but its sum is for a closed pressurised
// surface whose free edges are held or lie on a symmetry plane (the tyre on its rim); in that case
// (`symmetrize`) each element adds the symmetric part, which changes nothing in the sum and lets the
// Cholesky factorisation be used.
#include <vector>

#include "tirefem/element/follower_pressure.hpp"
#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/solver/form.hpp"

namespace tirefem {

class PressureForm final : public Form {
 public:
  PressureForm(const ShellMesh& mesh, std::vector<int> elements, double pressure, Kinematics kinematics,
               bool symmetrize);
  void add_pattern(PatternBuilder& pattern) const override;
  void assemble(const FormInput& input, SparseSystem& system) const override;
  bool symmetric() const override { return symmetrize_ || kinematics_ == Kinematics::linear; }
  bool has_potential() const override { return symmetrize_ || kinematics_ == Kinematics::linear; }
  // −λp ΔV on a closed surface (`symmetrize`, MODEL.md §8); −λ F·Δu for the dead load of the linear
  // theory; nothing for a follower pressure on an open surface, which has no potential.
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor) const override;

 private:
  const ShellMesh& mesh_;
  std::vector<int> elements_;
  double pressure_;
  Kinematics kinematics_;
  bool symmetrize_;
};

}  // namespace tirefem
