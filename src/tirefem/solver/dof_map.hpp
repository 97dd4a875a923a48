#pragma once
// Numbering of the free degrees of freedom (equations); constrained DOFs keep whatever value the
// displacement vector holds there (zero unless a prescribed value is set).
#include <vector>

#include <Eigen/Dense>

namespace tirefem {

class DofMap {
 public:
  explicit DofMap(int dof_count) : fixed_(dof_count, false) { renumber(); }
  void fix(int dof) {
    fixed_.at(dof) = true;
    renumber();
  }
  void fix(const std::vector<int>& dofs) {
    for (int d : dofs) fixed_.at(d) = true;
    renumber();
  }
  int dof_count() const { return static_cast<int>(fixed_.size()); }
  int equation_count() const { return equations_; }
  int equation(int dof) const { return equation_[dof]; }  // −1 when constrained
  bool is_fixed(int dof) const { return fixed_[dof]; }

  Eigen::VectorXd gather(const Eigen::VectorXd& full) const {
    Eigen::VectorXd r(equations_);
    for (int d = 0; d < dof_count(); ++d)
      if (equation_[d] >= 0) r[equation_[d]] = full[d];
    return r;
  }
  void scatter_add(const Eigen::VectorXd& reduced, Eigen::VectorXd& full) const {
    for (int d = 0; d < dof_count(); ++d)
      if (equation_[d] >= 0) full[d] += reduced[equation_[d]];
  }

 private:
  void renumber() {
    equation_.assign(fixed_.size(), -1);
    equations_ = 0;
    for (size_t d = 0; d < fixed_.size(); ++d)
      if (!fixed_[d]) equation_[d] = equations_++;
  }
  std::vector<bool> fixed_;
  std::vector<int> equation_;
  int equations_ = 0;
};

}  // namespace tirefem
