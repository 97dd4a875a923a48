#pragma once
// Other forms frozen at their linearisation about a state u0: R(u) = R0 + K0 (u − u0), tangent K0. Used
// for the geometrically linear contact solution: the tyre linearised about its inflated state, so the
// inflation's stress stiffening and the pressure's load stiffness are kept, but not their change with
// the contact deformation. Its pattern is K0's own, so K0 is added value by value.
#include "tirefem/solver/form.hpp"

namespace tirefem {

class LinearizedForm final : public Form {
 public:
  // `tangent` and `residual` (full length) as assembled at u0 by a problem over the same DofMap.
  LinearizedForm(DofMap dofs, SparseMatrix tangent, Eigen::VectorXd residual, Eigen::VectorXd u0);
  void add_pattern(PatternBuilder& pattern) const override;
  void assemble(const FormInput& input, SparseSystem& system) const override;
  bool has_potential() const override { return true; }
  // The quadratic Π = R0·w + ½ wᵀK0 w, w = u − u0 (K0 is symmetric here).
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor) const override;

 private:
  DofMap dofs_;
  SparseMatrix tangent_;
  Eigen::VectorXd residual_, u0_;
};

}  // namespace tirefem
