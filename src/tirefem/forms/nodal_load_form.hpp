#pragma once
// Dead (fixed-direction) loads: a full-length nodal force vector scaled by the load factor.
#include "tirefem/mesh/shell_mesh.hpp"
#include "tirefem/solver/form.hpp"

namespace tirefem {

class NodalLoadForm final : public Form {
 public:
  explicit NodalLoadForm(Eigen::VectorXd forces) : forces_(std::move(forces)) {}
  void add_pattern(PatternBuilder&) const override {}
  void assemble(const FormInput& input, SparseSystem& system) const override {
    for (Eigen::Index d = 0; d < forces_.size(); ++d)
      if (forces_[d] != 0.0) system.add_residual(static_cast<int>(d), -input.load_factor * forces_[d]);
  }
  bool has_potential() const override { return true; }
  // A dead load: Π = −λ F·u.
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor) const override {
    const double work = load_factor * forces_.dot(to - from);
    return EnergyChange{-work, std::abs(work)};
  }

 private:
  Eigen::VectorXd forces_;
};

// Consistent nodal forces of a dead load `traction` per unit reference area on the chosen face of the
// chosen elements (2 × 2 Gauss). Returns a full-length vector.
enum class Face { inner, outer };
Eigen::VectorXd surface_load_vector(const ShellMesh& mesh, const std::vector<int>& elements, Face face,
                                    const Eigen::Vector3d& traction);

}  // namespace tirefem
