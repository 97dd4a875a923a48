#pragma once
// The lower sidewall's outer face leaning on the rim flange (road/rim_flange.hpp): a unilateral Winkler
// layer, the rubber between the outer face and the rigid curl, pressed with the stiffness kf where the
// face enters the curl. Its energy is ½ ∫ kf ⟨g⟩₊² dA over the outer face (the tread's eq. 6 with the
// flange as the support), so the residual, the tangent (with the curl's curvature term) and the energy
// are those of WinklerContactForm, whose points here lie on the outer face itself (no tread height) on
// the elements near the flange, with a 3 × 3 Gauss rule. The contact region is always {g > 0} at the
// current iterate: the flange's contact is not part of the two-level iteration.
#include <vector>

#include "tirefem/forms/winkler_contact_form.hpp"
#include "tirefem/road/rim_flange.hpp"

namespace tirefem {

class RimFlangeForm final : public Form {
 public:
  RimFlangeForm(const ShellMesh& mesh, RimFlange flange, double stiffness);

  void add_pattern(PatternBuilder& pattern) const override { contact_.add_pattern(pattern); }
  void assemble(const FormInput& input, SparseSystem& system) const override { contact_.assemble(input, system); }
  bool has_potential() const override { return true; }
  std::optional<EnergyChange> energy_change(const Eigen::VectorXd& from, const Eigen::VectorXd& to,
                                            double load_factor) const override {
    return contact_.energy_change(from, to, load_factor);
  }

  // The flange's force on the tyre at each point (TreadPointState::force), for the rim's reaction.
  std::vector<TreadPointState> evaluate(const Eigen::VectorXd& u) const { return contact_.evaluate(u); }
  int point_count() const { return static_cast<int>(contact_.points().size()); }

 private:
  RimFlange flange_;  // before contact_, which refers to it
  WinklerContactForm contact_;
};

}  // namespace tirefem
