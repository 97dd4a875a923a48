#include "tirefem/solver/nonlinear_problem.hpp"

#include <chrono>

namespace tirefem {
namespace {
SparseMatrix build_pattern(const DofMap& dofs, const std::vector<std::unique_ptr<Form>>& forms) {
  PatternBuilder pattern;
  for (const auto& f : forms) f->add_pattern(pattern);
  return pattern.build(dofs);
}
}  // namespace

NonlinearProblem::NonlinearProblem(DofMap dofs, std::vector<std::unique_ptr<Form>> forms)
    : dofs_(std::move(dofs)), forms_(std::move(forms)), system_(dofs_, build_pattern(dofs_, forms_)) {
  for (const auto& f : forms_)
    if (!f->symmetric() || !f->has_potential()) has_potential_ = false;
}

std::optional<EnergyChange> NonlinearProblem::energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                                            double load_factor) {
  if (!has_potential_) return std::nullopt;
  const auto t0 = std::chrono::steady_clock::now();
  EnergyChange total;
  for (const auto& f : forms_) {
    const std::optional<EnergyChange> part = f->energy_change(from, to, load_factor);
    if (!part) return std::nullopt;
    total += *part;
  }
  ++stats_.energy_evaluations;
  stats_.energy_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return total;
}

void NonlinearProblem::evaluate(const Eigen::VectorXd& displacement, double load_factor,
                                bool with_tangent) {
  const auto t0 = std::chrono::steady_clock::now();
  system_.clear(with_tangent);
  const FormInput input{displacement, load_factor, with_tangent};
  for (const auto& f : forms_) f->assemble(input, system_);
  ++stats_.assemblies;
  stats_.assembly_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool NonlinearProblem::symmetric() const {
  for (const auto& f : forms_)
    if (!f->symmetric()) return false;
  return true;
}

double NonlinearProblem::load_scale() {
  if (load_scale_ < 0) {
    evaluate(Eigen::VectorXd::Zero(dofs_.dof_count()), 1.0, false);
    load_scale_ = dofs_.gather(system_.residual()).norm();
  }
  return load_scale_;
}

}  // namespace tirefem
