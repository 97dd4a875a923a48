#include "tirefem/forms/pressure_form.hpp"

#include "tirefem/forms/shell_internal_force.hpp"

namespace tirefem {

PressureForm::PressureForm(const ShellMesh& mesh, std::vector<int> elements, double pressure,
                           Kinematics kinematics, bool symmetrize)
    : mesh_(mesh), elements_(std::move(elements)), pressure_(pressure), kinematics_(kinematics),
      symmetrize_(symmetrize) {}

void PressureForm::add_pattern(PatternBuilder& pattern) const {
  for (int e : elements_) pattern.add_block(mesh_.element_dofs(e));
}

void PressureForm::assemble(const FormInput& input, SparseSystem& system) const {
  const int n = static_cast<int>(elements_.size());
  BlockBatch& batch = system.batch(n);
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    const int e = elements_[i];
    const ElementConfiguration x = element_configuration(mesh_, e, input.displacement);
    PressureLoad load = follower_pressure(x.reference, x.current, input.load_factor * pressure_, kinematics_, input.with_tangent);
    // Residual = internal − external: the load enters with a minus sign, and so does its stiffness. The
    // load acts on the inner face: only its 4 nodes' block (the first 12 DOFs) is added.
    const Eigen::Matrix<double, 12, 1> f = -load.force.head<12>();
    Eigen::Matrix<double, 12, 12> k = -load.tangent.topLeftCorner<12, 12>();
    if (symmetrize_) k = 0.5 * (k + k.transpose()).eval();
    const std::array<int, 24> dofs = mesh_.element_dofs(e);
    batch.set(i, std::span<const int>(dofs.data(), 12), f, k, input.with_tangent);
  }
  system.add(batch);
}

std::optional<EnergyChange> PressureForm::energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                                       double load_factor) const {
  if (!symmetrize_ && kinematics_ == Kinematics::nonlinear) return std::nullopt;
  const int n = static_cast<int>(elements_.size());
  const double p = load_factor * pressure_;
  std::vector<EnergyChange> parts(n);  // summed in order afterwards: the same result on any thread count
#pragma omp parallel for schedule(static)
  for (int i = 0; i < n; ++i) {
    const int e = elements_[i];
    const NodeMatrix reference = mesh_.element_reference(e);
    const NodeMatrix at_from = element_current(mesh_, e, from), at_to = element_current(mesh_, e, to);
    if (kinematics_ == Kinematics::linear) {
      const ElementVector f = follower_pressure(reference, reference, p, kinematics_, false).force;
      ElementVector du;
      for (int k = 0; k < 8; ++k) du.segment<3>(3 * k) = at_to.col(k) - at_from.col(k);
      parts[i] = {-f.dot(du), std::abs(f.dot(du))};
      continue;
    }
    const double v_from = enclosed_volume_part(reference, at_from), v_to = enclosed_volume_part(reference, at_to);
    parts[i] = {-p * (v_to - v_from), std::abs(p) * (std::abs(v_to) + std::abs(v_from))};
  }
  EnergyChange total;
  for (const EnergyChange& part : parts) total += part;
  return total;
}

}  // namespace tirefem
