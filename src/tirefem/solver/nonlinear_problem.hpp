#pragma once
// The nonlinear problem R(u, λ) = 0: a sum of forms over a DOF map with homogeneous constraints.
#include <memory>
#include <vector>

#include "tirefem/solver/form.hpp"

namespace tirefem {

struct AssemblyStats {
  int assemblies = 0;
  double assembly_s = 0.0;
  int energy_evaluations = 0;
  double energy_s = 0.0;
};

class NonlinearProblem {
 public:
  NonlinearProblem(DofMap dofs, std::vector<std::unique_ptr<Form>> forms);

  // Fills system() with the residual and (optionally) the tangent at (u, λ).
  void evaluate(const Eigen::VectorXd& displacement, double load_factor, bool with_tangent);
  const SparseSystem& system() const { return system_; }
  const DofMap& dofs() const { return dofs_; }
  bool symmetric() const;
  // Π(to) − Π(from) at λ when every form derives from a potential (MODEL.md §8), else nothing.
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor);
  bool has_potential() const { return has_potential_; }
  const AssemblyStats& stats() const { return stats_; }
  // ‖R_free(0, 1)‖: the size of the applied load, the scale for residual tolerances.
  double load_scale();

 private:
  DofMap dofs_;
  std::vector<std::unique_ptr<Form>> forms_;
  SparseSystem system_;
  AssemblyStats stats_;
  double load_scale_ = -1.0;
  bool has_potential_ = true;
};

}  // namespace tirefem
