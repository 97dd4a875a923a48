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

// What one flange carries in a state: the tyre's force on it, split into the push along the wheel axis
// (outward, away from the tyre's mid-plane, > 0 when the bead presses the flange as inflation does) and
// the in-plane resultant (the flange's share of the wheel load), its largest contact pressure, and the
// share of the circumference where the lower sidewall touches it (below 1: the wall has lifted off the
// flange over part of its round, e.g. on the side away from a large lateral force).
struct RimFlangeLoad {
  int side = 1;  // the flange at x > 0 (+1) or x < 0 (−1), x the wheel axis
  double axial_force_N = 0.0;
  double radial_force_N = 0.0;
  double peak_pressure_MPa = 0.0;
  double contact_fraction = 0.0;  // element columns (round the axis) with a point in contact / all
};

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
  const std::vector<TreadPoint>& points() const { return contact_.points(); }  // in evaluate()'s order
  // The load on each flange the form's points reach (one on a half model, two on a full one), at u.
  std::vector<RimFlangeLoad> loads(const Eigen::VectorXd& u) const;

 private:
  RimFlange flange_;  // before contact_, which refers to it
  WinklerContactForm contact_;
  int u_elements_ = 0, v_elements_ = 0;  // of the mesh: element e lies in column e / u_elements_
};

}  // namespace tirefem
